#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/benchmark.sh [DATA_DIR]
#
# Produces the tables of README "Results": every method in one run per data set, one thread,
# on YorkUrban (all images, then the odd images the defaults were not tuned on), KITTI and
# EuRoC. DATA_DIR defaults to $LSD_ADVANCE_DATA_DIR, else ../shared/data beside the repository.
# Builds the samples first when the build directory has none. Takes about 10 minutes.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_BUILD_DIR:-$REPO/build}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
DATA="${1:-${LSD_ADVANCE_DATA_DIR:-$REPO/../shared/data}}"
[ -d "$DATA/yorkurban" ] || { echo "ERROR: no yorkurban/ in $DATA" >&2; exit 1; }

if [ ! -x "$BUILD/lsd_advance_benchmark" ]; then
  bash "$REPO/scripts/install_deps.sh"
  [ -f "$BUILD/CMakeCache.txt" ] || cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF
  cmake --build "$BUILD" -j"$JOBS" --target lsd_advance_benchmark
fi

B="$BUILD/lsd_advance_benchmark"
STILL="lsd,fld,fld_merge,edlines,plvins,lsdadvance_paper,lsdadvance_base,lsdadvance"
SEQUENCE="lsd,fld,edlines,lsdadvance_paper,lsdadvance_filter,lsdadvance_alpha1,lsdadvance,lsdadvance_continuous,lsdadvance_tracking"

echo "### YorkUrban-LineSegment, all 51 images"
echo
"$B" --dataset=yorkurban --data="$DATA/yorkurban" --methods="$STILL" --repeats=3
echo
echo "### YorkUrban-LineSegment, the 25 odd images (not used to choose the defaults)"
echo
"$B" --dataset=yorkurban --data="$DATA/yorkurban" --subset=odd --methods="$STILL" --repeats=3
echo
echo "### KITTI, 51 consecutive frames (a sequence: inter-frame factors active)"
echo
"$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$SEQUENCE"
echo
echo "### EuRoC V1_01 before take-off, 95 frames of a still camera"
echo
"$B" --dataset=sequence --data="$DATA/euroc_v101_static" --methods="$SEQUENCE"
