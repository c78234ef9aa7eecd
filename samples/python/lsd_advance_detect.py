#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Detects line segments in an image, each image of a folder or each frame of a video, the
Python counterpart of samples/lsd_advance_detect.cpp: optionally writes them (<stem>.txt,
x1 y1 x2 y2 per row) and drawn on the image (<stem>.png), draws what each stage of LSDAdvance
did (--draw=filter,groups,merge, from getLastStageOutputs() and getLastSources()), and prints
segments per image, the share of long segments and the time of the detection.

    python3 lsd_advance_detect.py --input=building.jpg --output=out --draw

Bad input ends the program with one "Error: ..." line and exit status 1; unreadable files of a
folder are reported, skipped and counted (exit status 2). Uses the standalone module
`lsd_advance` when importable, else cv2.ximgproc (in-tree build).
"""

import argparse
import collections
import math
import os
import re
import sys

import cv2
import numpy as np

try:
    import lsd_advance as lsda
except ImportError:  # an OpenCV built with the module in-tree
    lsda = cv2.ximgproc

METHODS = ("lsdadvance", "lsd", "fld", "edlines")
EXIT_SKIPPED = 2  # exit status of a run that skipped unreadable files of a folder and did the others
LOG_LEVEL_FATAL = 1  # cv::utils::logging::LOG_LEVEL_FATAL, for cv2.setLogLevel

# --------------------------------------------------------------------------------------------
# Command line and errors, shared with lsd_advance_lbd_matching.py (the C++ samples' command_line.hpp)


class SampleArgumentParser(argparse.ArgumentParser):
    """argparse with the samples' error report: one "Error: ..." line and exit status 1, and no
    abbreviated option names (the C++ samples accept none)."""

    def __init__(self, **kwargs):
        super().__init__(allow_abbrev=False, **kwargs)

    def error(self, message):
        self.exit(1, "Error: %s\n" % message)


def _range_text(low, high, low_excluded):
    if high is None:
        return ("> %g" if low_excluded else ">= %g") % low
    return ("in (%g, %g]" if low_excluded else "in [%g, %g]") % (low, high)


def number(low, high=None, low_excluded=False):
    """argparse type: a finite number in [low, high] ((low, high] with low_excluded; no upper bound for None)."""
    def parse(text):
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not math.isfinite(value) or value < low or (low_excluded and value == low) or \
                (high is not None and value > high):
            raise argparse.ArgumentTypeError("must be a number %s, got '%s'" % (_range_text(low, high, low_excluded), text))
        return value
    return parse


def integer(low, high=None):
    """argparse type: an integer in [low, high] (no upper bound for None)."""
    def parse(text):
        if not re.fullmatch(r"[+-]?[0-9]+", text.strip()) or int(text) < low or (high is not None and int(text) > high):
            raise argparse.ArgumentTypeError("must be an integer %s, got '%s'" % (_range_text(low, high, False), text))
        return int(text)
    return parse


def message_of(error):
    """A cv2.error as one line: OpenCV's file parsers (FileStorage) raise their own name as the
    message and "<file>(<line>): <reason>" as the function; that becomes
    "cannot parse <file>: line <line>: <reason>"."""
    if error.code == cv2.Error.StsParseError:
        for text in (error.func, error.err):
            found = re.fullmatch(r"(.*)\(([0-9]+)\): (.*)", text or "", re.DOTALL)
            if found:
                return "cannot parse %s: line %s: %s" % found.groups()
    return error.err


def run_reporting_errors(run):
    """Exits with run()'s status, or with 1 and the error's message (the samples' error report)."""
    try:
        sys.exit(run())
    except cv2.error as e:
        sys.exit("Error: " + message_of(e))
    except (RuntimeError, ValueError, OSError) as e:
        sys.exit("Error: %s" % e)


def check_output_folder(option, path):
    """Raises unless the folder of the output file of --option=path exists (an empty path is fine)."""
    folder = os.path.dirname(path) or "."
    if path and not os.path.isdir(folder):
        raise RuntimeError("--%s=%s: the folder %s does not exist" % (option, path, folder))


def open_params_file(path):
    """The LSDAdvance parameters file, open for reading; raises RuntimeError when it is missing,
    empty or not valid YAML, XML or JSON (with file, line and reason for a syntax error)."""
    accepted = " (YAML, XML or JSON written by LSDAdvance::save() or write())"
    # Checked here: FileStorage would log an error of its own before returning False.
    if not os.path.isfile(path):
        raise RuntimeError("no such parameters file: " + path + accepted)
    if os.path.getsize(path) == 0:
        raise RuntimeError("the parameters file %s is empty%s" % (path, accepted))
    fs = cv2.FileStorage()
    try:
        opened = fs.open(path, cv2.FILE_STORAGE_READ)
    except cv2.error as e:
        message = message_of(e)
        raise RuntimeError(message if message != e.err else
                           "cannot read the parameters file %s: %s%s" % (path, e.err, accepted)) from None
    if not opened:
        raise RuntimeError("cannot read the parameters file " + path + accepted)
    return fs


# --------------------------------------------------------------------------------------------
# Methods and input

LineMethod = collections.namedtuple("LineMethod", "name detect reset lsd_advance")
LineMethod.__doc__ = """A detector: detect(gray) -> lines or None; reset() starts a new sequence;
lsd_advance: the LSDAdvance detector behind it (for its stage outputs), else None."""


def make_method(name, params_path):
    """The LineMethod of one of METHODS; params_path, when given, configures LSDAdvance."""
    if params_path and name != "lsdadvance":
        raise ValueError("parameters apply to the lsdadvance method only, not to '%s'" % name)
    if name == "lsdadvance":
        detector = lsda.createLSDAdvance()
        if params_path:
            fs = open_params_file(params_path)
            # save() nests the parameters under the algorithm's name; write() does not.
            named = fs.getNode(detector.getDefaultName())
            detector.read(fs.root() if named.empty() else named)
        return LineMethod("LSDAdvance", detector.detect, detector.reset, detector)
    if name == "lsd":
        lsd = cv2.createLineSegmentDetector()
        return LineMethod("LSD", lambda gray: lsd.detect(gray)[0], lambda: None, None)
    if name == "fld":
        fld = cv2.ximgproc.createFastLineDetector()
        return LineMethod("FLD", fld.detect, lambda: None, None)
    ed = cv2.ximgproc.createEdgeDrawing()

    def detect_edlines(gray):
        ed.detectEdges(gray)
        return ed.detectLines()
    return LineMethod("EDLines", detect_edlines, lambda: None, None)


def read_gray_image(path):
    """The gray image of a file, None when OpenCV cannot decode it. The bytes go to imdecode:
    imread's file reader would also print libjpeg's warnings (a truncated JPEG), the sample
    reports unreadable files itself."""
    try:
        data = np.fromfile(path, np.uint8)
    except OSError:
        return None
    return cv2.imdecode(data, cv2.IMREAD_GRAYSCALE) if data.size else None


class FrameSource:
    """The gray images to detect on, as (gray, stem): an image file, the images of a folder in
    name order, or the frames of a video. A file of a folder that cannot be read as an image is
    reported on stderr and skipped (skipped lists them); with a progress label, "[label] k/n"
    counts the files on one stderr line."""

    def __init__(self, source, progress_label=""):
        self.progress_label = progress_label
        self.skipped = []
        self.single_image = False
        self.video = None
        self._progress_shown = False
        path = cv2.samples.findFile(source, False, True) or source
        self.paths = []
        if os.path.isdir(path):
            self.paths = list(lsda.line_evaluation.loadSequence(path).imagePaths)  # name order; raises when there is none
        elif os.path.isfile(path) and cv2.haveImageReader(path):
            self.paths = [path]
            self.single_image = True
        elif os.path.exists(path) and cv2.haveImageWriter(path):
            # A file named as an image (OpenCV would write one under this name) is not tried as a
            # video: the video backends would only add their own messages to the sample's error.
            raise RuntimeError("cannot read %s as an image" % path)
        elif not os.path.exists(path) and "://" not in path and "%" not in path:
            # Streams and image-sequence patterns do not exist as files; anything else missing is
            # reported here rather than by the video backends' warnings.
            raise RuntimeError("no such image, folder or video: " + path)
        else:
            # The backends that cannot open the file log why; the sample's error says it once.
            log_level = cv2.setLogLevel(LOG_LEVEL_FATAL)
            self.video = cv2.VideoCapture(path)
            cv2.setLogLevel(log_level)
            if not self.video.isOpened():
                raise RuntimeError("cannot read %s as an image or a video" % path)

    def count(self):
        """Number of images, 0 when a video does not tell."""
        if self.video is not None:
            return max(0, int(self.video.get(cv2.CAP_PROP_FRAME_COUNT)))
        return len(self.paths)

    def _show_progress(self, done):
        if not self.progress_label or self.single_image:
            return
        total = self.count()
        sys.stderr.write("\r[%s] %d%s" % (self.progress_label, done, "/%d" % total if total else ""))
        sys.stderr.flush()
        self._progress_shown = True

    def _end_progress_line(self):
        if self._progress_shown:
            sys.stderr.write("\n")
        self._progress_shown = False

    def __iter__(self):
        if self.video is not None:
            index = 0
            while True:
                ok, frame = self.video.read()
                if not ok or frame is None:
                    break
                if frame.ndim == 3:
                    frame = cv2.cvtColor(frame, cv2.COLOR_BGRA2GRAY if frame.shape[2] == 4 else cv2.COLOR_BGR2GRAY)
                index += 1
                self._show_progress(index)
                yield frame, "frame_%06d" % (index - 1)
            self._end_progress_line()
            return
        read = 0
        for index, path in enumerate(self.paths):
            self._show_progress(index + 1)
            gray = read_gray_image(path)
            if gray is not None:
                read += 1
                yield gray, os.path.splitext(os.path.basename(path))[0]
                continue
            if self.single_image:
                raise RuntimeError("cannot read %s as an image" % path)
            self.skipped.append(path)
            self._end_progress_line()
            sys.stderr.write("skipped %s: not an image OpenCV can read\n" % path)
        self._end_progress_line()
        if read == 0 and self.skipped:
            raise RuntimeError("none of the %d image files could be read" % len(self.skipped))


# --------------------------------------------------------------------------------------------
# Drawings of the stages (as samples/lsd_advance_detect.cpp draws them, pixel for pixel)

GREY, KEPT, DROPPED, FUSED = (150, 150, 150), (80, 220, 80), (60, 60, 235), (230, 200, 40)
PIECE_A, PIECE_B = (40, 170, 255), (200, 80, 255)
DRAWINGS = ("lines", "filter", "groups", "merge")


def parse_drawings(text):
    """The set of DRAWINGS that --draw asks for; --draw alone means lines."""
    kinds = set()
    for kind in text.split(","):
        if kind == "stages":
            kinds |= {"filter", "groups", "merge"}
        elif kind in DRAWINGS:
            kinds.add(kind)
        elif kind:
            raise ValueError("unknown drawing '%s'; known: lines, filter, groups, merge, stages" % kind)
    return kinds


def _pixel(value):
    """A float coordinate as cv::Point(Point2f) makes it: float32, rounded half to even."""
    return int(round(float(np.float32(value))))


class StageCanvas:
    """The image, or a region of it enlarged to about 900 px wide (--zoom), darkened so that
    coloured segments stand out on any content; segments are given in image coordinates."""

    def __init__(self, gray, region):
        x, y, w, h = region
        self.region = region
        self.scale = max(1, round(900.0 / w))
        dim = cv2.convertScaleAbs(gray[y:y + h, x:x + w], alpha=0.4, beta=10)
        dim = cv2.resize(dim, None, fx=self.scale, fy=self.scale, interpolation=cv2.INTER_LINEAR)
        self.image = cv2.cvtColor(dim, cv2.COLOR_GRAY2BGR)
        self.stroke = max(1, round(min(self.image.shape[:2]) / 900.0))
        self.whole = (w, h) == (gray.shape[1], gray.shape[0])

    def copy(self):
        """A separate drawing on the same background."""
        other = StageCanvas.__new__(StageCanvas)
        other.__dict__.update(self.__dict__)
        other.image = self.image.copy()
        return other

    def at(self, x, y):
        """Pixel i of the image covers [i - 0.5, i + 0.5), as pixel centres are integers."""
        rx, ry = self.region[:2]
        return (_pixel((float(np.float32(x) - np.float32(rx)) + 0.5) * self.scale - 0.5),
                _pixel((float(np.float32(y) - np.float32(ry)) + 0.5) * self.scale - 0.5))

    def segment(self, s, colour, thickness, target=None):
        cv2.line(self.image if target is None else target, self.at(s[0], s[1]), self.at(s[2], s[3]), colour,
                 thickness, cv2.LINE_AA)

    def endpoints(self, s, colour):
        cv2.circle(self.image, self.at(s[0], s[1]), self.stroke + 1, colour, cv2.FILLED, cv2.LINE_AA)
        cv2.circle(self.image, self.at(s[2], s[3]), self.stroke + 1, colour, cv2.FILLED, cv2.LINE_AA)

    def shown_part(self):
        """For the title: which part of the image is shown."""
        return "" if self.whole else " [region %d,%d %dx%d, %dx]" % (tuple(self.region) + (self.scale,))


def parse_zoom(text):
    """--zoom=x,y,w,h (pixels, width and height >= 1) as a tuple; None when not given."""
    if not text:
        return None
    found = re.fullmatch(r"([+-]?[0-9]+),([+-]?[0-9]+),([+-]?[0-9]+),([+-]?[0-9]+)", text)
    if not found or int(found.group(3)) < 1 or int(found.group(4)) < 1:
        raise ValueError("--zoom must be x,y,width,height in pixels, width and height >= 1, got '%s'" % text)
    return tuple(int(v) for v in found.groups())


def zoom_region(zoom, size):
    """The zoom rectangle within the image of size (width, height); the whole image without --zoom."""
    if zoom is None:
        return (0, 0) + tuple(size)
    x0, y0 = max(zoom[0], 0), max(zoom[1], 0)
    x1, y1 = min(zoom[0] + zoom[2], size[0]), min(zoom[1] + zoom[3], size[1])
    if x1 <= x0 or y1 <= y0:
        raise ValueError("--zoom=%d,%d,%d,%d does not overlap the %dx%d image" % (zoom + tuple(size)))
    return (x0, y0, x1 - x0, y1 - y0)


def with_caption(picture, title, legend):
    """The drawing with a black band above it: a title, then the legend of (colour, text), wrapped."""
    font = cv2.FONT_HERSHEY_SIMPLEX
    width = picture.shape[1]
    scale = min(1.2, max(0.42, width / 1500.0))
    weight = 2 if scale > 0.8 else 1
    (_, text_height), baseline = cv2.getTextSize("Ag", font, scale, weight)
    row_height, margin, key_length = text_height + baseline + 8, 8, 3 * text_height

    rows, x = [[]], margin  # rows of (x, item), the title alone on the first row
    for colour, text in legend:
        item_width = key_length + 6 + cv2.getTextSize(text, font, scale, weight)[0][0]
        if len(rows) == 1 or (x + item_width > width - margin and rows[-1]):
            rows.append([])
            x = margin
        rows[-1].append((x, colour, text))
        x += item_width + 3 * margin
    out = np.zeros((picture.shape[0] + len(rows) * row_height + margin, width, 3), np.uint8)
    out[out.shape[0] - picture.shape[0]:] = picture
    cv2.putText(out, title, (margin, margin + text_height), font, scale, (255, 255, 255), weight, cv2.LINE_AA)
    for r in range(1, len(rows)):
        y = margin + r * row_height + text_height
        for x, colour, text in rows[r]:
            cv2.line(out, (x, y - text_height // 2), (x + key_length, y - text_height // 2), colour,
                     max(2, weight + 1), cv2.LINE_AA)
            cv2.putText(out, text, (x + key_length + 6, y), font, scale, (255, 255, 255), weight, cv2.LINE_AA)
    return out


def group_colour(k):
    """Distinct colour number k: hues spaced by the golden angle, bright and saturated."""
    hue = math.fmod(k * 0.618033988749895, 1.0) * 180.0
    hsv = np.array([[[round(hue), 170 if k % 3 == 1 else 255, 255]]], np.uint8)
    return tuple(int(c) for c in cv2.cvtColor(hsv, cv2.COLOR_HSV2BGR)[0, 0])


def _segments(array):
    """Segments of an (N, 1, 4) array (or None) as a list of 4-tuples of floats."""
    return [] if array is None else [tuple(float(v) for v in s) for s in array.reshape(-1, 4)]


class Stages:
    """The outputs of the stages of the last detect(), the lines it returned with the base segments
    each was made from, and how the stages were run."""

    def __init__(self, detector, lines):
        base, filtered, labels, merged = detector.getLastStageOutputs()
        self.base, self.filtered, self.merged = _segments(base), _segments(filtered), _segments(merged)
        self.lines = _segments(lines)
        self.sources = [[int(i) for i in s.reshape(-1)] for s in detector.getLastSources()]
        self.labels = [] if labels is None else [int(v) for v in labels.reshape(-1)]
        self.stats = detector.getLastStats()
        self.filter_first = detector.getStageOrder() == lsda.LSDAdvance_FILTER_THEN_MERGE
        self.filter_on = detector.getLengthFilterMode() != lsda.LSDAdvance_LENGTH_FILTER_NONE
        self.merge_on = detector.getMergeStrategy() != lsda.LSDAdvance_MERGE_NONE

    def filter_input(self):
        return self.base if self.filter_first else self.merged

    def grouping_input(self):
        return self.filtered if self.filter_first else self.base


def draw_filter(canvas, st):
    """(a) Stage 1: the segments it kept and those it dropped."""
    w = canvas.stroke
    inputs = st.filter_input()
    k = 0  # the filter keeps segments in their order: kept ones are a subsequence of the input
    for s in inputs:
        if k < len(st.filtered) and s == st.filtered[k]:
            k += 1
        else:
            canvas.segment(s, DROPPED, w)
    for s in st.filtered:
        canvas.segment(s, KEPT, w + 1)
    # Short segments stay when strong (setKeepStrongSegments): then the response threshold is shown too.
    strong = st.stats.minResponse > 0
    title = "Stage 1, length filter on the %s segments: min length %.1f px%s (alpha %.2f)%s%s" % (
        "base" if st.filter_first else "merged", st.stats.minLength,
        " or min response %.4f" % st.stats.minResponse if strong else "", st.stats.alpha,
        "" if st.filter_on else " - filter off", canvas.shown_part())
    dropped = "dropped (shorter and weaker): %d" if strong else "dropped (shorter): %d"
    return with_caption(canvas.image, title, [(KEPT, "kept: %d" % len(st.filtered)),
                                              (DROPPED, dropped % (len(inputs) - len(st.filtered)))])


def draw_groups(canvas, st):
    """(b) Stage 2: each group of two or more segments in its own colour, segments alone in grey."""
    w = canvas.stroke
    inputs = st.grouping_input()
    alone = grouped = 0
    for i, s in enumerate(inputs):
        if not st.labels or st.labels[i] < 0:
            canvas.segment(s, GREY, w)
            alone += 1
    for i, label in enumerate(st.labels):
        if label >= 0:
            canvas.segment(inputs[i], group_colour(label), w + 1)
            grouped += 1
    title = "Stage 2, grouping of the %s segments by angle and endpoints%s%s" % (
        "filtered" if st.filter_first else "base", "" if st.merge_on else " - merging off", canvas.shown_part())
    return with_caption(canvas.image, title, [
        (group_colour(0), "%d groups of 2+ segments (one colour each): %d segments" % (st.stats.mergeGroups, grouped)),
        (GREY, "alone: %d" % alone)])


def draw_merge(canvas, st):
    """(c) Stage 3: every returned line fused from several base segments (getLastSources()) as a
    wide band with those pieces drawn thin on top in alternating colours; lines of one segment in
    grey."""
    w = canvas.stroke
    fused = pieces = unchanged = 0
    for line, sources in zip(st.lines, st.sources):
        if len(sources) == 1:
            canvas.segment(line, GREY, w)
            unchanged += 1
    bands = canvas.image.copy()
    for line, sources in zip(st.lines, st.sources):
        if len(sources) > 1:
            canvas.segment(line, FUSED, 4 * w + 3, bands)
            fused += 1
    canvas.image = cv2.addWeighted(bands, 0.6, canvas.image, 0.4, 0)
    for sources in st.sources:
        if len(sources) > 1:
            for i in sources:
                colour = PIECE_B if pieces % 2 else PIECE_A
                canvas.segment(st.base[i], colour, w)
                canvas.endpoints(st.base[i], colour)
                pieces += 1
    title = "Stage 3, merging: %d segments in, %d out, %d returned%s%s" % (
        len(st.grouping_input()), len(st.merged), len(st.lines), "" if st.merge_on else " - merging off",
        canvas.shown_part())
    return with_caption(canvas.image, title, [
        (FUSED, "fused lines: %d" % fused),
        (PIECE_A, "base segments they were fused from (orange and pink in turn): %d" % pieces),
        (GREY, "lines of one segment: %d" % unchanged)])


def write_image(path, image):
    if not cv2.imwrite(path, image):
        raise RuntimeError("cannot write " + path)


# --------------------------------------------------------------------------------------------


def main():
    parser = SampleArgumentParser(
        description="Detects line segments with LSDAdvance (or another method) and writes them to text files.",
        epilog="Exit status: 0, 1 on an error, 2 when unreadable files of a folder were skipped.")
    parser.add_argument("-i", "--input", required=True,
                        help="an image, a folder of images (png, jpg, jpeg, ppm, pgm, bmp) or a video; "
                             "OpenCV sample names are found in OPENCV_SAMPLES_DATA_PATH")
    parser.add_argument("-o", "--output", default="",
                        help="folder for <stem>.txt (x1 y1 x2 y2 per segment, pixel centres); created if missing")
    parser.add_argument("-m", "--method", default="lsdadvance", choices=METHODS)
    parser.add_argument("--sequence", action="store_true",
                        help="the images of a folder (in name order) or a video are consecutive frames: "
                             "LSDAdvance's inter-frame factor is on; otherwise every image is independent")
    parser.add_argument("--draw", nargs="?", const="lines", default="",
                        help="also write drawings (needs --output), a comma-separated list: lines (<stem>.png, the "
                             "segments on the image; --draw alone means lines); for LSDAdvance filter "
                             "(<stem>_filter.png: kept and dropped by the length filter), groups (<stem>_groups.png: "
                             "the merge groups in colours), merge (<stem>_merge.png: fused segments and their "
                             "pieces); stages = filter,groups,merge")
    parser.add_argument("--ext", default="png", choices=("png", "jpg"), help="file type of the drawings")
    parser.add_argument("--zoom", default="",
                        help="the filter, groups and merge drawings show only this region x,y,width,height (px, "
                             "width and height >= 1, overlapping the image) of the image, enlarged to about 900 px wide")
    parser.add_argument("--no-segments", action="store_true", help="with --output, write only the drawings, not <stem>.txt")
    parser.add_argument("-p", "--params", default="",
                        help="YAML/XML of LSDAdvance parameters saved with save() or write(), for the lsdadvance method")
    parser.add_argument("--long", type=number(0, low_excluded=True), default=60.0,
                        help="length in pixels from which a segment counts as long, > 0")
    args = parser.parse_args()
    draw = parse_drawings(args.draw)
    zoom = parse_zoom(args.zoom)
    if draw and not args.output:
        raise ValueError("--draw needs --output=<folder>")

    method = make_method(args.method, args.params)
    if draw - {"lines"} and method.lsd_advance is None:
        raise ValueError("--draw=filter, groups or merge needs an LSDAdvance method, not " + method.name)
    source = FrameSource(args.input, "detect")
    if args.output:
        os.makedirs(args.output, exist_ok=True)
    drawer = lsda.createLSDAdvance()
    segments, long_segments, ms = 0, 0.0, []
    method.reset()
    for gray, stem in source:
        # Unrelated images must not steer the inter-frame factor of the next one.
        if not args.sequence:
            method.reset()
        tm = cv2.TickMeter()
        tm.start()
        lines = method.detect(gray)
        tm.stop()
        if lines is None:  # what cv2's detectors return for no segment
            lines = np.zeros((0, 1, 4), np.float32)
        ms.append(tm.getTimeMilli())
        segments += len(lines)
        long_segments += lsda.line_evaluation.longSegmentShare(lines, args.long) * len(lines)
        if args.output and not args.no_segments:
            lsda.line_evaluation.writeSegments(os.path.join(args.output, stem + ".txt"), lines)
        if "lines" in draw:
            canvas = drawer.drawSegments(gray.copy(), lines)
            write_image(os.path.join(args.output, stem + "." + args.ext), canvas)
        if draw - {"lines"}:
            stages = Stages(method.lsd_advance, lines)
            canvas = StageCanvas(gray, zoom_region(zoom, (gray.shape[1], gray.shape[0])))
            for kind, drawing in (("filter", draw_filter), ("groups", draw_groups), ("merge", draw_merge)):
                if kind in draw:
                    write_image(os.path.join(args.output, "%s_%s.%s" % (stem, kind, args.ext)),
                                drawing(canvas.copy(), stages))
    if not ms:
        raise RuntimeError("no frame in " + args.input)

    print("method:            %s" % method.name)
    if source.skipped:
        print("images:            %d (%d unreadable file(s) skipped)" % (len(ms), len(source.skipped)))
    else:
        print("images:            %d" % len(ms))
    print("segments / image:  %.1f" % (segments / len(ms)))
    print("long share:        %.3f (>= %g px, over all segments)" % (long_segments / segments if segments else 0.0,
                                                                       args.long))
    # The C++ sample's median: the upper of the two middle values for an even count.
    print("ms / image:        %.2f mean, %.2f median (detection only)" % (np.mean(ms), sorted(ms)[len(ms) // 2]))
    if args.output:
        if not args.no_segments:
            print("wrote %d segment file(s)%s to %s" % (len(ms), " and drawings" if draw else "", args.output))
        else:
            print("wrote the drawings of %d image(s) to %s" % (len(ms), args.output))
    return EXIT_SKIPPED if source.skipped else 0


if __name__ == "__main__":
    run_reporting_errors(main)
