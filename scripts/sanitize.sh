#!/usr/bin/env bash
# The AddressSanitizer + UndefinedBehaviorSanitizer build and its tests (docs/reliability.md).
#
#   bash scripts/sanitize.sh --fast   # CI's part (scripts/test.sh --sanitize-fast, after the tests):
#                                     # Clang build in build-fuzz of the reader areas (common, logs, tyre,
#                                     # brake, track, vehicle) and their unit tests, those tests,
#                                     # then a smoke of 10 CPU seconds of every fuzz target
#   bash scripts/sanitize.sh --full   # every test (ctest) of an ASan + UBSan build of everything,
#                                     # in build-sanitize with the default compiler (slow: the
#                                     # optimal-control and FE tests run several times slower;
#                                     # without the Python package, whose tests are then not
#                                     # registered: python/CMakeLists.txt)
#
# Undefined behaviour is fatal (-fno-sanitize-recover; UBSAN_OPTIONS halt_on_error), as are leaks
# and memory errors. Needs clang for --fast (scripts/install-deps.sh --fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:---fast}
jobs=$(nproc)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

case "$mode" in
  --fast)
    build=${HOTLAP_FUZZ_BUILD:-build-fuzz}
    # One build serves both: the libraries carry the sanitizers and libFuzzer's coverage
    # instrumentation; hotlap_tests links them without libFuzzer.
    HOTLAP_FUZZ_BUILD=$build bash scripts/fuzz.sh --configure
    cmake --build "$build" --parallel "$jobs" --target hotlap_tests hotlap_fuzzers
    # The tests in one GoogleTest shard per core, side by side; each shard's output after it.
    pids=()
    for ((i = 0; i < jobs; i++)); do
      (cd "$build" && GTEST_TOTAL_SHARDS=$jobs GTEST_SHARD_INDEX=$i \
        ./hotlap_tests --gtest_brief=1 >"shard-$i.log" 2>&1) &
      pids+=($!)
    done
    failed=0
    for i in "${!pids[@]}"; do
      wait "${pids[$i]}" || failed=1
      cat "$build/shard-$i.log"
    done
    if [ "$failed" -ne 0 ]; then
      echo "sanitize.sh: a shard of the sanitized tests failed (above)" >&2
      exit 1
    fi
    HOTLAP_FUZZ_BUILD=$build HOTLAP_FUZZ_JOBS=$jobs bash scripts/fuzz.sh all 10
    ;;
  --full)
    build=${HOTLAP_SANITIZE_BUILD:-build-sanitize}
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHOTLAP_SANITIZE=ON \
      -DHOTLAP_BUILD_BENCH=OFF -DHOTLAP_BUILD_PYTHON=OFF >/dev/null
    cmake --build "$build" --parallel "$jobs"
    (cd "$build" && ctest --output-on-failure --parallel "$jobs" --timeout 3600)
    ;;
  *)
    echo "sanitize.sh: unknown option '$mode' (--fast or --full)" >&2
    exit 2
    ;;
esac
