#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/check_scalar.sh
#
# The scalar build: the module compiled with LSD_ADVANCE_SCALAR=ON (src/primitives.hpp), so that
# every vector path (#if CV_SIMD128) takes its scalar #else, as on a platform without universal
# intrinsics, and the tests that hold the optimised parts to their oracles run on it: BASE_FAST_LSD
# against OpenCV's LSD, the smoothing against OpenCV's Gaussian, the grouping and the merging
# sweep against their all-pairs rules, the line responses. The build proves itself scalar: a
# static_assert in src/fast_lsd/kernels.cpp, and LSDAdvance_Build.universal_intrinsics_are_compiled_
# unless_the_scalar_build, which must run and pass. Only the test files of those tests are built.
#
# Environment: LSD_ADVANCE_SCALAR_BUILD_DIR (default <repo>/build-scalar), LSD_ADVANCE_JOBS,
# OPENCV_SOURCE_DIR, LSD_ADVANCE_DATA_DIR (as scripts/test.sh).
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_SCALAR_BUILD_DIR:-$REPO/build-scalar}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
T0=$SECONDS
section() { echo; echo "==== [scalar] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh"
if [ -z "${OPENCV_SOURCE_DIR:-}" ]; then
  OPENCV_SOURCE_DIR="$(bash "$REPO/scripts/fetch_opencv_source.sh" | tail -n1)"
fi

section "configure ($BUILD, LSD_ADVANCE_SCALAR=ON)"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=ON -DBUILD_EXAMPLES=OFF -DBUILD_APPS=OFF \
  -DLSD_ADVANCE_SCALAR=ON -DOPENCV_SOURCE_DIR="$OPENCV_SOURCE_DIR" \
  -DLSD_ADVANCE_TEST_FILES="test_main.cpp;test_fast_lsd.cpp;test_aliased_edges.cpp;test_grouping.cpp;test_merging_sweep.cpp;test_line_response.cpp"

section "build opencv_test_lsd_advance"
cmake --build "$BUILD" -j"$JOBS" --target opencv_test_lsd_advance

export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
section "the oracle tests on the scalar paths"
LOG="$BUILD/opencv_test_lsd_advance.scalar.log"
rc=0
( cd "$BUILD" && ./opencv_test_lsd_advance \
    --gtest_filter='LSDAdvance_Build.*:LSDAdvance_FastLsd*:LSDAdvance_AliasedEdges.the_smoothing*:LSDAdvance_Grouping.*:LSDAdvance_MergingSweep*:LSDAdvance_LineResponse.*' ) \
  >"$LOG" 2>&1 || rc=$?
grep -E '^\[ *(OK|FAILED|PASSED|SKIPPED) *\]|^\[=+\]' "$LOG" | tail -n 40 || true
passed="$(sed -nE 's/^\[  PASSED  \] ([0-9]+) tests?\..*/\1/p' "$LOG" | tail -n1)"
failed="$(sed -nE 's/^\[  FAILED  \] ([0-9]+) tests?, listed below:.*/\1/p' "$LOG" | tail -n1)"
passed="${passed:-0}"; failed="${failed:-0}"
if ! grep -qE '^\[ +OK \] LSDAdvance_Build\.universal_intrinsics_are_compiled_unless_the_scalar_build' "$LOG"; then
  echo "ERROR: the check that this build compiled no vector path did not pass; log: $LOG" >&2
  failed=$((failed + 1))
fi
if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then
  echo "ERROR: opencv_test_lsd_advance exited with $rc without a gtest failure summary; log: $LOG" >&2
  failed=1
fi
if [ "$passed" -eq 0 ] && [ "$failed" -eq 0 ]; then
  echo "ERROR: no test ran" >&2
  failed=1
fi
section "done"
echo "scalar build: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
