#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Matches line segments between two images with OpenCV's LBD descriptor (cv2.line_descriptor),
the Python counterpart of samples/lsd_advance_lbd_matching.cpp (two images; its --sequence mode
is C++ only): detects, converts to KeyLines, describes, matches (mutual nearest neighbours under
a Hamming bound), prints the number of matches and, given the homography from image 1 to
image 2, how many are correct (mapped within 3 px and overlapping, doc/matching.md).

    python3 lsd_advance_lbd_matching.py graf1.png graf3.png -H H1to3p.xml --draw matches.jpg

Needs the standalone module `lsd_advance` (its linesToKeyLines makes the KeyLines).
"""

import argparse

import cv2
import numpy as np

import lsd_advance as lsda
from lsd_advance_detect import METHODS, make_method, run_reporting_errors

# line_descriptor::DrawLinesMatchesFlags::NOT_DRAW_SINGLE_LINES, which OpenCV 4.6's cv2 does not export.
NOT_DRAW_SINGLE_LINES = 2


def describe_lines(gray, lines):
    """(KeyLines, LBD descriptors: one row of 32 bytes per KeyLine) of segments."""
    if lines is None or len(lines) == 0:
        return [], None
    keylines = lsda.linesToKeyLines(lines, (gray.shape[1], gray.shape[0]))
    return cv2.line_descriptor.BinaryDescriptor_createBinaryDescriptor().compute(gray, keylines)


def match_lines(descriptors1, descriptors2, max_hamming=30, cross_check=True):
    """Matches of lines 1 (query) to lines 2 (train): nearest neighbours within max_hamming bits,
    mutual ones only with cross_check (the usual set-up of line-based SLAM front ends)."""
    if descriptors1 is None or descriptors2 is None:
        return []
    matcher = cv2.line_descriptor.BinaryDescriptorMatcher()
    forward = matcher.match(descriptors1, descriptors2)
    nearest_of_2 = [-1] * len(descriptors2)
    if cross_check:
        for m in matcher.match(descriptors2, descriptors1):
            nearest_of_2[m.queryIdx] = m.trainIdx
    return [m for m in forward
            if m.distance <= max_hamming and (not cross_check or nearest_of_2[m.trainIdx] == m.queryIdx)]


def draw_matches(gray1, keylines1, gray2, keylines2, matches, path):
    # Matched lines only, each match in its own colour; with NOT_DRAW_SINGLE_LINES,
    # drawLineMatches draws into a canvas of the right size that the caller allocates.
    canvas = np.zeros((max(gray1.shape[0], gray2.shape[0]), gray1.shape[1] + gray2.shape[1], 3), np.uint8)
    canvas = cv2.line_descriptor.drawLineMatches(
        cv2.cvtColor(gray1, cv2.COLOR_GRAY2BGR), keylines1, cv2.cvtColor(gray2, cv2.COLOR_GRAY2BGR), keylines2,
        matches, canvas, (-1, -1, -1, -1), (-1, -1, -1, -1), np.ones(len(matches), np.int8),
        NOT_DRAW_SINGLE_LINES)
    if not cv2.imwrite(path, canvas, [cv2.IMWRITE_JPEG_QUALITY, 85]):
        raise RuntimeError("cannot write " + path)
    print("wrote " + path)


def find(path):
    return cv2.samples.findFile(path, False, True) or path


def main():
    parser = argparse.ArgumentParser(description="Matches line segments with LBD, e.g. lsd_advance_lbd_matching.py "
                                                 "graf1.png graf3.png -H H1to3p.xml --draw matches.jpg")
    parser.add_argument("image1", nargs="?", default="graf1.png",
                        help="first image (OpenCV sample names are found in OPENCV_SAMPLES_DATA_PATH)")
    parser.add_argument("image2", nargs="?", default="graf3.png", help="second image")
    parser.add_argument("-m", "--method", default="lsdadvance", choices=METHODS)
    parser.add_argument("-p", "--params", default="",
                        help="YAML/XML of LSDAdvance parameters saved with save() or write(), for the lsdadvance method")
    parser.add_argument("-H", "--homography", default="",
                        help="3x3 homography from image 1 to image 2 (text, or OpenCV XML such as H1to3p.xml)")
    parser.add_argument("--max-hamming", type=int, default=30,
                        help="largest Hamming distance of a kept match (LBD: 256 bits)")
    parser.add_argument("--no-cross-check", action="store_true", help="keep every nearest neighbour, not only mutual ones")
    parser.add_argument("-d", "--draw", default="", help="write the matches drawn side by side to this image")
    args = parser.parse_args()

    gray1 = cv2.imread(find(args.image1), cv2.IMREAD_GRAYSCALE)
    gray2 = cv2.imread(find(args.image2), cv2.IMREAD_GRAYSCALE)
    if gray1 is None or gray2 is None:
        raise RuntimeError("cannot read " + (args.image2 if gray1 is not None else args.image1))
    name, detect, reset = make_method(args.method, args.params)
    # Two unrelated detections: neither may steer the other's inter-frame factor.
    reset()
    lines1 = detect(gray1)
    reset()
    lines2 = detect(gray2)
    keylines1, descriptors1 = describe_lines(gray1, lines1)
    keylines2, descriptors2 = describe_lines(gray2, lines2)
    matches = match_lines(descriptors1, descriptors2, args.max_hamming, not args.no_cross_check)

    print("method:          %s" % name)
    print("segments:        %d / %d" % (0 if lines1 is None else len(lines1), 0 if lines2 is None else len(lines2)))
    print("matches:         %d" % len(matches))
    if args.homography:
        H = lsda.line_evaluation.readHomography(find(args.homography))
        s = lsda.line_evaluation.evaluateHomographyMatches(lines1, lines2, matches, H, (gray1.shape[1], gray1.shape[0]),
                                           (gray2.shape[1], gray2.shape[0]))
        print("correct:         %d (precision %.3f; mapped within 3 px, overlapping)" % (s.correct, s.precision))
        print("repeatability:   %.3f (%d of %d visible segments)" % (s.repeatability, s.repeated, s.visible))
        print("localisation:    %.2f px (mean, repeated segments)" % s.localisationError)
    if args.draw:
        draw_matches(gray1, keylines1, gray2, keylines2, matches, args.draw)
    return 0


if __name__ == "__main__":
    run_reporting_errors(main)
