#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/check_intree.sh
#
# In-tree build check: builds a minimal OpenCV 4.10 (the `opencv` source package of Debian 13,
# trixie, with its contrib) with this checkout as an extra module, exactly as opencv_contrib
# modules are built, then runs the in-tree opencv_test_lsd_advance, imports the Python bindings
# and runs the Python tests of misc/python/test on that cv2: with OpenCV's own runner
# (modules/python/test/test.py, which finds them through opencv_python_tests.cfg), then with the
# tests of the samples and scripts (scripts/test_python.sh). With the standalone build and tests on
# Debian 12's OpenCV 4.6 (scripts/test.sh), both ends of the supported versions are tested.
# Fetching the source changes nothing in the system's apt set-up (scripts/fetch_opencv_source.sh
# --suite: a private apt state with trixie's source index only).
#
# Environment:
#   LSD_ADVANCE_INTREE_DIR  scratch dir (default: <repo>/build-intree); holds modules/lsd_advance
#                           (a copy of this checkout's module files: OpenCV takes the module name
#                           from the folder name) and the OpenCV build dir opencv-build/
#   OPENCV_SOURCE_DIR       OpenCV source tree with contrib/ (default: the one
#                           scripts/fetch_opencv_source.sh --suite <LSD_ADVANCE_INTREE_SUITE> fetches)
#   LSD_ADVANCE_INTREE_SUITE  Debian release whose `opencv` source package is built (default:
#                           trixie, OpenCV 4.10); empty: the source package of the installed
#                           libopencv-dev (Debian 12: 4.6, the one the standalone build uses)
#   LSD_ADVANCE_INTREE_PYTHON=0  skip the cv2 bindings build, import check and Python tests
#   LSD_ADVANCE_DATA_DIR    passed through to the tests
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SCRATCH="${LSD_ADVANCE_INTREE_DIR:-$REPO/build-intree}"
WITH_PYTHON="${LSD_ADVANCE_INTREE_PYTHON:-1}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
T0=$SECONDS

section() { echo; echo "==== [check_intree] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh" --intree

section "OpenCV source"
SUITE="${LSD_ADVANCE_INTREE_SUITE-trixie}"
if [ -z "${OPENCV_SOURCE_DIR:-}" ]; then
  OPENCV_SOURCE_DIR="$(bash "$REPO/scripts/fetch_opencv_source.sh" ${SUITE:+--suite "$SUITE"} | tail -n1)"
fi
[ -d "$OPENCV_SOURCE_DIR/contrib/modules/ximgproc" ] \
  || { echo "ERROR: $OPENCV_SOURCE_DIR has no contrib/modules/ximgproc" >&2; exit 1; }
echo "OpenCV source: $OPENCV_SOURCE_DIR"

# OpenCV derives the module name from the folder name: mirror the module's files into
# $SCRATCH/modules/lsd_advance (a copy, not a symlink: the scratch dir may live inside the
# checkout). Only files whose content changed are rewritten (with a fresh mtime), so the
# build system rebuilds exactly what changed; files gone from the checkout are removed.
MODDIR="$SCRATCH/modules/lsd_advance"
mkdir -p "$MODDIR"
MODULE_ENTRIES=(CMakeLists.txt cmake include misc src test perf samples apps doc)
( cd "$MODDIR" && find . -type f ) | while IFS= read -r f; do
  [ -f "$REPO/$f" ] || rm -f "$MODDIR/$f"
done
for entry in "${MODULE_ENTRIES[@]}"; do
  [ -e "$REPO/$entry" ] || continue
  ( cd "$REPO" && find "$entry" -type f ) | while IFS= read -r f; do
    if ! cmp -s "$REPO/$f" "$MODDIR/$f"; then
      mkdir -p "$(dirname "$MODDIR/$f")"
      cp "$REPO/$f" "$MODDIR/$f"
    fi
  done
done
BUILD="$SCRATCH/opencv-build"

BUILD_LIST="core,imgproc,imgcodecs,videoio,highgui,features2d,flann,calib3d,video,ts,ximgproc,line_descriptor,lsd_advance"
PY_ARGS=(-DBUILD_opencv_python3=OFF -DBUILD_opencv_python2=OFF)
if [ "$WITH_PYTHON" = 1 ]; then
  BUILD_LIST="$BUILD_LIST,python3,python_tests"
  PY_ARGS=(-DBUILD_opencv_python3=ON -DBUILD_opencv_python2=OFF
           -DPYTHON3_EXECUTABLE=/usr/bin/python3 -DPYTHON_DEFAULT_EXECUTABLE=/usr/bin/python3)
fi
# A build dir configured from another OpenCV source tree cannot be reused: start it afresh.
if [ -f "$BUILD/CMakeCache.txt" ]; then
  old_src="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$BUILD/CMakeCache.txt")"
  if [ "$(cd "$old_src" 2>/dev/null && pwd -P)" != "$(cd "$OPENCV_SOURCE_DIR" && pwd -P)" ]; then
    echo "Build dir $BUILD was configured from '$old_src': removing it"
    rm -rf "$BUILD"
  fi
