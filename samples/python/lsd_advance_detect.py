#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Detects line segments in an image, each image of a folder or each frame of a video, the
Python counterpart of samples/lsd_advance_detect.cpp: optionally writes them (<stem>.txt,
x1 y1 x2 y2 per row) and drawn on the image (<stem>.png), and prints segments per image, the
share of long segments and the time of the detection.

    python3 lsd_advance_detect.py --input=building.jpg --output=out --draw

Uses the standalone module `lsd_advance` when importable, else cv2.ximgproc (in-tree build).
"""

import argparse
import os
import sys

import cv2
import numpy as np

try:
    import lsd_advance as lsda
except ImportError:  # an OpenCV built with the module in-tree
    lsda = cv2.ximgproc

METHODS = ("lsdadvance", "lsd", "fld", "edlines")


def make_method(name, params_path):
    """(display name, detect(gray) -> lines or None, reset()) of one of METHODS."""
    if params_path and name != "lsdadvance":
        raise ValueError("parameters apply to the lsdadvance method only, not to '%s'" % name)
    if name == "lsdadvance":
        detector = lsda.createLSDAdvance()
        if params_path:
            fs = cv2.FileStorage(params_path, cv2.FILE_STORAGE_READ)
            if not fs.isOpened():
                raise RuntimeError("cannot open " + params_path)
            # save() nests the parameters under the algorithm's name; write() does not.
            named = fs.getNode(detector.getDefaultName())
            detector.read(fs.root() if named.empty() else named)
        return "LSDAdvance", detector.detect, detector.reset
    if name == "lsd":
        lsd = cv2.createLineSegmentDetector()
        return "LSD", lambda gray: lsd.detect(gray)[0], lambda: None
    if name == "fld":
        fld = cv2.ximgproc.createFastLineDetector()
        return "FLD", fld.detect, lambda: None
    ed = cv2.ximgproc.createEdgeDrawing()

    def detect_edlines(gray):
        ed.detectEdges(gray)
        return ed.detectLines()
    return "EDLines", detect_edlines, lambda: None


def frames(source):
    """(gray image, stem) of an image, of the images of a folder in name order, or of a video."""
    path = cv2.samples.findFile(source, False, True) or source
    if os.path.isdir(path):
        paths = lsda.line_evaluation.loadSequence(path).imagePaths
    elif os.path.isfile(path) and cv2.haveImageReader(path):
        paths = [path]
    else:
        if not os.path.exists(path) and "://" not in path and "%" not in path:
            raise RuntimeError("no such image, folder or video: " + path)
        video = cv2.VideoCapture(path)
        if not video.isOpened():
            raise RuntimeError("cannot read %s as an image or a video" % path)
        index = 0
        while True:
            ok, frame = video.read()
            if not ok or frame is None:
                return
            if frame.ndim == 3:
                frame = cv2.cvtColor(frame, cv2.COLOR_BGRA2GRAY if frame.shape[2] == 4 else cv2.COLOR_BGR2GRAY)
            yield frame, "frame_%06d" % index
            index += 1
    for p in paths:
        gray = cv2.imread(p, cv2.IMREAD_GRAYSCALE)
        if gray is None:
            raise RuntimeError("cannot read " + p)
        yield gray, os.path.splitext(os.path.basename(p))[0]


def main():
    parser = argparse.ArgumentParser(description="Detects line segments with LSDAdvance (or another method) "
                                                 "and writes them to text files.")
    parser.add_argument("-i", "--input", required=True,
                        help="an image, a folder of images (png, jpg, jpeg, ppm, pgm, bmp) or a video; "
                             "OpenCV sample names are found in OPENCV_SAMPLES_DATA_PATH")
    parser.add_argument("-o", "--output", default="",
                        help="folder for <stem>.txt (x1 y1 x2 y2 per segment, pixel centres); created if missing")
    parser.add_argument("-m", "--method", default="lsdadvance", choices=METHODS)
    parser.add_argument("--sequence", action="store_true",
                        help="the images of a folder (in name order) or a video are consecutive frames: "
                             "LSDAdvance's inter-frame factor is on; otherwise every image is independent")
    parser.add_argument("--draw", action="store_true",
                        help="also write <stem>.png, the segments drawn on the image (needs --output)")
    parser.add_argument("-p", "--params", default="",
                        help="YAML/XML of LSDAdvance parameters saved with save() or write(), for the lsdadvance method")
    parser.add_argument("--long", type=float, default=60.0, help="length in pixels from which a segment counts as long")
    args = parser.parse_args()
    if args.draw and not args.output:
        parser.error("--draw needs --output")

    name, detect, reset = make_method(args.method, args.params)
    if args.output:
        os.makedirs(args.output, exist_ok=True)
    drawer = cv2.createLineSegmentDetector()
    segments, long_segments, ms = 0, 0.0, []
    reset()
    for gray, stem in frames(args.input):
        # Unrelated images must not steer the inter-frame factor of the next one.
        if not args.sequence:
            reset()
        tm = cv2.TickMeter()
        tm.start()
        lines = detect(gray)
        tm.stop()
        if lines is None:  # what cv2's detectors return for no segment
            lines = np.zeros((0, 1, 4), np.float32)
        ms.append(tm.getTimeMilli())
        segments += len(lines)
        long_segments += lsda.line_evaluation.longSegmentShare(lines, args.long) * len(lines)
        if args.output:
            lsda.line_evaluation.writeSegments(os.path.join(args.output, stem + ".txt"), lines)
        if args.draw:
            canvas = cv2.cvtColor(gray, cv2.COLOR_GRAY2BGR)
            if len(lines):
                canvas = drawer.drawSegments(canvas, lines)
            png = os.path.join(args.output, stem + ".png")
            if not cv2.imwrite(png, canvas):
                raise RuntimeError("cannot write " + png)
    if not ms:
        raise RuntimeError("no frame in " + args.input)

    print("method:            %s" % name)
    print("images:            %d" % len(ms))
    print("segments / image:  %.1f" % (segments / len(ms)))
    print("long share:        %.3f (>= %g px, over all segments)" % (long_segments / segments if segments else 0.0,
                                                                       args.long))
    # The C++ sample's median: the upper of the two middle values for an even count.
    print("ms / image:        %.2f mean, %.2f median (detection only)" % (np.mean(ms), sorted(ms)[len(ms) // 2]))
    if args.output:
        print("wrote %d segment file(s)%s to %s" % (len(ms), " and drawings" if args.draw else "", args.output))
    return 0


def run_reporting_errors(run):
    """Exits with run()'s status, or with 1 and the error's message (the samples' error report)."""
    try:
        sys.exit(run())
    except cv2.error as e:
        sys.exit("Error: " + e.err)
    except (RuntimeError, ValueError, OSError) as e:
        sys.exit("Error: %s" % e)


if __name__ == "__main__":
    run_reporting_errors(main)
