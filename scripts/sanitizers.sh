#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/sanitizers.sh
#
# Builds the library and opencv_test_lsd_advance with AddressSanitizer and
# UndefinedBehaviorSanitizer (-DLSD_ADVANCE_SANITIZE=address,undefined, every report fatal; OpenCV
# and its ts are linked as they are, not instrumented) in a build directory of its own, and runs the
# unit tests; then with ThreadSanitizer in another, and runs the tests of the threaded code. Any
# sanitizer report (memory error, leak, undefined behaviour, data race) or test failure fails the
# script. Ends with the line `sanitizers: N passed, M failed` (both runs).
#
# LSDAdvance_LongSequence.* is not run here: ASan's quarantine keeps freed memory resident by
# design, which is what that test measures. Everything else is.
#
# Environment:
#   LSD_ADVANCE_ASAN_BUILD_DIR  build directory (default: <repo>/build-asan)
#   LSD_ADVANCE_TSAN_BUILD_DIR  build directory of the ThreadSanitizer run (default: <repo>/build-tsan)
#   OPENCV_SOURCE_DIR, LSD_ADVANCE_DATA_DIR, LSD_ADVANCE_JOBS  as for scripts/test.sh
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_ASAN_BUILD_DIR:-$REPO/build-asan}"
TSAN_BUILD="${LSD_ADVANCE_TSAN_BUILD_DIR:-$REPO/build-tsan}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
T0=$SECONDS
section() { echo; echo "==== [sanitizers] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh"
if [ -z "${OPENCV_SOURCE_DIR:-}" ]; then
  OPENCV_SOURCE_DIR="$(bash "$REPO/scripts/fetch_opencv_source.sh" | tail -n1)"
fi

# Configures and builds opencv_test_lsd_advance in $1 with the sanitizers $2, from the test files $3
# (a CMake list; empty: all). At -O1 with line tables only (-g1), as the sanitizers' documentation
# advises: reports keep their file:line stacks, and the build takes half the time of -O2 -g.
build_tests() {
  section "configure ($1, $2)"
  cmake -S "$REPO" -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DBUILD_TESTS=ON -DBUILD_EXAMPLES=OFF -DBUILD_APPS=OFF \
    -DLSD_ADVANCE_SANITIZE="$2" -DLSD_ADVANCE_TEST_FILES="$3" -DOPENCV_SOURCE_DIR="$OPENCV_SOURCE_DIR"
  section "build opencv_test_lsd_advance ($2)"
  cmake --build "$1" -j"$JOBS" --target opencv_test_lsd_advance
}

export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
passed_all=0; failed_all=0; status=0

# Runs opencv_test_lsd_advance of build $1 with the gtest filter $2 into log $3; a line matching the
# regular expression $4 is a sanitizer report. Adds to passed_all / failed_all, sets status.
run_tests() {
  local rc=0 passed failed reports
  ( cd "$1" && ./opencv_test_lsd_advance --gtest_filter="$2" ) >"$3" 2>&1 || rc=$?
  grep -E '^\[ *(OK|FAILED|PASSED|SKIPPED) *\]|^\[=+\]' "$3" | tail -n 30 || true
  passed="$(sed -nE 's/^\[  PASSED  \] ([0-9]+) tests?\..*/\1/p' "$3" | tail -n1)"
  failed="$(sed -nE 's/^\[  FAILED  \] ([0-9]+) tests?, listed below:.*/\1/p' "$3" | tail -n1)"
  passed="${passed:-0}"; failed="${failed:-0}"
  reports="$(grep -cE "$4" "$3" || true)"
  if [ "$reports" -ne 0 ]; then
    echo "ERROR: $reports sanitizer report(s); log: $3" >&2
    grep -E -A40 "$4" "$3" | head -n 120 >&2
  fi
  if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then
    echo "ERROR: opencv_test_lsd_advance exited with $rc without a gtest failure summary (sanitizer abort?)" >&2
    tail -n 60 "$3" >&2
    failed=1
  fi
  if [ "$passed" -eq 0 ] && [ "$failed" -eq 0 ]; then
    echo "ERROR: no test ran" >&2
    failed=1
  fi
  passed_all=$((passed_all + passed)); failed_all=$((failed_all + failed))
  if [ "$rc" -ne 0 ] || [ "$failed" -ne 0 ] || [ "$reports" -ne 0 ]; then status=1; fi
}

build_tests "$BUILD" address,undefined ""
# Stop at the first report, with a stack; leaks are reports too.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
# Leaks inside OpenCV itself, each explained in the file; what was suppressed is printed.
export LSAN_OPTIONS="suppressions=$REPO/scripts/lsan_suppressions.txt:print_suppressions=1"
section "unit tests under ASan + UBSan"
run_tests "$BUILD" "${GTEST_FILTER:-*}:-LSDAdvance_LongSequence.*" "$BUILD/opencv_test_lsd_advance.sanitizers.log" \
  'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:'

# The tests of the code that runs in parallel (the tiles of BASE_FAST_LSD, the gradient rows, the
# stages on separate instances, computeLBD's tasks and its calls from several threads), on
# std::threads that ThreadSanitizer sees (test/thread_sanitizer_backend.cpp), at 1, 2, 3 and 8
# threads: built from their files alone.
build_tests "$TSAN_BUILD" thread "test_main.cpp;thread_sanitizer_backend.cpp;test_fast_lsd.cpp;test_robustness.cpp;test_lbd_descriptor.cpp"
# Exit (code 66) at the first report: an abort there hangs in ThreadSanitizer's own handler.
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$REPO/scripts/tsan_suppressions.txt:print_suppressions=1"
section "threaded unit tests under TSan"
run_tests "$TSAN_BUILD" "${GTEST_FILTER:-LSDAdvance_FastLsd.*:LSDAdvance_FastLsdOracle.*:LSDAdvance_Determinism.*:LSDAdvance_Concurrency.*:LSDAdvance_LBD.*thread*}" \
  "$TSAN_BUILD/opencv_test_lsd_advance.tsan.log" 'WARNING: ThreadSanitizer|ERROR: ThreadSanitizer'

section "done"
echo "sanitizers: $passed_all passed, $failed_all failed"
exit $status
