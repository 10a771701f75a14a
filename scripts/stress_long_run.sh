#!/usr/bin/env bash
# A one-hour simulated walk (tests/data/cli/long_walk.yaml: 3600 s at 50 Hz,
# the biped on a 2 km path, four tibia sensors) under /usr/bin/time -v, to show
# that memory stays flat: outputs are streamed to disk, not held. Prints, for a
# shorter walk (SHORT_S simulated seconds, default 360) and for the hour:
#  - walk: the peak resident memory during the walk (the process's VmHWM read
#    every 0.2 s until the end's files begin: readings.csv appears under its
#    own name, the first file committed);
#  - end: the peak over the whole run (/usr/bin/time's maximum resident set),
#    which includes the end, where the terrain files and score are made;
# then the sizes of the hour's files.
#
#   scripts/stress_long_run.sh [PROXSIM_BINARY] [OUT_DIR] [SHORT_S]
set -euo pipefail
cd "$(dirname "$0")/.."
binary="${1:-build/release/proxsim}"
out="${2:-build/stress-long-run}"
short_s="${3:-360}"
[ -x /usr/bin/time ] || { echo "stress_long_run: needs /usr/bin/time (Debian package 'time')" >&2; exit 2; }
[[ "$short_s" =~ ^[0-9]+$ ]] && [ "$short_s" -gt 0 ] || { echo "stress_long_run: SHORT_S: expected a whole number of seconds > 0, got $short_s" >&2; exit 2; }
# runs SCENARIO under /usr/bin/time -v into $out; prints "walk_peak_kB end_peak_kB wall"
measure() {
  local log hwm walk_kb=0 pid
  log="$(mktemp)"
  rm -rf "$out"
  /usr/bin/time -v "$binary" run "$1" --out "$out" --no-report 2>"$log" >/dev/null &
  pid=$!
  # /usr/bin/time's one child is proxsim: its high-water mark until the walk's end
  while kill -0 "$pid" 2>/dev/null; do
    local child
    child="$(pgrep -P "$pid" | head -n 1 || true)"
    if [ -n "$child" ] && [ ! -e "$out/readings.csv" ]; then
      hwm="$(awk '/^VmHWM:/ {print $2}' "/proc/$child/status" 2>/dev/null || true)"
      [ -n "$hwm" ] && walk_kb="$hwm"
    fi
    sleep 0.2
  done
  wait "$pid" || { cat "$log" >&2; exit 1; }
  echo "$walk_kb $(awk -F': ' '/Maximum resident set size/ {print $2}' "$log") $(awk -F': ' '/Elapsed \(wall clock\) time/ {print $2}' "$log")"
  rm -f "$log"
}

# the same walk for SHORT_S seconds, then for the hour: flat memory means the same peaks
short="$(mktemp --suffix=.yaml)"
sed "s/^duration_s: 3600\$/duration_s: $short_s/" tests/data/cli/long_walk.yaml >"$short"
read -r short_walk_kb short_kb short_wall < <(measure "$short")
rm -f "$short"
read -r walk_kb peak_kb wall < <(measure tests/data/cli/long_walk.yaml)
echo "${short_s} s walk: peak RSS walking ${short_walk_kb} kB, at the end ${short_kb} kB (+$((short_kb - short_walk_kb)) kB), wall ${short_wall}"
echo "3600 s walk: peak RSS walking ${walk_kb} kB, at the end ${peak_kb} kB (+$((peak_kb - walk_kb)) kB), wall ${wall}"
echo "samples: $(python3 -c "import json;print(json.load(open('$out/summary.json'))['samples'])")"
du -b "$out"/* | sort -k2
