#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/benchmark.sh [DATA_DIR]
#
# Produces the tables of README "Results": every method in one run per data set, one thread,
# on YorkUrban (all images, then the odd images the defaults were not tuned on), KITTI and
# EuRoC, then LBD line matching on the HPatches graffiti pairs, OpenCV's graf1/graf3 and KITTI
# (doc/matching.md), with all lines and at line budgets of 100, 200 and 400 per image, and the
# tracks the matches chain into on KITTI and EuRoC. DATA_DIR defaults to $LSD_ADVANCE_DATA_DIR, else ../shared/data beside the repository.
# Builds (or brings up to date) the benchmark program first. With ELSED's sources beside the
# repository (../shared/peers/elsed) or in LSD_ADVANCE_ELSED_DIR, ELSED is built as an optional
# peer and measured in every table. Takes about 20 minutes.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
#   LSD_ADVANCE_ELSED_DIR  ELSED's sources (see scripts/elsed_peer.sh; set it empty to leave ELSED out)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_BUILD_DIR:-$REPO/build}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
DATA="${1:-${LSD_ADVANCE_DATA_DIR:-$REPO/../shared/data}}"
[ -d "$DATA/yorkurban" ] || { echo "ERROR: no yorkurban/ in $DATA" >&2; exit 1; }

[ -x "$BUILD/lsd_advance_benchmark" ] || bash "$REPO/scripts/install_deps.sh"
PEER_ARG="$(bash "$REPO/scripts/elsed_peer.sh")"
if [ -f "$BUILD/CMakeCache.txt" ]; then
  cmake "$BUILD" "$PEER_ARG" >/dev/null   # keeps the build's other options
else
  cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF "$PEER_ARG"
fi
cmake --build "$BUILD" -j"$JOBS" --target lsd_advance_benchmark
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"

B="$BUILD/lsd_advance_benchmark"
PEER=""
[ "$PEER_ARG" = "-DLSD_ADVANCE_ELSED_DIR=" ] || PEER=",elsed"
STILL="lsd,fld,fld_merge,edlines$PEER,plvins,lsdadvance_paper,lsdadvance_base,lsdadvance_fastest,lsdadvance_opencv_full,lsdadvance"
MATCHING="lsd,fld,edlines$PEER,lsdadvance_paper,lsdadvance_merge,lsdadvance"
SEQUENCE="lsd,fld,edlines$PEER,lsdadvance_paper,lsdadvance_filter,lsdadvance_fastest,lsdadvance,lsdadvance_interframe,lsdadvance_continuous,lsdadvance_tracking,lsdadvance_sequence"
BUDGET="lsd,fld,edlines$PEER,lsdadvance_paper,lsdadvance,lsdadvance_sequence"

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
"$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$SEQUENCE" --no-match
echo
echo "### EuRoC V1_01 before take-off, 95 frames of a still camera"
echo
"$B" --dataset=sequence --data="$DATA/euroc_v101_static" --methods="$SEQUENCE" --no-match
echo
echo "### LBD matching, HPatches v_graffiti (pairs 1-2 ... 1-6, exact homographies)"
echo
"$B" --dataset=homography --data="$DATA/hpatches_v_graffiti" --methods="$MATCHING"
echo
echo "### LBD matching, OpenCV's graf1.png / graf3.png with H1to3p.xml"
echo
"$B" --dataset=homography --image1=graf1.png --image2=graf3.png --homography=H1to3p.xml --methods="$MATCHING"
echo
echo "### LBD matching, KITTI consecutive frames (epipolar check, 50 pairs)"
echo
"$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$MATCHING"
echo
echo "### LBD matching at equal line budgets (each method's N lines of highest KeyLine response): HPatches v_graffiti"
echo
"$B" --dataset=homography --data="$DATA/hpatches_v_graffiti" --methods="$BUDGET" --top=100,200,400
echo
echo "### LBD matching at equal line budgets: OpenCV's graf1.png / graf3.png"
echo
"$B" --dataset=homography --image1=graf1.png --image2=graf3.png --homography=H1to3p.xml --methods="$BUDGET" --top=100,200,400
echo
echo "### LBD matching and tracks at equal line budgets: KITTI"
echo
"$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$BUDGET" --top=100,200,400
echo
echo "### Tracks at equal line budgets: EuRoC V1_01, still camera"
echo
"$B" --dataset=sequence --data="$DATA/euroc_v101_static" --methods="$BUDGET" --top=100,200,400