fi
GEN_ARGS=()
if command -v ninja >/dev/null 2>&1 && [ ! -f "$BUILD/Makefile" ]; then GEN_ARGS=(-G Ninja); fi
CCACHE_ARGS=(-DENABLE_CCACHE=OFF)
if command -v ccache >/dev/null 2>&1; then CCACHE_ARGS=(-DENABLE_CCACHE=ON); fi

# Optimised at -O1: the check is of the integration (module, tests, bindings), and -O1 compiles
# OpenCV's modules in markedly less time than Release's -O3; the optimised code is what the
# standalone build tests (same compiler, no -ffast-math: the same floating-point results).
section "configure OpenCV ($BUILD)"
cmake -S "$OPENCV_SOURCE_DIR" -B "$BUILD" "${GEN_ARGS[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DOPENCV_EXTRA_MODULES_PATH="$OPENCV_SOURCE_DIR/contrib/modules/ximgproc;$OPENCV_SOURCE_DIR/contrib/modules/line_descriptor;$SCRATCH/modules/lsd_advance" \
  -DBUILD_LIST="$BUILD_LIST" \
  -DBUILD_SHARED_LIBS=ON -DBUILD_TESTS=ON -DBUILD_PERF_TESTS=ON -DBUILD_EXAMPLES=ON \
  -DBUILD_DOCS=OFF -DBUILD_opencv_apps=OFF -DBUILD_JAVA=OFF -DBUILD_opencv_java=OFF -DBUILD_opencv_js=OFF \
  -DBUILD_opencv_world=OFF -DINSTALL_TESTS=OFF -DOPENCV_GENERATE_PKGCONFIG=OFF \
  "${PY_ARGS[@]}" "${CCACHE_ARGS[@]}" \
  -DOPENCV_DOWNLOAD_TRIES_LIST= -DOPENCV_SKIP_PYTHON_WARNING=ON \
  -DCPU_DISPATCH= -DENABLE_PRECOMPILED_HEADERS=OFF \
  -DWITH_IPP=OFF -DWITH_OPENCL=OFF -DWITH_CUDA=OFF -DWITH_ITT=OFF -DWITH_CAROTENE=OFF \
  -DWITH_EIGEN=OFF -DWITH_LAPACK=OFF -DWITH_TBB=OFF -DWITH_OPENMP=OFF -DWITH_VA=OFF -DWITH_VA_INTEL=OFF \
  -DWITH_FFMPEG=OFF -DWITH_GSTREAMER=OFF -DWITH_V4L=OFF -DWITH_1394=OFF -DWITH_GPHOTO2=OFF \
  -DWITH_GTK=OFF -DWITH_QT=OFF -DWITH_OPENGL=OFF -DWITH_VTK=OFF \
  -DWITH_OPENEXR=OFF -DWITH_OPENJPEG=OFF -DWITH_JASPER=OFF -DWITH_GDAL=OFF -DWITH_GDCM=OFF \
  -DWITH_PROTOBUF=OFF -DWITH_QUIRC=OFF -DWITH_ADE=OFF -DWITH_IMGCODEC_HDR=ON \
  -DWITH_AVIF=OFF -DWITH_SPNG=OFF -DWITH_OBSENSOR=OFF -DWITH_WAYLAND=OFF -DWITH_FLATBUFFERS=OFF \
  -DBUILD_ZLIB=OFF -DBUILD_JPEG=OFF -DBUILD_PNG=OFF -DBUILD_TIFF=OFF -DBUILD_WEBP=OFF \
  -DBUILD_OPENJPEG=OFF -DBUILD_JASPER=OFF -DBUILD_OPENEXR=OFF -DBUILD_PROTOBUF=OFF \
  -DBUILD_ITT=OFF -DBUILD_IPP_IW=OFF \
  >"$SCRATCH/configure.log" 2>&1 \
  || { tail -n 60 "$SCRATCH/configure.log"; echo "ERROR: OpenCV configure failed (log: $SCRATCH/configure.log)" >&2; exit 1; }
