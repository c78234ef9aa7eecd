#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/check_install.sh [<build dir>]
#
# Checks the install of a configured and built standalone build (default: $LSD_ADVANCE_BUILD_DIR,
# else <repo>/build, as scripts/test.sh leaves it) as a user would use it:
#   1. `cmake --install <build> --prefix <fresh temp prefix>`; the header tree, library, CMake
#      package and pkg-config file are where doc/building.md says, and no test, perf test, ts or fuzzer
#      is installed;
#   2. the consumer project scripts/install_consumer (a copy) configured with
#      CMAKE_PREFIX_PATH=<prefix> only, built, and run on OpenCV's building.jpg: it must report a
#      positive segment count;
#   3. the same main.cpp built with `g++ main.cpp $(pkg-config --cflags --libs opencv_lsd_advance)`
#      (PKG_CONFIG_PATH=<prefix>/<libdir>/pkgconfig, -Wl,-rpath) must report the same count;
#   4. an installed sample program (<prefix>/bin/lsd_advance_demo) runs through its install
#      RPATH, loads the installed library, and detects as many segments as the consumer;
#   5. consumers see the KeyLine API (HAVE_OPENCV_LINE_DESCRIPTOR) exactly when the library has it;
#   6. when the build has the Python module (LSD_ADVANCE_PYTHON=ON), the installed `lsd_advance`
#      imports from <prefix> (PYTHONPATH) and detects as many segments as the consumer, as KeyLines
#      that cv2's LBD describes;
#   7. doc/building.md "Another prefix": in a clean shell (env -i, PATH=/usr/local/bin:/usr/bin:/bin) that
#      sources only <prefix>/bin/setup_vars_lsd_advance.sh, the commands of doc/building.md and the
#      tutorial run as written: the sample program by name, pkg-config and a program built with
#      its flags (no rpath), the consumer configured without -DCMAKE_PREFIX_PATH, `python3`
#      importing lsd_advance, and the installed Python detect sample; all from <prefix>, all
#      with the consumer's segment count.
# The consumer is not installed: it is this check's project, a user's to copy (doc/building.md).
# Exits non-zero with an `ERROR:` line on the first failure; the temp prefix is removed on success
# and kept (path printed) on failure.
#
# Environment:
#   OPENCV_SAMPLES_DATA_PATH  folder of OpenCV's sample data (default: Debian opencv-doc's)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${1:-${LSD_ADVANCE_BUILD_DIR:-$REPO/build}}"
DATA="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
IMAGE="$DATA/building.jpg"
T0=$SECONDS

fail() { echo "ERROR: check_install: $*" >&2; exit 1; }
trap 'echo "ERROR: check_install: line $LINENO failed: $BASH_COMMAND" >&2' ERR
step() { echo "==== [check_install] $* ($((SECONDS - T0)) s)"; }
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$BUILD/CMakeCache.txt"; }
# the integer that follows the line start $2 in the text $1
count_in() { sed -nE "s|^$2 *([0-9]+).*|\1|p" <<<"$1" | head -n1; }

[ -f "$BUILD/CMakeCache.txt" ] || fail "$BUILD is not a configured build directory (no CMakeCache.txt)"
[ "$(cache_value CMAKE_PROJECT_NAME)" = "lsd_advance" ] \
  || fail "$BUILD is not a standalone lsd_advance build (CMAKE_PROJECT_NAME is not lsd_advance)"
[ -f "$IMAGE" ] || fail "$IMAGE is missing (Debian: apt-get install opencv-doc, or set OPENCV_SAMPLES_DATA_PATH)"
for tool in cmake g++ pkg-config; do
  command -v "$tool" >/dev/null || fail "$tool is not installed"
done

WORK="$(mktemp -d "${TMPDIR:-/tmp}/lsd_advance_check_install.XXXXXX")"
PREFIX="$WORK/prefix"
cleanup() {
  if [ "$1" -eq 0 ]; then rm -rf "$WORK"; else echo "check_install: kept $WORK for inspection" >&2; fi
}
trap 'cleanup $?' EXIT

