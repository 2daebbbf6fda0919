#!/bin/sh
# Converged sphere-solver references for tests/it/sphere_convergence.rs.
# Runs the release CLI (solver of SOLVER_VERSION 2, commit 9204750: the mesh
# density change of version 3 does not change the converged limit) at
# resolutions 4 and 8 and extrapolates (Richardson, second order: the
# pull-off and the zero-load radius change by a factor 3.7-4.4 per doubling,
# docs/performance.md), then writes sphere_converged.json.
#   cargo build --release && sh tests/data/sphere_converged.sh
# The mu = 10, 30 and 100 lines (jump-out; large mu)
# are from solver version 5 through the library, since the CLI refuses
# resolution 8 there by its 120 s estimate (mu = 10, 30, 100 took 18 s,
# 113 s and ~4 min):
#   cargo run --release --example sphere_large_mu -- --raw --res 4,8 10 30 100
# and are kept when the loop below is rerun (they are appended last).
set -e
BIN=${BIN:-target/release/asperity}
cd "$(dirname "$0")/../.."
out=tests/data/sphere_converged.raw
grep -E '"case":"(10|30|100)"' $out > $out.mu10 || true
: > $out
for case in "0.005" "0.01" "0.5" "1" "0.01 --rho 10"; do
  for res in 4 8; do
    mu=${case%% *}; rest=${case#"$mu"}
    printf '{"case":"%s","resolution":%s,"facts":%s}\n' "$case" "$res" \
      "$($BIN sphere --mu $mu $rest --resolution $res --json)" >> $out
  done
done
cat $out.mu10 >> $out && rm $out.mu10
python3 tests/data/sphere_converged.py
