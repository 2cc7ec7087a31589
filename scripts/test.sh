#!/usr/bin/env bash
# Fresh machine → all tests: installs the packages, builds, runs every suite (GPU suites on
# lavapipe with two threads, the Khronos validation layer and a random test order), then the CPU
# suites again under AddressSanitizer + UndefinedBehaviorSanitizer, then every libFuzzer harness
# for THRONG_FUZZ_SECONDS (default 20) seconds each: any finding fails the run. The sanitizer
# suites and the harnesses share one clang tree (build-asan/): the engine is compiled once per
# tree, two times in all.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
./scripts/install_deps.sh
./scripts/build.sh
export LP_NUM_THREADS=2 THRONG_VALIDATION=1
ctest --preset release -j"$jobs"
cmake --preset asan
# The CPU suites' executables (script checks such as the viewer linkage need no target of their
# own, only the two binaries).
targets=(throng throng-view)
available=$(cmake --build build-asan --target help | sed -n 's/^\.\.\. \([^ ]*\).*/\1/p')
for test in $(ctest --test-dir build-asan -N -L cpu 2>/dev/null | sed -n 's/^ *Test *#[0-9]*: *//p'); do
  if grep -qx "$test" <<<"$available"; then targets+=("$test"); fi
done
cmake --build --preset asan -j"$jobs" --target "${targets[@]}"
ctest --preset asan-cpu -j"$jobs"
./scripts/fuzz.sh "${THRONG_FUZZ_SECONDS:-20}"