LIBDIR="$(cache_value CMAKE_INSTALL_LIBDIR)"
[ -n "$LIBDIR" ] || fail "CMAKE_INSTALL_LIBDIR is not in $BUILD/CMakeCache.txt"
for var in CMAKE_INSTALL_LIBDIR CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR CMAKE_INSTALL_DATADIR \
           LSD_ADVANCE_PYTHON_INSTALL_DIR; do
  case "$(cache_value "$var")" in
    /*) fail "$var is absolute ($(cache_value "$var")): installing would write outside the temp prefix";;
  esac
done

step "install $BUILD into $PREFIX"
cmake --install "$BUILD" --prefix "$PREFIX" >"$WORK/install.log" 2>&1 \
  || { cat "$WORK/install.log" >&2; fail "cmake --install $BUILD --prefix $PREFIX failed"; }

step "installed tree"
INC="$PREFIX/include/opencv4/opencv2"
[ -f "$INC/lsd_advance.hpp" ] || fail "missing $INC/lsd_advance.hpp"
for h in "$REPO"/include/opencv2/lsd_advance/*.hpp; do
  [ -f "$INC/lsd_advance/$(basename "$h")" ] || fail "missing $INC/lsd_advance/$(basename "$h")"
done
[ ! -e "$PREFIX/include/opencv2" ] || fail "headers installed to include/opencv2 instead of include/opencv4/opencv2"
LIB="$PREFIX/$LIBDIR/libopencv_lsd_advance.so"
if [ ! -L "$LIB" ] || [ ! -f "$(readlink -f "$LIB")" ]; then fail "$LIB is not a symlink to the installed library"; fi
PKGDIR="$PREFIX/$LIBDIR/cmake/opencv_lsd_advance"
for f in opencv_lsd_advanceConfig.cmake opencv_lsd_advanceConfigVersion.cmake opencv_lsd_advanceTargets.cmake; do
  [ -f "$PKGDIR/$f" ] || fail "missing $PKGDIR/$f"
done
PC_DIR="$PREFIX/$LIBDIR/pkgconfig"
[ -f "$PC_DIR/opencv_lsd_advance.pc" ] || fail "missing $PC_DIR/opencv_lsd_advance.pc"
# Nothing of the tests: no test or perf binary, no ts library or header, no fuzzer.
not_installed="$(find "$PREFIX" | grep -E '/opencv_(test|perf)_[^/]*$|lsda_opencv_ts|/lsd_advance_fuzz[^/]*$|/opencv2/ts(\.hpp|/|$)' || true)"
[ -z "$not_installed" ] || fail "tests/ts/fuzzer were installed:"$'\n'"$not_installed"
echo "$(find "$PREFIX" -type f | wc -l) files installed; headers, library, CMake package, pkg-config file present; no tests"

step "CMake consumer (scripts/install_consumer, CMAKE_PREFIX_PATH=$PREFIX)"
CONSUMER_SRC="$REPO/scripts/install_consumer"
cp -r "$CONSUMER_SRC" "$WORK/consumer"
cmake -S "$WORK/consumer" -B "$WORK/consumer/build" -DCMAKE_PREFIX_PATH="$PREFIX" >"$WORK/consumer.log" 2>&1 \
  || { cat "$WORK/consumer.log" >&2; fail "configuring the consumer against $PREFIX failed"; }
found_dir="$(sed -n 's/^opencv_lsd_advance_DIR:[A-Z]*=//p' "$WORK/consumer/build/CMakeCache.txt")"
[ "$found_dir" = "$PKGDIR" ] || fail "the consumer found opencv_lsd_advance in '$found_dir', not in $PKGDIR"
cmake --build "$WORK/consumer/build" >>"$WORK/consumer.log" 2>&1 \
  || { cat "$WORK/consumer.log" >&2; fail "building the consumer against $PREFIX failed"; }
out="$("$WORK/consumer/build/lsd_advance_consumer" "$IMAGE")" || fail "lsd_advance_consumer $IMAGE failed: $out"
echo "$out"
cmake_count="$(count_in "$out" "")"
if [ -z "$cmake_count" ] || [ "$cmake_count" -le 0 ]; then fail "the CMake consumer reported no segments: '$out'"; fi
# Bad input: one "Error:" line and exit status 1.
for bad in "" "$WORK/no_such_image.jpg"; do
  rc=0
  err="$("$WORK/consumer/build/lsd_advance_consumer" ${bad:+"$bad"} 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 1 ] || [ "$(wc -l <<<"$err")" -ne 1 ] || [[ "$err" != "Error: "* ]]; then
    fail "lsd_advance_consumer ${bad:-without an image} should print one 'Error:' line and exit 1, got $rc: $err"
  fi
done

step "pkg-config consumer (g++ main.cpp \$(pkg-config --cflags --libs opencv_lsd_advance))"
export PKG_CONFIG_PATH="$PC_DIR${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
pc_libdir="$(pkg-config --variable=libdir opencv_lsd_advance)"
[ "$pc_libdir" = "$PREFIX/$LIBDIR" ] || fail "pkg-config libdir is '$pc_libdir', expected $PREFIX/$LIBDIR"
pc_version="$(pkg-config --modversion opencv_lsd_advance)"
cmake_version="$(sed -n 's/^set(PACKAGE_VERSION "\(.*\)")$/\1/p' "$PKGDIR/opencv_lsd_advanceConfigVersion.cmake")"
[ "$pc_version" = "$cmake_version" ] || fail "pkg-config version $pc_version differs from the CMake package's $cmake_version"
# shellcheck disable=SC2046  # pkg-config's output is meant to be split into arguments
( cd "$WORK/consumer" && g++ main.cpp $(pkg-config --cflags --libs opencv_lsd_advance) \
    -Wl,-rpath,"$pc_libdir" -o lsd_advance_consumer_pc ) || fail "building main.cpp with pkg-config failed"
out="$("$WORK/consumer/lsd_advance_consumer_pc" "$IMAGE")" || fail "the pkg-config build of main.cpp failed on $IMAGE: $out"
echo "$out (version $pc_version)"
[ "$(count_in "$out" "")" = "$cmake_count" ] || fail "pkg-config build reports '$out', the CMake build $cmake_count segments"

step "KeyLine API seen by consumers = KeyLine API of the library"
# (outputs captured first: grep -q closing a pipe early would fail the pipeline under pipefail)
lib_symbols="$(nm -DC "$(readlink -f "$LIB")")" || fail "nm -D $LIB failed"
if grep -q 'cv::ximgproc::linesToKeyLines' <<<"$lib_symbols"; then lib_keylines=yes; else lib_keylines=no; fi
# shellcheck disable=SC2046
pc_macros="$(echo '#include <opencv2/lsd_advance.hpp>' \
  | g++ -x c++ -E -dM - $(pkg-config --cflags opencv_lsd_advance))" || fail "preprocessing with pkg-config's flags failed"
if grep -q '^#define HAVE_OPENCV_LINE_DESCRIPTOR' <<<"$pc_macros"; then pc_keylines=yes; else pc_keylines=no; fi
if grep -q 'INTERFACE_COMPILE_DEFINITIONS.*HAVE_OPENCV_LINE_DESCRIPTOR' "$PKGDIR/opencv_lsd_advanceTargets.cmake"; then
  cmake_keylines=yes; else cmake_keylines=no; fi
echo "library: $lib_keylines, pkg-config consumer: $pc_keylines, CMake target defines it: $cmake_keylines"
[ "$lib_keylines$lib_keylines" = "$pc_keylines$cmake_keylines" ] \
  || fail "the KeyLine API of the library ($lib_keylines) and of its consumers (pkg-config $pc_keylines, CMake $cmake_keylines) differ"

if [ "$(cache_value BUILD_EXAMPLES)" = "ON" ]; then
  step "installed sample program (install RPATH)"
  SAMPLE="$PREFIX/bin/lsd_advance_demo"
  [ -x "$SAMPLE" ] || fail "$SAMPLE is not installed"
  [ ! -e "$PREFIX/bin/lsd_advance_benchmark" ] || fail "the apps were installed (they are the repository's tooling)"
  loaded="$(env -u LD_LIBRARY_PATH ldd "$SAMPLE" | sed -n 's/.*libopencv_lsd_advance[^ ]* => \([^ ]*\).*/\1/p')"
  [ "$(readlink -f "$loaded")" = "$(readlink -f "$LIB")" ] \
    || fail "$SAMPLE loads libopencv_lsd_advance from '$loaded', not from $PREFIX/$LIBDIR"
  env -u LD_LIBRARY_PATH "$SAMPLE" --help >/dev/null 2>&1 || fail "$SAMPLE --help failed"
  out="$(env -u LD_LIBRARY_PATH "$SAMPLE" "$IMAGE" --output="$WORK/demo.png")" || fail "$SAMPLE $IMAGE failed: $out"
  echo "$out"
  # the demo detects with createLSDAdvance() and default parameters, as main.cpp does
  sample_count="$(count_in "$out" "LSDAdvance:")"
  [ "$sample_count" = "$cmake_count" ] || fail "$SAMPLE reports $sample_count segments, the consumer $cmake_count"
