#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/test.sh
#
# Installs the Debian dependencies, fetches Debian's OpenCV source package of the installed
# version (for OpenCV's test framework `ts`, which Debian does not package), builds the module
# standalone with tests and the Python module, runs every unit test of opencv_test_lsd_advance and
# of opencv_test_lsd_advance_lsd_in_ximgproc (the module built with LineSegmentDetector in ximgproc),
# the Python tests and the tests of the programs and scripts (scripts/test_python.sh:
# misc/python/test, apps/lsd_advance_bench/test and scripts/test) and a short perf smoke run of
# opencv_perf_lsd_advance. Ends with the line `tests: N passed, M failed` (all of them together);
# exits non-zero on any failure.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   OPENCV_SOURCE_DIR      OpenCV source tree of the installed version (default:
#                          ${XDG_CACHE_HOME:-~/.cache}/lsd_advance/opencv-<version>, fetched there)
#   LSD_ADVANCE_DATA_DIR   test data directory, passed through to the tests
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
#   LSD_ADVANCE_ELSED_DIR  ELSED's sources for the optional peer in the samples and perf suite
#                          (default: ../shared/peers/elsed beside the repository when present;
#                          set it empty to build without; scripts/elsed_peer.sh)
#   GTEST_FILTER           the usual gtest filter, if a subset is wanted
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_BUILD_DIR:-$REPO/build}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
T0=$SECONDS
section() { echo; echo "==== [test] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh"

section "OpenCV source tree (for ts)"
if [ -z "${OPENCV_SOURCE_DIR:-}" ]; then
  OPENCV_SOURCE_DIR="$(bash "$REPO/scripts/fetch_opencv_source.sh" | tail -n1)"
fi
echo "OPENCV_SOURCE_DIR=$OPENCV_SOURCE_DIR"

section "configure ($BUILD)"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
  -DBUILD_TESTS=ON -DBUILD_EXAMPLES=ON -DOPENCV_SOURCE_DIR="$OPENCV_SOURCE_DIR" \
  "$(bash "$REPO/scripts/elsed_peer.sh")"

section "build"
cmake --build "$BUILD" -j"$JOBS"

export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
if [ -n "${LSD_ADVANCE_DATA_DIR:-}" ]; then
  export LSD_ADVANCE_DATA_DIR
  echo "LSD_ADVANCE_DATA_DIR=$LSD_ADVANCE_DATA_DIR"
fi

# Runs the gtest binary $1 of the build and adds its counts to passed / failed (a crash, or no
# test run at all, counts as a failure); sets skipped from its summary.
passed=0; failed=0; skipped=""
gtest_rc=0
run_gtest() {
  local name="$1" log="$BUILD/$1.log" rc=0 n_passed n_failed n_skipped
  ( cd "$BUILD" && "./$name" ) 2>&1 | tee "$log" || rc=${PIPESTATUS[0]}
  rc=${rc:-0}
  # gtest summary lines: "[  PASSED  ] N tests." / "[  FAILED  ] M tests, listed below:"
  n_passed="$(sed -nE 's/^\[  PASSED  \] ([0-9]+) tests?\..*/\1/p' "$log" | tail -n1)"
  n_failed="$(sed -nE 's/^\[  FAILED  \] ([0-9]+) tests?, listed below:.*/\1/p' "$log" | tail -n1)"
  n_skipped="$(sed -nE 's/^\[  SKIPPED \] ([0-9]+) tests?, listed below:.*/\1/p' "$log" | tail -n1)"
  n_passed="${n_passed:-0}"; n_failed="${n_failed:-0}"
  if [ "$rc" -ne 0 ] && [ "$n_failed" -eq 0 ]; then
    echo "ERROR: $name exited with $rc without a gtest failure summary (crash?)" >&2
    n_failed=1
  fi
  if [ "$rc" -eq 0 ] && [ "$n_passed" -eq 0 ] && [ "$n_failed" -eq 0 ]; then
    echo "ERROR: $name ran no test" >&2
    rc=1
  fi
  passed=$((passed + n_passed)); failed=$((failed + n_failed))
  if [ -n "$n_skipped" ]; then skipped=$(( ${skipped:-0} + n_skipped )); fi
  if [ "$rc" -ne 0 ]; then gtest_rc=$rc; fi
}

section "unit tests: opencv_test_lsd_advance"
run_gtest opencv_test_lsd_advance

section "unit tests against LineSegmentDetector moved to ximgproc: opencv_test_lsd_advance_lsd_in_ximgproc"
run_gtest opencv_test_lsd_advance_lsd_in_ximgproc

section "Python and sample program tests: scripts/test_python.sh"
PY_LOG="$BUILD/python_tests.log"
py_rc=0
bash "$REPO/scripts/test_python.sh" "$BUILD" 2>&1 | tee "$PY_LOG" || py_rc=${PIPESTATUS[0]}
py_rc=${py_rc:-0}
py_passed="$(sed -nE 's/^python tests: ([0-9]+) passed, ([0-9]+) failed$/\1/p' "$PY_LOG" | tail -n1)"
py_failed="$(sed -nE 's/^python tests: ([0-9]+) passed, ([0-9]+) failed$/\2/p' "$PY_LOG" | tail -n1)"
py_passed="${py_passed:-0}"; py_failed="${py_failed:-1}"
if [ "$py_rc" -ne 0 ] && [ "$py_failed" -eq 0 ]; then py_failed=1; fi
echo "C++ tests: $passed passed, $failed failed; Python and sample program tests: $py_passed passed, $py_failed failed"
passed=$((passed + py_passed))
failed=$((failed + py_failed))

section "perf smoke run: opencv_perf_lsd_advance"
perf_rc=0
if [ -x "$BUILD/opencv_perf_lsd_advance" ]; then
  ( cd "$BUILD" && ./opencv_perf_lsd_advance --perf_min_samples=1 --perf_force_samples=3 \
      --perf_time_limit=1 --perf_max_deviation=1000 ) >"$BUILD/opencv_perf_lsd_advance.log" 2>&1 \
    || perf_rc=$?
  grep -E '^\[ *(RUN|OK|FAILED|PASSED) *\]|^\[=+\]' "$BUILD/opencv_perf_lsd_advance.log" | tail -n 40 || true
  if [ "$perf_rc" -ne 0 ]; then
    tail -n 60 "$BUILD/opencv_perf_lsd_advance.log"
    echo "ERROR: opencv_perf_lsd_advance failed (exit $perf_rc); log: $BUILD/opencv_perf_lsd_advance.log" >&2
  fi
else
  echo "ERROR: $BUILD/opencv_perf_lsd_advance was not built" >&2
  perf_rc=1
fi

section "done"
if [ -n "$skipped" ]; then
  echo "tests: $passed passed, $failed failed, $skipped skipped"
else
  echo "tests: $passed passed, $failed failed"
fi
if [ "$gtest_rc" -ne 0 ] || [ "$py_rc" -ne 0 ] || [ "$failed" -ne 0 ] || [ "$perf_rc" -ne 0 ]; then
  exit 1
fi
