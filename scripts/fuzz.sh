#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, in the sanitizer tree `cmake --preset asan`: Debian's
# clang with ASan and UBSan) and runs each for SECONDS (default 60) from its committed seed
# corpus, as many at once as there are cores.
#   scripts/fuzz.sh [SECONDS] [HARNESS...]     e.g. scripts/fuzz.sh 600, scripts/fuzz.sh 30 bvh tsc
# A crash, sanitizer report, leak, input slower than 10 s, allocation over 1 GiB or resident
# memory over 2 GiB is a finding: the input is kept under fuzz/findings/<harness>/, its path
# and the report's first lines are printed, and the script exits 1 after running the rest.
# New inputs the fuzzer finds go to build-asan/corpus/<harness>/ (not committed).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() {
  echo "usage: scripts/fuzz.sh [SECONDS] [HARNESS...]" >&2
  exit 2
}
seconds=${1:-60}
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || usage
shift $(( $# > 0 ? 1 : 0 ))

all=()
for source in fuzz/*_fuzzer.cpp; do
  name=$(basename "$source" _fuzzer.cpp)
  all+=("$name")
done
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=("${all[@]}")
for name in "${harnesses[@]}"; do
  [ -f "fuzz/${name}_fuzzer.cpp" ] || { echo "error: no harness '$name' (have: ${all[*]})" >&2; exit 2; }
done

jobs=$(nproc 2>/dev/null || echo 2)
cmake --preset asan >/dev/null
targets=()
for name in "${harnesses[@]}"; do targets+=("fuzz_$name"); done
cmake --build build-asan -j"$jobs" --target "${targets[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
mkdir -p build-asan/logs

# One harness, its log in build-asan/logs/<harness>.log and its exit status in <harness>.status.
run_harness() {
  local name=$1 corpus=build-asan/corpus/$1 findings=fuzz/findings/$1 log=build-asan/logs/$1.log
  mkdir -p "$corpus" "$findings" "fuzz/corpus/$name"
  local status=0
  build-asan/bin/fuzz_"$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$findings/" \
    "$corpus" "fuzz/corpus/$name" >"$log" 2>&1 || status=$?
  echo "$status" >"build-asan/logs/$name.status"
}

# Each harness is one single-threaded process: run a core's worth at a time.
echo "== ${#harnesses[@]} harnesses for ${seconds} s each, $jobs at a time"
running=0
for name in "${harnesses[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
  run_harness "$name" &
  running=$((running + 1))
done
wait

failed=()
for name in "${harnesses[@]}"; do
  log=build-asan/logs/$name.log
  status=$(cat "build-asan/logs/$name.status")
  echo "== fuzz_$name"
  grep -E '^stat::number_of_executed_units|^#[0-9]+ *DONE' "$log" | tail -2 | sed 's/^/   /' || true
  if [ "$status" -ne 0 ]; then
    failed+=("$name")
    echo "FINDING in fuzz_$name (exit $status), log $log"
    grep -E 'Test unit written to' "$log" | sed 's/^/   /' || true
    # The report's first line and its first frames outside the sanitizer and fuzzer runtimes.
    grep -m1 -E 'ERROR: |runtime error|throng fuzz finding' "$log" | sed 's/^/   /' || true
    grep -E '^ *#[0-9]+ 0x' "$log" | grep -v -E ' in (__sanitizer|__asan|__ubsan|__interceptor|fuzzer::|__pthread|raise|abort|__libc|_start|main )|libc\.so' |
      head -8 | sed -E 's/ \(BuildId: [0-9a-f]+\)//; s/^/   /' || true
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]}"
  exit 1
fi
echo "fuzz: no findings in ${harnesses[*]} (${seconds} s each)"
