#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/demo.sh [lsd_advance_demo arguments, e.g. my.jpg --output=out.png]
#
# Installs the Debian dependencies, builds the library and the samples (no tests: no OpenCV
# source needed) and runs the demo, samples/lsd_advance_demo.cpp, on OpenCV's building.jpg (from
# opencv-doc): LSD and LSDAdvance side by side in build/lsd_advance_demo.png.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_BUILD_DIR:-$REPO/build}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
T0=$SECONDS
section() { echo; echo "==== [demo] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh"

section "configure ($BUILD, BUILD_TESTS=OFF)"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF -DBUILD_EXAMPLES=ON

section "build"
cmake --build "$BUILD" -j"$JOBS" --target lsd_advance_demo

section "run lsd_advance_demo"
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"
OUTPUT="$BUILD/lsd_advance_demo.png"
ARGS=("$@")
# default output next to the binary unless the caller chose one
if ! printf '%s\n' "${ARGS[@]+"${ARGS[@]}"}" | grep -q -- '^--output'; then
  ARGS+=("--output=$OUTPUT")
else
  OUTPUT="$(printf '%s\n' "${ARGS[@]}" | sed -nE 's/^--output=?//p' | tail -n1)"
fi
"$BUILD/lsd_advance_demo" "${ARGS[@]+"${ARGS[@]}"}"

section "done"
if [ -f "$OUTPUT" ]; then
  echo "Result image: $(cd "$(dirname "$OUTPUT")" && pwd)/$(basename "$OUTPUT")"
else
  echo "ERROR: lsd_advance_demo did not write $OUTPUT" >&2
  exit 1
fi
