#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Matches line segments between two images with OpenCV's LBD descriptor (cv2.line_descriptor),
the Python counterpart of samples/lsd_advance_lbd_matching.cpp (two images; its --sequence mode
is C++ only): detects, converts to KeyLines, describes, matches (mutual nearest neighbours under
a Hamming bound), prints the number of matches and, given the homography from image 1 to
image 2, how many are correct (mapped within 3 px and overlapping, doc/matching.md).

    python3 lsd_advance_lbd_matching.py graf1.png graf3.png -H=H1to3p.xml --draw=matches.jpg

With the homography, the drawing shows correct matches in green and wrong ones in red, with their
counts. Bad input ends the program with one "Error: ..." line and exit status 1. Needs the
standalone module `lsd_advance` (its linesToKeyLines makes the KeyLines).
"""

import cv2
import numpy as np

import lsd_advance as lsda
from lsd_advance_detect import (METHODS, SampleArgumentParser, check_output_folder, integer, make_method,
                                read_gray_image, run_reporting_errors)

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


RIGHT, WRONG = (60, 200, 60), (60, 60, 255)


def classes_under_homography(lines1, lines2, matches, H):
    """[(name, colour, mask)] of the correct (green) and wrong (red) matches under the homography
    H, as evaluateHomographyMatches counts them."""
    correct = np.array([lsda.line_evaluation.correspondUnderHomography(lines1[m.queryIdx].reshape(4), lines2[m.trainIdx].reshape(4), H)
                        for m in matches], bool)
    return [("correct", RIGHT, correct.astype(np.int8)), ("wrong", WRONG, (~correct).astype(np.int8))]


def draw_matches(gray1, keylines1, gray2, keylines2, matches, classes, path):
    """The matches drawn side by side, each class of [(name, colour, mask)] in its colour with its
    count in the top-left corner; without classes, each match in its own random colour."""
    # Matched lines only; with NOT_DRAW_SINGLE_LINES, drawLineMatches draws into a canvas of the
    # right size that the caller allocates, after copying the two images into it: each class
    # is drawn on the halves of the previous drawing.
    height1, width1 = gray1.shape
    canvas = np.zeros((max(height1, gray2.shape[0]), width1 + gray2.shape[1], 3), np.uint8)
    colour1, colour2 = cv2.cvtColor(gray1, cv2.COLOR_GRAY2BGR), cv2.cvtColor(gray2, cv2.COLOR_GRAY2BGR)
    passes = classes or [("", (-1, -1, -1, -1), np.ones(len(matches), np.int8))]
    for i, (_, colour, mask) in enumerate(passes):
        if i > 0:
            colour1 = canvas[:height1, :width1].copy()
            colour2 = canvas[:gray2.shape[0], width1:].copy()
        # The matched segments in the colour of their match (-1: random, one colour per match).
        canvas = cv2.line_descriptor.drawLineMatches(colour1, keylines1, colour2, keylines2, matches, canvas,
                                                     colour, colour, mask, NOT_DRAW_SINGLE_LINES)
    # The counts, one line per class, on a dark box in the top-left corner.
    scale = max(0.5, canvas.shape[1] / 1600.0)
    weight, margin = 2 if scale > 0.8 else 1, 8
    (_, text_height), baseline = cv2.getTextSize("Ag", cv2.FONT_HERSHEY_SIMPLEX, scale, weight)
    row_height = text_height + baseline + 6
    rows = ["%s: %d" % (name, np.count_nonzero(mask)) for name, _, mask in classes]
    if rows:
        width = max(cv2.getTextSize(r, cv2.FONT_HERSHEY_SIMPLEX, scale, weight)[0][0] for r in rows)
        cv2.rectangle(canvas, (0, 0), (width + 2 * margin - 1, len(rows) * row_height + margin - 1), (0, 0, 0),
                      cv2.FILLED)
    for i, (row, (_, colour, _)) in enumerate(zip(rows, classes)):
        cv2.putText(canvas, row, (margin, (i + 1) * row_height), cv2.FONT_HERSHEY_SIMPLEX, scale, colour, weight,
                    cv2.LINE_AA)
    if not cv2.imwrite(path, canvas, [cv2.IMWRITE_JPEG_QUALITY, 85]):
        raise RuntimeError("cannot write " + path)
    print("wrote " + path)


def find(path):
    return cv2.samples.findFile(path, False, True) or path


def main():
    parser = SampleArgumentParser(description="Matches line segments with LBD, e.g. lsd_advance_lbd_matching.py "
                                              "graf1.png graf3.png -H=H1to3p.xml --draw=matches.jpg")
    parser.add_argument("image1", nargs="?", default="graf1.png",
                        help="first image (OpenCV sample names are found in OPENCV_SAMPLES_DATA_PATH)")
    parser.add_argument("image2", nargs="?", default="graf3.png", help="second image")
    parser.add_argument("-m", "--method", default="lsdadvance", choices=METHODS)
    parser.add_argument("-p", "--params", default="",
                        help="YAML/XML of LSDAdvance parameters saved with save() or write(), for the lsdadvance method")
    parser.add_argument("-H", "--homography", default="",
                        help="3x3 homography from image 1 to image 2 (text, or OpenCV XML such as H1to3p.xml)")
    parser.add_argument("--max-hamming", type=integer(0, 256), default=30,
                        help="largest Hamming distance of a kept match, 0 to 256 (LBD: 256 bits)")
    parser.add_argument("--no-cross-check", action="store_true", help="keep every nearest neighbour, not only mutual ones")
    parser.add_argument("-d", "--draw", default="",
                        help="write the matches drawn side by side to this image (.jpg or .png); with --homography, "
                             "correct matches in green and wrong ones in red, with their counts")
    args = parser.parse_args()
    check_output_folder("draw", args.draw)
    if args.draw and not cv2.haveImageWriter(args.draw):
        raise ValueError("--draw=%s: no image format for this file name (use .jpg or .png)" % args.draw)

    method = make_method(args.method, args.params)
    H = lsda.line_evaluation.readHomography(find(args.homography)) if args.homography else None
    gray1, gray2 = read_gray_image(find(args.image1)), read_gray_image(find(args.image2))
    if gray1 is None or gray2 is None:
        raise RuntimeError("cannot read %s as an image" % (args.image2 if gray1 is not None else args.image1))
    # Two unrelated detections: neither may steer the other's inter-frame factor.
    method.reset()
    lines1 = method.detect(gray1)
    method.reset()
    lines2 = method.detect(gray2)
    keylines1, descriptors1 = describe_lines(gray1, lines1)
    keylines2, descriptors2 = describe_lines(gray2, lines2)
    matches = match_lines(descriptors1, descriptors2, args.max_hamming, not args.no_cross_check)

    print("method:          %s" % method.name)
    print("segments:        %d / %d" % (0 if lines1 is None else len(lines1), 0 if lines2 is None else len(lines2)))
    print("matches:         %d" % len(matches))
    if H is not None:
        s = lsda.line_evaluation.evaluateHomographyMatches(lines1, lines2, matches, H, (gray1.shape[1], gray1.shape[0]),
                                           (gray2.shape[1], gray2.shape[0]))
        print("correct:         %d (precision %.3f; mapped within 3 px, overlapping)" % (s.correct, s.precision))
        print("repeatability:   %.3f (%d of %d visible segments)" % (s.repeatability, s.repeated, s.visible))
        print("localisation:    %.2f px (mean, repeated segments)" % s.localisationError)
    if args.draw:
        classes = [] if H is None else classes_under_homography(lines1, lines2, matches, H)
        draw_matches(gray1, keylines1, gray2, keylines2, matches, classes, args.draw)
    return 0


if __name__ == "__main__":
    run_reporting_errors(main)