grep -E 'To be built:|Disabled:|Unavailable:|lsd_advance' "$SCRATCH/configure.log" || true

TARGETS=(opencv_lsd_advance opencv_test_lsd_advance)
[ -n "$(ls "$REPO"/perf/*.cpp 2>/dev/null)" ] && TARGETS+=(opencv_perf_lsd_advance)
for s in "$REPO"/samples/*.cpp; do
  [ -f "$s" ] && TARGETS+=("example_lsd_advance_$(basename "$s" .cpp)")
done

# The bindings in the same build: their one large file (cv2.cpp) then compiles beside the
# others instead of alone at the end. OpenCV 4.10's typing-stub generator warns "Typing stubs
# generation has failed" when G-API is not built (upstream); the stubs are optional and the
# bindings are complete without them.
[ "$WITH_PYTHON" = 1 ] && TARGETS+=(opencv_python3)

section "build ${TARGETS[*]}"
nice cmake --build "$BUILD" -j"$JOBS" --target "${TARGETS[@]}"

section "run in-tree opencv_test_lsd_advance"
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
# The long data-driven tests (real data sets, 20,000 frames, 10000x10000 image) run the same
# code as the standalone build, which runs every test; in-tree they would only add minutes.
INTREE_FILTER="${GTEST_FILTER:--LSDAdvance_RealData.*:LSDAdvance_Matching.*:LSDAdvance_LongSequence.*:*10000x10000*}"
echo "gtest filter: $INTREE_FILTER"
rc=0
"$BUILD/bin/opencv_test_lsd_advance" --gtest_filter="$INTREE_FILTER" || rc=$?
if [ "$rc" -ne 0 ]; then
  echo "ERROR: in-tree opencv_test_lsd_advance failed (exit $rc)" >&2
  exit "$rc"
fi

if [ "$WITH_PYTHON" = 1 ]; then
  section "Python import check"
  PYTHONPATH="$BUILD/python_loader" LD_LIBRARY_PATH="$BUILD/lib" /usr/bin/python3 -c \
    'import cv2; f = cv2.ximgproc.createLSDAdvance; print("cv2", cv2.__version__, "from", cv2.__file__, "->", f.__doc__.splitlines()[0] if f.__doc__ else f)'

  section "Python tests by OpenCV's runner (misc/python/test, found through opencv_python_tests.cfg)"
  grep -qx '.*modules/lsd_advance/misc/python/test' "$BUILD/opencv_python_tests.cfg" \
    || { echo "ERROR: $BUILD/opencv_python_tests.cfg does not list the module's misc/python/test" >&2; exit 1; }
  runner_log="$SCRATCH/python_runner.log"
  runner_rc=0
  ( cd "$BUILD" && OPENCV_PYTEST_FILTER=test_lsd_advance PYTHONPATH="$BUILD/python_loader" LD_LIBRARY_PATH="$BUILD/lib" \
      PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 "$OPENCV_SOURCE_DIR/modules/python/test/test.py" \
      --repo "$OPENCV_SOURCE_DIR" ) 2>&1 | tee "$runner_log" || runner_rc=${PIPESTATUS[0]}
  ran="$(sed -nE 's/^Ran ([0-9]+) tests? in .*/\1/p' "$runner_log" | tail -n1)"
  if [ "${runner_rc:-0}" -ne 0 ] || [ "${ran:-0}" -eq 0 ]; then
    echo "ERROR: OpenCV's Python test runner failed or ran no test (exit ${runner_rc:-0}, ${ran:-0} tests)" >&2
    exit 1
  fi

  section "Python tests, with those of the samples and scripts, on the in-tree cv2 (scripts/test_python.sh, LSD_ADVANCE_PY_BACKEND=cv2)"
  LSD_ADVANCE_PY_BACKEND=cv2 PYTHONPATH="$BUILD/python_loader" LD_LIBRARY_PATH="$BUILD/lib" \
    bash "$REPO/scripts/test_python.sh" "$BUILD"
fi

section "in-tree check passed"
