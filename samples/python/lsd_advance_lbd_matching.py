#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Matches LSDAdvance's lines between two views with LBD (computeLBD: cv2.line_descriptor's
descriptors, byte for byte, faster), as lsd_advance_lbd_matching.cpp does: mutual nearest
neighbours within a Hamming distance (cv2.line_descriptor's matcher) and, given the homography
from image 1 to image 2, the number of correct matches (doc/matching.md).

    python3 lsd_advance_lbd_matching.py graf1.png graf3.png --homography=H1to3p.xml
"""

import argparse
import sys

import cv2

try:
    import lsd_advance as lsda
except ImportError:
    lsda = cv2.ximgproc


def describe_lines(gray, lines):
    """(KeyLines, LBD descriptors: one row of 32 bytes per KeyLine) of segments."""
    if lines is None or len(lines) == 0:
        return [], None
    keylines = lsda.linesToKeyLines(lines, (gray.shape[1], gray.shape[0]))
    return keylines, lsda.computeLBD(gray, keylines)


def match_lines(descriptors1, descriptors2, max_hamming=30):
    """Matches of lines 1 (query) to lines 2 (train) that are each other's nearest neighbour
    within max_hamming bits."""
    if descriptors1 is None or descriptors2 is None:
        return []
    matcher = cv2.line_descriptor.BinaryDescriptorMatcher()
    nearest_of_2 = {m.queryIdx: m.trainIdx for m in matcher.match(descriptors2, descriptors1)}
    return [m for m in matcher.match(descriptors1, descriptors2)
            if m.distance <= max_hamming and nearest_of_2.get(m.trainIdx) == m.queryIdx]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("image1", nargs="?", default="graf1.png", help="OpenCV's sample images are found by name")
    parser.add_argument("image2", nargs="?", default="graf3.png")
    parser.add_argument("-H", "--homography", help="3x3 homography from image 1 to image 2 (text or OpenCV XML)")
    args = parser.parse_args()
    detector = lsda.createLSDAdvance()
    grays, lines = [], []
    for name in (args.image1, args.image2):
        grays.append(cv2.imread(cv2.samples.findFile(name, True, True), cv2.IMREAD_GRAYSCALE))
        detector.reset()  # two views, not consecutive frames of a sequence
        lines.append(detector.detect(grays[-1]))
    described = [describe_lines(gray, segments) for gray, segments in zip(grays, lines)]
    matches = match_lines(described[0][1], described[1][1])
    print("segments:        %d / %d" % tuple(0 if s is None else len(s) for s in lines))
    print("matches:         %d" % len(matches))
    if args.homography:
        H = lsda.line_evaluation.readHomography(cv2.samples.findFile(args.homography, True, True))
        score = lsda.line_evaluation.evaluateHomographyMatches(lines[0], lines[1], matches, H, grays[0].shape[::-1],
                                                               grays[1].shape[::-1])
        print("correct:         %d (precision %.3f; mapped within 3 px, overlapping)" % (score.correct, score.precision))


if __name__ == "__main__":
    try:
        main()
    except cv2.error as e:
        sys.exit("Error: " + e.err)
