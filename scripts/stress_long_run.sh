#!/usr/bin/env bash
# A one-hour simulated walk (tests/data/cli/long_walk.yaml: 3600 s at 50 Hz,
# the biped on a 2 km path, four tibia sensors) under /usr/bin/time -v, to show
# that memory stays flat: outputs are streamed to disk, not held. Prints the
# peak resident memory and the sizes of the files written.
#
#   scripts/stress_long_run.sh [PROXSIM_BINARY] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
binary="${1:-build/release/proxsim}"
out="${2:-build/stress-long-run}"
[ -x /usr/bin/time ] || { echo "stress_long_run: needs /usr/bin/time (Debian package 'time')" >&2; exit 2; }
# runs SCENARIO under /usr/bin/time -v into $out; prints "peak_kB wall"
measure() {
  local log
  log="$(mktemp)"
  rm -rf "$out"
  /usr/bin/time -v "$binary" run "$1" --out "$out" --no-report 2>"$log" >/dev/null || { cat "$log" >&2; exit 1; }
  echo "$(awk -F': ' '/Maximum resident set size/ {print $2}' "$log") $(awk -F': ' '/Elapsed \(wall clock\) time/ {print $2}' "$log")"
  rm -f "$log"
}

# the same walk for 6 minutes, then for the hour: flat memory means the same peak
short="$(mktemp --suffix=.yaml)"
sed 's/^duration_s: 3600$/duration_s: 360/' tests/data/cli/long_walk.yaml >"$short"
read -r short_kb short_wall < <(measure "$short")
rm -f "$short"
read -r peak_kb wall < <(measure tests/data/cli/long_walk.yaml)
echo "6-minute walk:  peak RSS ${short_kb} kB ($((short_kb / 1024)) MiB), wall ${short_wall}"
echo "one-hour walk:  peak RSS ${peak_kb} kB ($((peak_kb / 1024)) MiB), wall ${wall}"
echo "samples: $(python3 -c "import json;print(json.load(open('$out/summary.json'))['samples'])")"
du -b "$out"/* | sort -k2
