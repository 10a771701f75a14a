#!/usr/bin/env bash
# Fresh machine → every test: installs what is missing, builds the release and
# the sanitizer (ASan+UBSan) presets, runs the whole CTest suite (but the
# `long` label) in release, its C++ tests (labels unit and cli; not python,
# browser, nor heavy: whole studies whose C++ paths the smaller tests cover)
# under the sanitizers, and the ray-dependent tests (label rays) once
# more on Embree's SSE4.2 code path.
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
# Embree picks its code path (SSE4.2, AVX2, AVX-512) from the CPU, and its hit
# distances differ in the last bits between them: the ray-dependent tests run
# once more on the SSE4.2 path, so that a test that holds only on this CPU's
# path fails here rather than on the next machine (docs/trust.md).
echo "=== release: the ray-dependent tests (label rays) again under PROXSIM_EMBREE_CONFIG=isa=sse4.2"
ctest --preset release-isa-sse42
