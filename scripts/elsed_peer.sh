#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/elsed_peer.sh
#
# Prints the CMake argument that builds ELSED, the optional peer detector of the samples and the
# perf suite (cmake/standalone.cmake, LSD_ADVANCE_ELSED_DIR): its folder when LSD_ADVANCE_ELSED_DIR
# names one, else ../shared/peers/elsed beside the repository when it holds ELSED's sources
# (as on CI), else an empty value (no peer). LSD_ADVANCE_ELSED_DIR= (set, empty) turns it off.
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ -n "${LSD_ADVANCE_ELSED_DIR+set}" ]; then
  dir="$LSD_ADVANCE_ELSED_DIR"    # as given: CMake reports a folder without ELSED's sources
elif [ -f "$REPO/../shared/peers/elsed/src/ELSED.cpp" ]; then
  dir="$(cd "$REPO/../shared/peers/elsed" && pwd)"
else
  dir=""
fi
echo "-DLSD_ADVANCE_ELSED_DIR=$dir"
