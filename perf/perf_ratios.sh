#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash perf/perf_ratios.sh [build dir] [extra opencv_perf_lsd_advance options]
#
# Runs the image cases of opencv_perf_lsd_advance (every method on the same images, in one run)
# and prints a Markdown table: per image set, the median time of each method (by its name in
# apps/lsd_advance_bench/line_methods.hpp) divided by the
# median time of OpenCV's LSD on the same image (the mean of these ratios over the set's images),
# and the median milliseconds. Needs LSD_ADVANCE_DATA_DIR for the YorkUrban and KITTI frames and
# OPENCV_SAMPLES_DATA_PATH for building.jpg (both default to this machine's locations).
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${1:-$REPO/build}"
shift || true
export LSD_ADVANCE_DATA_DIR="${LSD_ADVANCE_DATA_DIR:-$REPO/../shared/data}"
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"

LOG="$(mktemp)"
trap 'rm -f "$LOG"' EXIT
( cd "$BUILD" && ./opencv_perf_lsd_advance \
    --gtest_filter='LineDetection_Data_detect.*:LineDetection_Image_detect.*' \
    --perf_min_samples=15 --perf_force_samples=15 "$@" ) >"$LOG" 2>&1

# "[ RUN ] ...detect/N, where GetParam() = ("image", METHOD)" then "[ PERFSTAT ] (... median=X ...)".
awk '
  /^\[ RUN/ {
    line = $0
    sub(/.*GetParam\(\) = \(/, "", line); sub(/\)$/, "", line)
    n = split(line, part, ", ")
    image = part[1]; gsub(/"/, "", image); method = part[n]; gsub(/"/, "", method)
    set = image ~ /yorkurban/ ? "YorkUrban" : (image ~ /kitti/ ? "KITTI" : image)
    next
  }
  /PERFSTAT/ && /median=/ {
    m = $0; sub(/.*median=/, "", m); sub(/ .*/, "", m)
    ms[image, method] = m + 0; setOf[image] = set
    if (!(method in seenMethod)) { seenMethod[method] = 1; methods[++nm] = method }
    if (!(set in seenSet)) { seenSet[set] = 1; sets[++ns] = set }
  }
  END {
    header = "| method |"; rule = "|---|"
    for (s = 1; s <= ns; s++) { header = header " " sets[s] ": x LSD | ms |"; rule = rule "---:|---:|" }
    print header; print rule
    for (k = 1; k <= nm; k++) {
      row = "| " methods[k] " |"
      for (s = 1; s <= ns; s++) {
        sum = 0; cnt = 0; msSum = 0
        for (key in setOf) if (setOf[key] == sets[s] && ((key, "lsd") in ms) && ((key, methods[k]) in ms)) {
          sum += ms[key, methods[k]] / ms[key, "lsd"]; msSum += ms[key, methods[k]]; cnt++
        }
        row = row (cnt ? sprintf(" %.2f | %.1f |", sum / cnt, msSum / cnt) : " - | - |")
      }
      print row
    }
  }' "$LOG"
