#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/test_python.sh <build dir>
#
# Runs, with pytest, the Python tests of the bindings (misc/python/test, where OpenCV's own runner
# finds them in-tree; OpenCV's tests_common from the build's OpenCV source tree) on the module of a
# standalone build (<build>/python/lsd_advance, LSD_ADVANCE_PYTHON=ON), the tests of the programs
# (apps/lsd_advance_bench/test: the apps' error paths and folder runs, their method files, the C++
# and Python samples) and of the scripts (scripts/test/: the documentation's checks, the configure
# that scripts/demo.sh and scripts/test.sh share). Prints
# `python tests: N passed, M failed, K skipped` last (all folders); exits non-zero when a test
# fails or errors.
#
# Environment: LSD_ADVANCE_PY_BACKEND=cv2 tests cv2.ximgproc instead: <build dir> is then the
# OpenCV build dir of an in-tree build, whose cv2 the caller puts on PYTHONPATH (and
# LD_LIBRARY_PATH) and whose bin/example_lsd_advance_* samples are run (the apps are built
# standalone only: their tests skip); LSD_ADVANCE_SAMPLE_PREFIX (the C++ programs' path without
# their name) overrides where the programs are; OPENCV_SAMPLES_DATA_PATH (default: Debian's
# opencv-doc data); CI=true makes missing data or programs fail instead of skip.
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(cd "${1:?usage: test_python.sh <build dir>}" && pwd)"
PYTHON=/usr/bin/python3  # Debian's, with python3-opencv, python3-numpy and python3-pytest

if [ "${LSD_ADVANCE_PY_BACKEND:-standalone}" = standalone ] && \
   ! ls "$BUILD"/python/lsd_advance/_lsd_advance*.so >/dev/null 2>&1; then
  echo "ERROR: no Python module in $BUILD/python/lsd_advance (configure with -DLSD_ADVANCE_PYTHON=ON and build)" >&2
  echo "python tests: 0 passed, 1 failed, 0 skipped"
  exit 1
fi

# OpenCV's tests_common (NewOpenCVTests): from the standalone build's OPENCV_SOURCE_DIR, or from
# the source tree of the OpenCV build.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$BUILD/CMakeCache.txt"; }
OPENCV_TREE="$(cache_value OPENCV_SOURCE_DIR)"
[ -n "$OPENCV_TREE" ] || OPENCV_TREE="$(cache_value CMAKE_HOME_DIRECTORY)"
if [ ! -f "$OPENCV_TREE/modules/python/test/tests_common.py" ]; then
  echo "ERROR: no OpenCV source tree with modules/python/test/tests_common.py for $BUILD ('$OPENCV_TREE')" >&2
  echo "python tests: 0 passed, 1 failed, 0 skipped"
  exit 1
fi
export PYTHONPATH="$OPENCV_TREE/modules/python/test${PYTHONPATH:+:$PYTHONPATH}"

if [ "${LSD_ADVANCE_PY_BACKEND:-standalone}" = standalone ]; then
  export PYTHONPATH="$BUILD/python:$PYTHONPATH"
  SAMPLE_PREFIX="$BUILD/"
else
  SAMPLE_PREFIX="$BUILD/bin/example_lsd_advance_"  # an OpenCV build dir
fi
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
export LSD_ADVANCE_SAMPLE_PREFIX="${LSD_ADVANCE_SAMPLE_PREFIX:-$SAMPLE_PREFIX}"
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in the source tree

REPORT="$(mktemp)"
trap 'rm -f "$REPORT"' EXIT
rc=0
# -p no:cacheprovider: write nothing into the source tree.
"$PYTHON" -m pytest -p no:cacheprovider -q -rs --junitxml="$REPORT" "$REPO/misc/python/test" \
  "$REPO/apps/lsd_advance_bench/test" "$REPO/scripts/test" || rc=$?

read -r passed failed skipped < <("$PYTHON" - "$REPORT" <<'PY'
import sys
import xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
suite = root if root.tag == "testsuite" else root.find("testsuite")
tests, failures, errors, skipped = (int(suite.get(k, 0)) for k in ("tests", "failures", "errors", "skipped"))
print(tests - failures - errors - skipped, failures + errors, skipped)
PY
) || { passed=0; failed=1; skipped=0; }
# pytest exits non-zero also when nothing ran (collection error): count that as a failure.
if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then failed=1; fi
echo "python tests: $passed passed, $failed failed, $skipped skipped"
[ "$rc" -eq 0 ] && [ "$failed" -eq 0 ]
