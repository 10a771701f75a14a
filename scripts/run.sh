#!/usr/bin/env bash
# Fresh machine → the paper's experiment: installs what is missing, builds what
# the run needs (the `proxsim` binary, with the Python package and the viewer
# bundle its report uses; not the tests, fuzzers or benchmarks) and runs
# `proxsim run` (the built-in default scenario), passing any arguments on,
# e.g. scripts/run.sh --out my-out.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target proxsim
exec build/release/proxsim run "$@"
