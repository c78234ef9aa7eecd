#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/sanitizers.sh
#
# Builds the library and opencv_test_lsd_advance with AddressSanitizer and
# UndefinedBehaviorSanitizer (-DLSD_ADVANCE_SANITIZE=address,undefined, every report fatal; OpenCV
# and its ts are linked as they are, not instrumented) in a build directory of its own, and runs the unit tests. Any sanitizer report (memory error,
# leak, undefined behaviour) or test failure fails the script. Ends with the line
# `sanitizers: N passed, M failed`.
#
# LSDAdvance_LongSequence.* is not run here: ASan's quarantine keeps freed memory resident by
# design, which is what that test measures. Everything else is.
#
# Environment:
#   LSD_ADVANCE_ASAN_BUILD_DIR  build directory (default: <repo>/build-asan)
#   OPENCV_SOURCE_DIR, LSD_ADVANCE_DATA_DIR, LSD_ADVANCE_JOBS  as for scripts/test.sh
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_ASAN_BUILD_DIR:-$REPO/build-asan}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
T0=$SECONDS
section() { echo; echo "==== [sanitizers] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh"
if [ -z "${OPENCV_SOURCE_DIR:-}" ]; then
  OPENCV_SOURCE_DIR="$(bash "$REPO/scripts/fetch_opencv_source.sh" | tail -n1)"
fi

section "configure ($BUILD, address,undefined)"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTS=ON -DBUILD_EXAMPLES=OFF \
  -DLSD_ADVANCE_SANITIZE=address,undefined -DOPENCV_SOURCE_DIR="$OPENCV_SOURCE_DIR"

section "build opencv_test_lsd_advance"
cmake --build "$BUILD" -j"$JOBS" --target opencv_test_lsd_advance

export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
# Stop at the first report, with a stack; leaks are reports too.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
# Leaks inside OpenCV itself, each explained in the file; what was suppressed is printed.
export LSAN_OPTIONS="suppressions=$REPO/scripts/lsan_suppressions.txt:print_suppressions=1"

section "unit tests under ASan + UBSan"
LOG="$BUILD/opencv_test_lsd_advance.sanitizers.log"
rc=0
( cd "$BUILD" && ./opencv_test_lsd_advance --gtest_filter="${GTEST_FILTER:-*}:-LSDAdvance_LongSequence.*" ) \
  >"$LOG" 2>&1 || rc=$?
grep -E '^\[ *(OK|FAILED|PASSED|SKIPPED) *\]|^\[=+\]' "$LOG" | tail -n 30 || true

passed="$(sed -nE 's/^\[  PASSED  \] ([0-9]+) tests?\..*/\1/p' "$LOG" | tail -n1)"
failed="$(sed -nE 's/^\[  FAILED  \] ([0-9]+) tests?, listed below:.*/\1/p' "$LOG" | tail -n1)"
passed="${passed:-0}"; failed="${failed:-0}"
reports="$(grep -cE 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' "$LOG" || true)"
if [ "$reports" -ne 0 ]; then
  echo "ERROR: $reports sanitizer report(s); log: $LOG" >&2
  grep -E -A40 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' "$LOG" | head -n 120 >&2
fi
if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then
  echo "ERROR: opencv_test_lsd_advance exited with $rc without a gtest failure summary (sanitizer abort?)" >&2
  tail -n 60 "$LOG" >&2
  failed=1
fi
if [ "$passed" -eq 0 ] && [ "$failed" -eq 0 ]; then
  echo "ERROR: no test ran" >&2
  failed=1
fi

section "done"
echo "sanitizers: $passed passed, $failed failed"
if [ "$rc" -ne 0 ] || [ "$failed" -ne 0 ] || [ "$reports" -ne 0 ]; then
  exit 1
fi
