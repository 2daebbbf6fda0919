#!/usr/bin/env bash
# What the pull-off populations add to each example scene's run: CPU time
# (perf stat task-clock, all threads, mean of R runs) of `asperity run SCENE`
# as shipped and with `outputs.pull_off_population = false`, for each binary
# given (interleaved scene by scene, so that two builds see the same load).
# docs/performance.md ("Pull-off populations") quotes it.
#
#   cargo build --release && bash tools/reports/population_overhead.sh target/release/asperity [OTHER_BINARY]
#
# Prints `scene | with / without [ms]` per binary. Needs `perf`; R=10 by default.
set -euo pipefail
R=${R:-10}
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cpu_ms() { perf stat -r "$R" -e task-clock "$@" 2>&1 >/dev/null | awk '/task-clock/{print $1}'; }
for s in rf-mems-switch mems-gold calibrated-gold montecarlo-gold dmt-stiff soft-jkr max-load \
  conical-summits gold-rf-mems-plastic; do
  f=examples/scenes/$s.toml
  sed 's/^pull_off = true/pull_off = true\npull_off_population = false/' "$f" > "$tmp/$s.toml"
  line="$s"
  for bin in "$@"; do
    on=$(cpu_ms "$bin" run "$f" --out "$tmp/out")
    off=$(cpu_ms "$bin" run "$tmp/$s.toml" --out "$tmp/out")
    line="$line | $on / $off"
  done
  echo "$line"
done
