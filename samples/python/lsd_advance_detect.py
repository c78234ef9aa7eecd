#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Detects line segments with LSDAdvance, prints how many and writes them drawn on the image.

    python3 lsd_advance_detect.py building.jpg --preset=sequence --output=lines.png

Uses the standalone module lsd_advance when it is importable, else cv2.ximgproc (OpenCV built
with the module in-tree): both have the same names.
"""

import argparse
import sys

import cv2

try:
    import lsd_advance as lsda
except ImportError:
    lsda = cv2.ximgproc

PRESETS = ("most_accurate", "fastest", "paper", "sequence")

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("image", nargs="?", default="building.jpg", help="OpenCV's sample images are found by name")
parser.add_argument("--preset", choices=PRESETS, default="most_accurate", help="LSDAdvance::Preset")
parser.add_argument("--output", default="lsd_advance_detect.png", help="the segments drawn on the image")
args = parser.parse_args()

try:
    gray = cv2.imread(cv2.samples.findFile(args.image, True, True), cv2.IMREAD_GRAYSCALE)
    detector = lsda.createLSDAdvance(getattr(lsda, "LSDAdvance_PRESET_" + args.preset.upper()))
    ticks = cv2.TickMeter()
    ticks.start()
    lines = detector.detect(gray)  # (N, 1, 4) float32: x1 y1 x2 y2, like LSD; None for no segment
    ticks.stop()
    print("%d line segments in %s, %.1f ms (length threshold %.1f px)" % (
        0 if lines is None else len(lines), args.image, ticks.getTimeMilli(), detector.getLastStats().minLength))
    drawing = cv2.cvtColor(gray, cv2.COLOR_GRAY2BGR)
    if lines is not None:
        drawing = detector.drawSegments(drawing, lines)
    if not cv2.imwrite(args.output, drawing):
        raise RuntimeError("cannot write " + args.output)
    print("wrote " + args.output)
except (cv2.error, RuntimeError) as e:
    sys.exit("Error: %s" % (e.err if hasattr(e, "err") else e))
