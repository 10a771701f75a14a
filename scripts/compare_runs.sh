#!/usr/bin/env bash
# Whether a change kept every result bit for bit: runs two proxsim binaries
# (a reference, e.g. main's, and a new one) over every scenario in
# data/scenarios/, the paper's default run and the bench's closed-loop study
# of 40 generated rooms (src/bench/outcome_bench.cc), and compares their files
# byte for byte: readings.csv, poses.csv, summary.json, scene.json and
# profile.ply of each run (and its exit code); the study's results.csv, ranking.csv,
# failures.csv and replay files (failures/). Prints each file that differs;
# exits 1 if any does.
#
#   scripts/compare_runs.sh REFERENCE_BINARY NEW_BINARY [WORK_DIR]
#
# WORK_DIR (default: a new temporary folder) keeps the reference's outputs
# under ref/: run again with the same WORK_DIR, they are reused.
set -uo pipefail
cd "$(dirname "$0")/.."
ref="$(realpath "$1")"
new="$(realpath "$2")"
work="${3:-$(mktemp -d)}"
mkdir -p "$work/ref" "$work/new"
work="$(realpath "$work")"
scenarios="$(pwd)/data/scenarios"
fail=0

# run DIR BINARY ARGS...: one run into $work/DIR's side, its exit code beside it (DIR.rc)
run() {
  local dir="$1" bin="$2"
  shift 2
  "$bin" "$@" >/dev/null 2>&1
  echo $? >"$work/$dir.rc"
}

# whether DIR's runs ended alike and well: a run that failed on both sides
# leaves no files to differ, and must not pass for identical
ended_alike() {  # ended_alike DIR
  local dir="$1"
  if ! cmp -s "$work/ref/$dir.rc" "$work/new/$dir.rc"; then
    echo "differs: $dir (exit $(cat "$work/ref/$dir.rc") vs $(cat "$work/new/$dir.rc"))"; fail=1
  elif [ "$(cat "$work/ref/$dir.rc")" != 0 ]; then
    echo "failed on both: $dir (exit $(cat "$work/ref/$dir.rc"))"; fail=1
  fi
}

# whether the reference's run of DIR is kept from an earlier call (and went well)
ref_kept() { [ -d "$work/ref/$1" ] && [ "$(cat "$work/ref/$1.rc" 2>/dev/null)" = 0 ]; }

compare() {  # compare DIR FILE...
  local dir="$1"
  shift
  for file in "$@"; do
    if [ -e "$work/ref/$dir/$file" ] || [ -e "$work/new/$dir/$file" ]; then
      cmp -s "$work/ref/$dir/$file" "$work/new/$dir/$file" || { echo "differs: $dir/$file"; fail=1; }
    fi
  done
}

# every scenario, run from its folder (paths in it are relative to it)
for path in "$scenarios"/*.yaml; do
  name="$(basename "$path" .yaml)"
  # a robot moved by a caller (co-simulation) has no run of its own to compare
  grep -q '^ *locomotion: external' "$path" && continue
  ref_kept "$name" || { rm -rf "$work/ref/$name"; (cd "$scenarios" && run "ref/$name" "$ref" run "$path" --no-report --out "$work/ref/$name"); }
  rm -rf "$work/new/$name"
  (cd "$scenarios" && run "new/$name" "$new" run "$path" --no-report --out "$work/new/$name")
  ended_alike "$name"
  compare "$name" readings.csv poses.csv summary.json scene.json profile.ply
done

# the paper's default run
ref_kept paper || { rm -rf "$work/ref/paper"; run ref/paper "$ref" run --no-report --out "$work/ref/paper"; }
rm -rf "$work/new/paper"
run new/paper "$new" run --no-report --out "$work/new/paper"
ended_alike paper
compare paper readings.csv poses.csv summary.json scene.json profile.ply

# the bench's outcome study: 8 shin lasers, the stop rule, 40 rooms at difficulty 0.5
study="$work/rooms40.yaml"
if [ ! -e "$study" ]; then
  sensors=""
  n=0
  for link in left_tibia right_tibia; do
    for yaw_pitch in "0, 8, 0" "0, 20, 0" "0, 8, 30" "0, 8, -30"; do
      [ $n -gt 0 ] && sensors+=", "
      sensors+="{name: l$n, type: laser, link: $link, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [$yaw_pitch]}}"
      n=$((n + 1))
    done
  done
  printf 'proxsim: 1\nseed: 1\nduration_s: 10.0\nrate_hz: 50\nscene: {builtin: empty}\nrobot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n' >"$work/walker.yaml"
  printf 'proxsim_study: 1\nmode: outcomes\nbase: walker.yaml\nsets: [{name: eight_lasers, sensors: [%s]}]\nstrategies: [{name: stop}]\nworlds: {generate: {kind: room, difficulty: 0.5}, seeds: {from: 1, to: 40}}\n' \
    "$sensors" >"$study"
fi
ref_kept rooms40 || { rm -rf "$work/ref/rooms40"; (cd "$work" && run ref/rooms40 "$ref" study "$study" --no-report --threads 1 --out "$work/ref/rooms40"); }
rm -rf "$work/new/rooms40"
(cd "$work" && run new/rooms40 "$new" study "$study" --no-report --threads 1 --out "$work/new/rooms40")
ended_alike rooms40
compare rooms40 results.csv ranking.csv failures.csv
diff -r "$work/ref/rooms40/failures" "$work/new/rooms40/failures" >/dev/null || { echo "differs: rooms40/failures/"; fail=1; }

echo "compared $(ls "$scenarios"/*.yaml | wc -l) scenarios, the paper run and the 40-room study in $work: $([ $fail = 0 ] && echo identical || echo DIFFERENT)"
exit $fail
