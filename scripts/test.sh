#!/usr/bin/env bash
# Fresh machine → every test: installs what is missing, builds the release and
# the sanitizer (ASan+UBSan) presets, and runs the whole CTest suite under both.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh browser
for preset in release asan; do
  echo "=== $preset: configure and build"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  echo "=== $preset: tests"
  ctest --preset "$preset"
done
