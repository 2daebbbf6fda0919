#!/usr/bin/env bash
# Runs every shell line of README.md (its ```sh blocks) from a fresh clone of
# the committed tree, the install line included: `cargo install --locked
# --path .` into a temporary root whose bin/ comes first on the PATH, then
# every other line as written (`cargo test` excepted: CI runs it). Each line
# must exit 0 and `git status` must be clean afterwards (outputs only in
# ignored directories). tests/it/readme_lines.rs checks the same within
# `cargo test`, with the test build's binary instead of the installed one.
# Usage: bash tools/readme_lines.sh   (from anywhere; CI runs it)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
git clone -q "$repo" "$tmp/clone"
cd "$tmp/clone"
# Share the build directory: the dependencies are not rebuilt.
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$repo/target}"
export CARGO_INSTALL_ROOT="$tmp/root"
# `python` is a fresh venv's, so the README's `python -m pip install ./python`
# runs as written without touching the machine's Python.
python3 -m venv "$tmp/venv"
export PATH="$tmp/root/bin:$tmp/venv/bin:$PATH"
awk '
  /^```/ { insh = ($0 == "```sh"); next }
  !insh { next }
  {
    line = $0
    i = index(line, " #"); if (i > 0) line = substr(line, 1, i - 1)
    sub(/^[ \t]+/, "", line); sub(/[ \t]+$/, "", line)
    if (line ~ /^#/) next
    if (line ~ /\\$/) { pending = pending substr(line, 1, length(line) - 1) " "; next }
    line = pending line; pending = ""
    if (line != "") print line
  }' README.md > "$tmp/lines"
n=0
while IFS= read -r line; do
  case "$line" in
    "cargo test"*) echo "skip (CI runs it): $line"; continue ;;
  esac
  echo "== $line"
  bash -c "$line" < /dev/null > "$tmp/out" 2>&1 || { echo "FAILED: $line"; tail -5 "$tmp/out"; exit 1; }
  n=$((n + 1))
done < "$tmp/lines"
status=$(git status --porcelain)
if [ -n "$status" ]; then
  echo "README lines left files git does not ignore:"; echo "$status"; exit 1
fi
echo "README: $n lines ran, tree clean"