else
  echo "BUILD_EXAMPLES is OFF in $BUILD: no sample program to check"
fi

if [ "$(cache_value LSD_ADVANCE_PYTHON)" = "ON" ]; then
  step "installed Python module (import lsd_advance)"
  PYTHON="$(cache_value Python3_EXECUTABLE)"
  PYDIR="$PREFIX/$(cache_value LSD_ADVANCE_PYTHON_INSTALL_DIR)"
  [ -f "$PYDIR/lsd_advance/__init__.py" ] || fail "the Python package is not installed in $PYDIR/lsd_advance"
  # Its KeyLines are cv2's own: they go into cv2's LBD as they come.
  out="$(cd "$WORK" && env -u LD_LIBRARY_PATH PYTHONPATH="$PYDIR" "$PYTHON" -c '
import sys, cv2, lsd_advance
gray = cv2.imread(sys.argv[1], cv2.IMREAD_GRAYSCALE)
lines = lsd_advance.createLSDAdvance().detect(gray)
keylines = lsd_advance.createLSDAdvance().detectKeyLines(gray)
described = cv2.line_descriptor.BinaryDescriptor_createBinaryDescriptor().compute(gray, keylines)[1]
print(0 if lines is None else len(lines), "line segments, from", lsd_advance.__file__)
print("KeyLines described by LBD:", len(keylines), described.shape[0])' "$IMAGE")" \
    || fail "importing the installed lsd_advance with $PYTHON (PYTHONPATH=$PYDIR) failed: $out"
  echo "$out"
  [[ "$out" == *"from $PYDIR/lsd_advance/"* ]] || fail "Python imported lsd_advance from elsewhere than $PYDIR: $out"
  [ "$(count_in "$out" "")" = "$cmake_count" ] || fail "the Python module reports '$out', the C++ consumer $cmake_count segments"
  [ "$(sed -n 's/^KeyLines described by LBD: //p' <<<"$out")" = "$cmake_count $cmake_count" ] \
    || fail "the Python module's KeyLines are not all described by cv2's LBD: $out"
