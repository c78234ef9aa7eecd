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
# opencv_perf_lsd_advance. Whatever an earlier configure of the build folder cached (e.g.
# scripts/demo.sh's), it configures every test group on and fails, naming it, when one of them was
# not built. Ends with the line `tests: N passed, M failed, K skipped` (all of them together; the
# skipped ones are the tests of the evaluation data when LSD_ADVANCE_DATA_DIR is not set, and those
# say why); exits non-zero on any failure.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   OPENCV_SOURCE_DIR      OpenCV source tree of the installed version (default:
#                          ${XDG_CACHE_HOME:-~/.cache}/lsd_advance/opencv-<version>, fetched there)
#   LSD_ADVANCE_DATA_DIR   the evaluation data (doc/data.md), passed through to the tests; without
#                          it the tests that read it are skipped, except under CI=true (they fail)
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
#   LSD_ADVANCE_ELSED_DIR  ELSED's sources for the optional peer in the samples and perf suite
#                          (default: scripts/elsed_peer.sh's; set it empty to build without)
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

# Every option a test group depends on is given, so that no choice cached by an earlier configure
# of the same build folder (scripts/demo.sh's BUILD_TESTS=OFF, a sanitizer or a subset of test
# files, a Python module left out) leaves a group out.
section "configure ($BUILD)"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
  -DBUILD_TESTS=ON -DBUILD_EXAMPLES=ON -DBUILD_APPS=ON -DLSD_ADVANCE_PYTHON=ON \
  -DLSD_ADVANCE_TEST_FILES= -DLSD_ADVANCE_SANITIZE= -DLSD_ADVANCE_FUZZ=OFF \
  -DOPENCV_SOURCE_DIR="$OPENCV_SOURCE_DIR" "$(bash "$REPO/scripts/elsed_peer.sh")"

section "build"
cmake --build "$BUILD" -j"$JOBS"

# What the test groups run: the three gtest programs, the Python module, one program per sample
# and per app (their tests skip a missing program outside CI). A missing one fails here, by name.
missing=()
for program in opencv_test_lsd_advance opencv_test_lsd_advance_lsd_in_ximgproc opencv_perf_lsd_advance \
    $(cd "$REPO" && ls samples/*.cpp apps/lsd_advance_bench/*.cpp | xargs -n1 basename | sed 's/\.cpp$//'); do
  [ -x "$BUILD/$program" ] || missing+=("$program")
done
ls "$BUILD"/python/lsd_advance/_lsd_advance*.so >/dev/null 2>&1 || missing+=("the Python module (python/lsd_advance)")
if [ ${#missing[@]} -gt 0 ]; then
  echo "ERROR: the build in $BUILD lacks what the tests run: ${missing[*]}" >&2
  exit 1
fi

export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
if [ -n "${LSD_ADVANCE_DATA_DIR:-}" ]; then
  export LSD_ADVANCE_DATA_DIR
  echo "LSD_ADVANCE_DATA_DIR=$LSD_ADVANCE_DATA_DIR"
elif [ "${CI:-}" = "true" ]; then
  echo "LSD_ADVANCE_DATA_DIR is not set and CI=true: the tests that read the evaluation data fail (doc/data.md)"
else
  echo "LSD_ADVANCE_DATA_DIR is not set: the tests that read the evaluation data are skipped (doc/data.md)"
fi

# Runs the gtest binary $1 of the build and adds its counts to passed / failed / skipped (a crash,
# or no test run at all, counts as a failure).
passed=0; failed=0; skipped=0
gtest_rc=0
run_gtest() {
  local name="$1" log="$BUILD/$1.log" rc=0 n_passed n_failed n_skipped n_skipstat
  ( cd "$BUILD" && "./$name" ) 2>&1 | tee "$log" || rc=${PIPESTATUS[0]}
  rc=${rc:-0}
  # gtest summary lines: "[  PASSED  ] N tests." / "[  FAILED  ] M tests, listed below:" /
  # "[  SKIPPED ] K tests, listed below:" (GTEST_SKIP, not among the passed); OpenCV's ts counts a
  # test that threw SkipTestException (the data's, without LSD_ADVANCE_DATA_DIR) as passed and
  # prints "[ SKIPSTAT ] K tests skipped": those are taken out of the passed.
  n_passed="$(sed -nE 's/^\[  PASSED  \] ([0-9]+) tests?\..*/\1/p' "$log" | tail -n1)"
  n_failed="$(sed -nE 's/^\[  FAILED  \] ([0-9]+) tests?, listed below:.*/\1/p' "$log" | tail -n1)"
  n_skipped="$(sed -nE 's/^\[  SKIPPED \] ([0-9]+) tests?, listed below:.*/\1/p' "$log" | tail -n1)"
  n_skipstat="$(sed -nE 's/^\[ SKIPSTAT \] ([0-9]+) tests? skipped$/\1/p' "$log" | tail -n1)"
  n_passed="${n_passed:-0}"; n_failed="${n_failed:-0}"; n_skipped=$(( ${n_skipped:-0} + ${n_skipstat:-0} ))
  if [ "$rc" -ne 0 ] && [ "$n_failed" -eq 0 ]; then
    echo "ERROR: $name exited with $rc without a gtest failure summary (crash?)" >&2
    n_failed=1
  fi
  if [ "$rc" -eq 0 ] && [ "$n_passed" -eq 0 ] && [ "$n_failed" -eq 0 ]; then
    echo "ERROR: $name ran no test" >&2
    rc=1
  fi
  passed=$((passed + n_passed - ${n_skipstat:-0})); failed=$((failed + n_failed))
  skipped=$((skipped + n_skipped))
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
PY_SUMMARY='^python tests: ([0-9]+) passed, ([0-9]+) failed, ([0-9]+) skipped$'
py_passed="$(sed -nE "s/$PY_SUMMARY/\\1/p" "$PY_LOG" | tail -n1)"
py_failed="$(sed -nE "s/$PY_SUMMARY/\\2/p" "$PY_LOG" | tail -n1)"
py_skipped="$(sed -nE "s/$PY_SUMMARY/\\3/p" "$PY_LOG" | tail -n1)"
py_passed="${py_passed:-0}"; py_failed="${py_failed:-1}"; py_skipped="${py_skipped:-0}"
if [ "$py_rc" -ne 0 ] && [ "$py_failed" -eq 0 ]; then py_failed=1; fi
echo "C++ tests: $passed passed, $failed failed, $skipped skipped; Python and sample program tests:" \
  "$py_passed passed, $py_failed failed, $py_skipped skipped"
passed=$((passed + py_passed))
failed=$((failed + py_failed))
skipped=$((skipped + py_skipped))

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
perf_skipped="$(sed -nE 's/^\[ SKIPSTAT \] ([0-9]+) tests? skipped$/\1/p' "$BUILD/opencv_perf_lsd_advance.log" 2>/dev/null | tail -n1)"
if [ "$skipped" -gt 0 ] || [ -n "$perf_skipped" ]; then
  echo "Skipped: $skipped tests (their reasons: the SKIP and SKIPPED lines above) and ${perf_skipped:-0} perf cases" \
    "($BUILD/opencv_perf_lsd_advance.log); LSD_ADVANCE_DATA_DIR: ${LSD_ADVANCE_DATA_DIR:-not set} (doc/data.md)"
fi
echo "tests: $passed passed, $failed failed, $skipped skipped"
if [ "$gtest_rc" -ne 0 ] || [ "$py_rc" -ne 0 ] || [ "$failed" -ne 0 ] || [ "$perf_rc" -ne 0 ]; then
  exit 1
fi
