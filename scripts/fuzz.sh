#!/usr/bin/env bash
# Builds the libFuzzer targets (the "fuzz" preset: clang, ASan + UBSan) and runs
# each for a set time over its seed corpus (fuzz/corpus/<target>, committed).
# New inputs go to build/fuzz-work/<target>/corpus; every crash, leak or hang is
# written to build/fuzz-work/<target>/artifacts/ (the run goes on after one, in
# libFuzzer's fork mode) and makes the script exit 1. Leaks inside Assimp and
# urdfdom on files they refuse are suppressed (fuzz/lsan.supp says which).
# Keep each finding, once fixed, in fuzz/regressions/<target>/ (the GoogleTest
# FuzzRegression replays every file there, and every corpus file, in the
# ordinary test suite).
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]   # default: 60 s, all of them
#   PROXSIM_FUZZ_NO_BUILD=1 scripts/fuzz.sh ...        # without rebuilding first
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scenario urdf mesh trajectory journal outcome_journal cosim_state outcome_study)

if [ -z "${PROXSIM_FUZZ_NO_BUILD:-}" ]; then  # set it to run the fuzzers already built
  scripts/install-deps.sh fuzz
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz -j2
fi

status=0
for t in "${targets[@]}"; do
  work="build/fuzz-work/$t"
  mkdir -p "$work/corpus" "$work/artifacts"
  echo "=== fuzz_$t for ${seconds} s"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0" \
    "build/fuzz/fuzz/fuzz_$t" "$work/corpus" "fuzz/corpus/$t" \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 -max_len=8192 \
    -artifact_prefix="$work/artifacts/" >"$work/fuzz.log" 2>&1 || true
  grep -E "^#[0-9]+: cov|DONE" "$work/fuzz.log" | tail -n 2
  if compgen -G "$work/artifacts/*" >/dev/null; then
    echo "=== fuzz_$t FOUND PROBLEMS: $(ls "$work/artifacts" | wc -l) inputs in $work/artifacts/ (log: $work/fuzz.log)" >&2
    status=1
  else
    echo "=== fuzz_$t: nothing found"
  fi
done
exit $status