else
  echo "LSD_ADVANCE_PYTHON is not ON in $BUILD: no Python module to check"
fi

step "doc/building.md \"Another prefix\": a clean shell with only $PREFIX/bin/setup_vars_lsd_advance.sh sourced"
BINDIR="$(cache_value CMAKE_INSTALL_BINDIR)"
WITH_SAMPLES="$(cache_value BUILD_EXAMPLES)"
WITH_PYTHON="$(cache_value LSD_ADVANCE_PYTHON)"
SETUP="$PREFIX/$BINDIR/setup_vars_lsd_advance.sh"
[ -f "$SETUP" ] || fail "$SETUP is not installed"
mkdir -p "$WORK/home"
cp -r "$CONSUMER_SRC" "$WORK/home/consumer"
# The expected values go in as arguments; the shell sees nothing else of this script's environment.
out="$(cd "$WORK/home" && env -i HOME="$WORK/home" PATH=/usr/local/bin:/usr/bin:/bin \
  OPENCV_SAMPLES_DATA_PATH="$DATA" bash -euo pipefail -c '
. "$1"
prefix=$2; with_samples=$3; with_python=$4
echo "pkg-config: $(pkg-config --modversion opencv_lsd_advance) from $(pkg-config --variable=prefix opencv_lsd_advance)"
g++ consumer/main.cpp $(pkg-config --cflags --libs opencv_lsd_advance) -o lsd_count
image=$OPENCV_SAMPLES_DATA_PATH/building.jpg
echo "pkg-config program: $(./lsd_count "$image" 2>&1 || true)"
echo "pkg-config program loads: $(readlink -f "$(ldd ./lsd_count | sed -n "s/.*libopencv_lsd_advance[^ ]* => \([^ ]*\).*/\1/p")")"
cmake -S consumer -B consumer/build >consumer.log 2>&1 && cmake --build consumer/build >>consumer.log 2>&1 \
  || { cat consumer.log; exit 1; }
