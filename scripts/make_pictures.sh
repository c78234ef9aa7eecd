#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/make_pictures.sh [DATA_DIR]
#
# Regenerates the pictures of the documentation in doc/pics/ that are not measurements (the
# tutorial's commands write to out/; the charts of measurements, doc/pics/results_*.svg, come
# with doc/results.md from scripts/benchmark.sh): the demo picture of README, the drawings of the
# three stages on building.jpg and on YorkUrban's P1020831.jpg, and the LBD matches of
# graf1/graf3. Each command is the one doc/pictures.md prints next to its picture. DATA_DIR
# (YorkUrban) defaults to $LSD_ADVANCE_DATA_DIR, else ../shared/data beside the repository.
# Builds the programs first when the build directory has none. Takes a few seconds. Afterwards
# `git status doc/pics` shows what changed.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_BUILD_DIR:-$REPO/build}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
DATA="$(cd "${1:-${LSD_ADVANCE_DATA_DIR:-$REPO/../shared/data}}" && pwd)"
[ -d "$DATA/yorkurban" ] || { echo "ERROR: no yorkurban/ in $DATA" >&2; exit 1; }

SAMPLES=(lsd_advance_demo lsd_advance_detect lsd_advance_lbd_matching)
for s in "${SAMPLES[@]}"; do
  if [ ! -x "$BUILD/$s" ]; then
    bash "$REPO/scripts/install_deps.sh"
    [ -f "$BUILD/CMakeCache.txt" ] || cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF
    cmake --build "$BUILD" -j"$JOBS" --target "${SAMPLES[@]}"
    break
  fi
done
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"

# The commands run from the repository root, with the paths doc/pictures.md prints.
cd "$REPO"
mkdir -p doc/pics
run() { echo "+ $*" >&2; "$@"; }
YORKURBAN="$DATA/yorkurban"

run "$BUILD/lsd_advance_demo" building.jpg --output=doc/pics/building_lsd_vs_lsd_advance.jpg >/dev/null
run "$BUILD/lsd_advance_detect" --input=building.jpg --output=doc/pics --draw=filter,groups --ext=jpg --no-segments >/dev/null
run "$BUILD/lsd_advance_detect" --input=building.jpg --output=doc/pics --draw=merge --zoom=150,60,300,200 --ext=jpg \
  --no-segments >/dev/null
run "$BUILD/lsd_advance_detect" --input="$YORKURBAN/images/P1020831.jpg" --output=doc/pics --draw=stages --ext=jpg \
  --no-segments >/dev/null
run "$BUILD/lsd_advance_lbd_matching" graf1.png graf3.png -H=H1to3p.xml -d=doc/pics/lbd_matches_graf.jpg >/dev/null

echo "[make_pictures] wrote the pictures of doc/pics (git status doc/pics shows what changed)" >&2