echo "cmake package: $(sed -n "s/^opencv_lsd_advance_DIR:[A-Z]*=//p" consumer/build/CMakeCache.txt)"
echo "cmake program: $(consumer/build/lsd_advance_consumer "$image")"
if [ "$with_samples" = ON ]; then
  echo "sample program: $(command -v lsd_advance_demo)"
  lsd_advance_demo building.jpg --output=demo.png | sed -n "s/^LSDAdvance: *\([0-9]*\) segments.*/sample segments: \1/p"
fi
if [ "$with_python" = ON ]; then
  python3 -c "import sys, cv2, lsd_advance; print(\"python module:\", len(lsd_advance.createLSDAdvance().detect(cv2.imread(sys.argv[1], cv2.IMREAD_GRAYSCALE))), lsd_advance.__file__)" "$image"
  python3 "$prefix/share/opencv4/samples/lsd_advance/python/lsd_advance_detect.py" building.jpg --output=lines.png \
    | sed -n "s/^\([0-9]*\) line segments in building.jpg.*/python sample segments: \1/p"
fi
' check_env "$SETUP" "$PREFIX" "$WITH_SAMPLES" "$WITH_PYTHON" 2>&1)" \
  || fail "the commands of doc/building.md \"Another prefix\" failed in a clean shell:"$'\n'"$out"
echo "$out"
expect_line() { grep -qxF -- "$1" <<<"$out" || fail "expected the line '$1' in a clean shell with $SETUP sourced; got:"$'\n'"$out"; }
expect_line "pkg-config: $pc_version from $PREFIX"
expect_line "pkg-config program: $cmake_count line segments in $IMAGE"
expect_line "pkg-config program loads: $(readlink -f "$LIB")"
expect_line "cmake package: $PKGDIR"
expect_line "cmake program: $cmake_count line segments in $IMAGE"
if [ "$WITH_SAMPLES" = "ON" ]; then
  expect_line "sample program: $PREFIX/$BINDIR/lsd_advance_demo"
  expect_line "sample segments: $cmake_count"
fi
if [ "$WITH_PYTHON" = "ON" ]; then
  expect_line "python module: $cmake_count $PYDIR/lsd_advance/__init__.py"
  expect_line "python sample segments: $cmake_count"
fi

step "passed: install of $BUILD works for CMake, pkg-config and Python consumers, and with its environment script"
