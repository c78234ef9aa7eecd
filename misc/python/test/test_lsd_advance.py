#!/usr/bin/env python
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of the Python bindings, found by OpenCV's runner in-tree (modules/python/test/test.py) and
run by scripts/test_python.sh in the standalone build. They test cv2.ximgproc when it has the
module (an OpenCV built with it), otherwise the standalone module lsd_advance: the same names from
the same headers.

Data: OpenCV's sample images (OPENCV_SAMPLES_DATA_PATH, default Debian's opencv-doc folder);
missing images skip the tests that need them, except with CI=true, where they fail.
"""

import importlib
import math
import os
import re
import sys
import tempfile

import numpy as np
import cv2 as cv

from tests_common import NewOpenCVTests

api = cv.ximgproc if hasattr(cv.ximgproc, "createLSDAdvance") else importlib.import_module("lsd_advance")
evaluation = api.line_evaluation

HEADER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "include", "opencv2",
                      "lsd_advance", "lsd_advance.hpp")
DATA = os.environ.get("OPENCV_SAMPLES_DATA_PATH", "/usr/share/doc/opencv-doc/examples/data")
CI = os.environ.get("CI") == "true"
NOT_PARAMETERS = {"format"}  # keys of write() that are not parameters


def saved_parameters(detector):
    """The names of LSDAdvance's own parameters save() writes (the bases' are in maps)."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "params.yml")
        detector.save(path)
        fs = cv.FileStorage(path, cv.FILE_STORAGE_READ)
        node = fs.getNode(detector.getDefaultName())
        return sorted(k for k in node.keys() if k not in NOT_PARAMETERS and not node.getNode(k).isMap())


PARAMETERS = saved_parameters(api.createLSDAdvance())
BASE_STRUCTS = ("LSDParams", "FLDParams", "EDLinesParams")


def fields(struct):
    return sorted(a for a in dir(struct) if not a.startswith("_"))


def getter(detector, name):
    return getattr(detector, "get" + name[0].upper() + name[1:])


def setter(detector, name):
    return getattr(detector, "set" + name[0].upper() + name[1:])


def other_values(name):
    """Values other than the default that the setter of name accepts, nearest first."""
    value = getter(api.createLSDAdvance(), name)()
    if isinstance(value, bool):
        candidates = [not value]
    elif isinstance(value, int):
        candidates = [value + 1, value - 1, value * 2, value // 2, value + 2, 0, 1, 2, 3, 4, 10, 20, 40]
    else:
        candidates = [value * 0.5, value * 0.9, value * 1.1, value * 2, value + 1, value - 1, 0.3, 3.0, 10.0]
    accepted = []
    for v in candidates:
        if v == value or v in accepted:
            continue
        try:
            setter(api.createLSDAdvance(), name)(v)
        except cv.error:
            continue
        accepted.append(v)
    return accepted


def set_up_for(detector, name):
    """What a parameter that acts only in another configuration needs first."""
    if name == "baselineRatio":
        detector.setMergeStrategy(api.LSDAdvance_MERGE_BASELINES)
    if name == "minLineLength":  # the lengths the values tried (up to 10 px) drop: the base's shortest
        detector.setLengthFilterMode(api.LSDAdvance_LENGTH_FILTER_NONE)
    if name in ("directionBins", "gridCells"):
        detector.setLineOrder(api.LSDAdvance_LINE_ORDER_ACROSS_DIRECTIONS)


def as_lines(lines):
    """detect()'s result as an (N, 1, 4) array, N = 0 for None."""
    return np.zeros((0, 1, 4), np.float32) if lines is None else lines


def as_set(lines):
    """Lines as a sorted list of (x1, y1, x2, y2): detect() orders them by response, processSegments()
    (without an image) by length."""
    return sorted(map(tuple, as_lines(lines).reshape(-1, 4).tolist()))


def header_text():
    with open(HEADER) as f:
        return f.read()


def header_methods():
    return sorted(set(re.findall(r"CV_WRAP(?:_AS\((\w+)\))?\s+(?:virtual\s+)?[\w:<>]+\s+(\w+)\s*\(", header_text())))


def header_constants():
    """{binding name: value} of the enum constants of class LSDAdvance."""
    text = header_text()
    body = text[text.index("class CV_EXPORTS_W LSDAdvance"):]
    constants = {}
    for enum in re.findall(r"\benum\s+\w+\s*\{(.*?)\}", body, re.S):
        enum = re.sub(r"/\*.*?\*/|//[^\n]*", "", enum, flags=re.S)  # comments name other enums' values
        constants.update(("LSDAdvance_" + n, int(v)) for n, v in re.findall(r"\b([A-Z][A-Z0-9_]+)\s*=\s*(\d+)", enum))
    return constants


def random_segments(count, seed):
    rng = np.random.default_rng(seed)
    start = rng.uniform(0, 500, (count, 2))
    angle = rng.uniform(0, math.pi, count)
    length = rng.uniform(2, 80, count)
    end = start + np.stack([np.cos(angle), np.sin(angle)], 1) * length[:, None]
    return np.concatenate([start, end], 1).astype(np.float32).reshape(-1, 1, 4)


def interframe_alpha(kept_before_last, kept_last):
    """The documented LENGTH_FILTER_INTERFRAME rule."""
    r = (kept_last - kept_before_last) / kept_before_last if kept_before_last else 0.0
    if r < -0.1:
        return 1 - 0.2 * (1 + r)
    if r > 0.1:
        return min(1 + 0.1 * (r - 0.1), 1.2)
    return 1.0


class StderrOfProcess(object):
    """What the process writes to its standard error (file descriptor 2: OpenCV's log) meanwhile."""

    def __enter__(self):
        sys.stderr.flush()
        self.saved = os.dup(2)
        self.file = tempfile.TemporaryFile()
        os.dup2(self.file.fileno(), 2)
        return self

    def __exit__(self, *exc):
        sys.stderr.flush()
        os.dup2(self.saved, 2)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read().decode("utf-8", "replace")
        self.file.close()


class lsd_advance_test(NewOpenCVTests):

    def image(self, name, flags=cv.IMREAD_GRAYSCALE):
        path = os.path.join(DATA, name)
        if not os.path.isfile(path):
            message = "missing %s (install opencv-doc or set OPENCV_SAMPLES_DATA_PATH)" % path
            if CI:
                self.fail(message + " (CI=true: required)")
            self.skipTest(message)
        return cv.imread(path, flags)

    def building(self):
        return self.image("building.jpg")

    def small_building(self):
        return cv.resize(self.building(), None, fx=0.5, fy=0.5, interpolation=cv.INTER_AREA)

    # ----------------------------------------------------------------------------------------
    # detect

    def test_detect_returns_n_by_1_by_4_float32(self):
        lines = api.createLSDAdvance().detect(self.building())
        self.assertIsInstance(lines, np.ndarray)
        self.assertEqual(lines.dtype, np.float32)
        self.assertEqual(lines.ndim, 3)
        self.assertEqual(lines.shape[1:], (1, 4))
        self.assertGreater(lines.shape[0], 0)

    def test_detect_returns_what_cv2_detectors_return_for_no_segment(self):
        blank = np.zeros((64, 64), np.uint8)
        expected = cv.ximgproc.createFastLineDetector().detect(blank)
        self.assertIsNone(expected)
        self.assertIsNone(api.createLSDAdvance().detect(blank))

    def test_detect_equals_processSegments_of_opencv_lsd(self):
        building = self.building()
        detector = api.createLSDAdvance()
        detector.setBaseDetector(api.LSDAdvance_BASE_LSD)
        p = detector.getLSDParams()
        p.fullScaleSigma = 0  # OpenCV's LSD reads the image as it is
        detector.setLSDParams(p)
        lsd = cv.createLineSegmentDetector(p.refine, p.scale, p.sigmaScale, p.quant, p.angleTolerance, p.logEps,
                                           p.densityThreshold, p.numBins)
        base = lsd.detect(building)[0]
        lines = detector.detect(building)
        self.assertEqual(detector.getLastStats().baseSegments, len(base))
        size = (building.shape[1], building.shape[0])
        self.assertEqual(as_set(detector.processSegments(base, None, size)), as_set(lines))
        self.assertEqual(as_set(detector.processSegments(base, imageSize=size)), as_set(lines))

    def test_mask_keeps_lines_off_its_zeros_in_detect_and_detectKeyLines(self):
        building = self.small_building()
        detector = api.createLSDAdvance()
        everything = detector.detect(building)
        self.assertTrue(np.array_equal(detector.detect(building, None, np.full_like(building, 255)), everything))
        self.assertIsNone(detector.detect(building, mask=np.zeros_like(building)))
        mask = np.zeros_like(building)
        mask[:, :building.shape[1] // 2] = 255  # the left half only
        lines = detector.detect(building, mask=mask)
        self.assertGreater(len(lines), 0)
        self.assertLess(len(lines), len(everything))
        self.assertTrue(np.all(np.round(lines[:, 0, [0, 2]]) < building.shape[1] // 2))
        keylines = detector.detectKeyLines(building, mask)
        self.assertEqual(len(keylines), len(lines))

    def test_mask_of_another_type_or_size_raises_cv2_error(self):
        building = self.small_building()
        for mask in (np.zeros(building.shape, np.float32), np.zeros((8, 8), np.uint8)):
            with self.subTest(shape=mask.shape, dtype=mask.dtype), self.assertRaises(cv.error) as info:
                api.createLSDAdvance().detect(building, mask=mask)
            self.assertIn("the mask must be CV_8UC1 of the image's size", str(info.exception))

    def test_computeLineResponses_is_length_times_squared_contrast_of_the_brighter_left(self):
        # A step of 150 gray levels under a 120 px segment pointing up (bright side on its left).
        step = np.full((200, 300), 50, np.uint8)
        step[:, :150] = 200
        up = np.array([[[149.5, 160, 149.5, 40]]], np.float32)
        responses = api.computeLineResponses(step, up)
        self.assertEqual(responses.shape, (1, 1))
        self.assertEqual(responses.dtype, np.float32)
        self.assertAlmostEqual(responses[0, 0], 120 / 300 * (150 / 255) ** 2, delta=1e-5 * responses[0, 0])
        self.assertEqual(api.computeLineResponses(step, up[:, :, [2, 3, 0, 1]])[0, 0], 0)
        with self.assertRaises(cv.error):
            api.computeLineResponses(np.zeros((0, 0), np.uint8), up)

    def test_keepStrongSegments_is_off_by_default_and_on_in_the_sequence_preset(self):
        building = self.building()
        self.assertFalse(api.createLSDAdvance().getKeepStrongSegments())
        sequence = api.createLSDAdvance(api.LSDAdvance_PRESET_SEQUENCE)
        self.assertTrue(sequence.getKeepStrongSegments())
        self.assertGreater(len(sequence.detect(building)), len(api.createLSDAdvance().detect(building)))
        self.assertGreater(sequence.getLastStats().minResponse, 0)

    def test_gray_bgr_and_bgra_input_agree(self):
        building = self.building()
        detector = api.createLSDAdvance()
        gray = detector.detect(building)
        bgr = cv.cvtColor(building, cv.COLOR_GRAY2BGR)
        for image in (bgr, cv.cvtColor(bgr, cv.COLOR_BGR2BGRA)):
            detector.reset()
            self.assertTrue(np.array_equal(detector.detect(image), gray))

    def test_non_contiguous_views_give_the_lines_of_a_contiguous_copy(self):
        small = self.small_building()
        detector = api.createLSDAdvance()
        expected = detector.detect(small)
        wide = np.zeros((small.shape[0], small.shape[1] * 2), np.uint8)
        wide[:, ::2] = small
        views = {
            "column stride 2": wide[:, ::2],
            "flipped twice": np.ascontiguousarray(small[::-1, ::-1])[::-1, ::-1],
            "Fortran order": np.asfortranarray(small),
            "channel of a BGR image": cv.cvtColor(small, cv.COLOR_GRAY2BGR)[:, :, 1],
        }
        for name, view in views.items():
            with self.subTest(view=name):
                detector.reset()
                self.assertTrue(np.array_equal(detector.detect(view), expected))

    def test_output_array_that_fits_is_filled_in_place(self):
        small = self.small_building()
        detector = api.createLSDAdvance()
        expected = detector.detect(small)
        out = np.zeros_like(expected)
        detector.reset()
        self.assertIs(detector.detect(small, out), out)
        self.assertTrue(np.array_equal(out, expected))

    def test_getLastStats_counts_the_last_call(self):
        detector = api.createLSDAdvance()
        lines = detector.detect(self.small_building())
        stats = detector.getLastStats()
        self.assertEqual(stats.outputSegments, len(lines))
        self.assertGreaterEqual(stats.baseSegments, stats.mergedSegments)
        self.assertGreaterEqual(stats.mergedSegments, stats.outputSegments)
        self.assertEqual(stats.alpha, 1.0)
        self.assertGreater(stats.minLength, 0)
        # A new LSDAdvanceStats has the C++ constructor's values: those before the first call.
        fresh = api.LSDAdvanceStats()
        self.assertEqual((fresh.alpha, fresh.baseSegments), (api.createLSDAdvance().getLastStats().alpha, 0))

    # ----------------------------------------------------------------------------------------
    # Bad input: OpenCV's own messages, as cv2.error

    def test_bad_image_raises_cv2_error_with_opencv_message(self):
        cases = [(np.zeros((0, 0), np.uint8), "the input image is empty"),
                 (np.zeros((32, 32), np.float64), "unsupported image type CV_64FC1"),
                 (np.zeros((32, 32, 2), np.uint8), "unsupported image type CV_8UC2"),
                 (None, "the input image is empty")]
        for image, message in cases:
            with self.subTest(message=message), self.assertRaises(cv.error) as info:
                api.createLSDAdvance().detect(image)
            self.assertIn(message, str(info.exception))
            self.assertTrue(str(info.exception).startswith("OpenCV("))
            self.assertIn(message, info.exception.err)

    def test_unsupported_numpy_dtype_raises(self):
        with self.assertRaises((TypeError, cv.error)) as info:
            api.createLSDAdvance().detect(np.zeros((8, 8), bool))
        self.assertIn("not supported", str(info.exception))

    def test_non_finite_segments_raise_cv2_error(self):
        segments = np.array([[[0, 0, math.nan, 5]]], np.float32)
        with self.assertRaisesRegex(cv.error, "finite"):
            api.createLSDAdvance().processSegments(segments)

    def test_rejected_setter_raises_naming_the_parameter_and_keeps_the_value(self):
        detector = api.createLSDAdvance()
        before = detector.getMergeThreshold()
        with self.assertRaises(cv.error) as info:
            detector.setMergeThreshold(math.nan)
        self.assertRegex(str(info.exception), r"mergeThreshold must be a finite number in [\[(].*, got nan")
        self.assertEqual(detector.getMergeThreshold(), before)

    def test_real_setters_reject_nan(self):
        for name in PARAMETERS:
            detector = api.createLSDAdvance()
            before = getter(detector, name)()
            if not isinstance(before, float):
                continue
            with self.subTest(parameter=name), self.assertRaises(cv.error) as info:
                setter(detector, name)(math.nan)
            self.assertIn(name, str(info.exception))
            self.assertIn("nan", str(info.exception))
            self.assertEqual(getter(detector, name)(), before)

    # ----------------------------------------------------------------------------------------
    # The API: every method and constant of the header, every parameter

    def test_every_wrapped_method_of_the_header_is_exposed(self):
        detector = api.createLSDAdvance()
        methods = sorted(set(alias or name for alias, name in header_methods()))
        self.assertGreater(len(methods), 40)
        for name in ("drawSegments", "getLastSources", "detectKeyLines"):
            self.assertIn(name, methods)
        self.assertEqual([m for m in methods if not hasattr(detector, m)], [])
        self.assertIsInstance(detector, cv.Algorithm)

    def test_every_enum_constant_is_exposed_with_its_cpp_value(self):
        constants = header_constants()
        self.assertIn("LSDAdvance_LENGTH_FILTER_INTERFRAME", constants)
        self.assertIn("LSDAdvance_PRESET_PAPER", constants)
        self.assertEqual({n: getattr(api, n, None) for n in constants}, constants)

    def test_every_saved_parameter_has_a_getter_and_a_setter_and_a_field(self):
        detector = api.createLSDAdvance()
        self.assertEqual(PARAMETERS, fields(api.LSDAdvance.Params()))
        for name in PARAMETERS:
            self.assertTrue(callable(getter(detector, name)), name)
            self.assertTrue(callable(setter(detector, name)), name)

    def test_new_params_structs_hold_the_defaults(self):
        # The C++ constructors run (a struct without one would be zeros).
        detector = api.createLSDAdvance()
        params = api.LSDAdvance.Params()
        self.assertEqual({n: getattr(params, n) for n in PARAMETERS}, {n: getter(detector, n)() for n in PARAMETERS})
        for struct in ("LSDParams", "FLDParams"):
            made, got = getattr(api.LSDAdvance, struct)(), getattr(detector, "get" + struct)()
            self.assertEqual({n: getattr(made, n) for n in fields(made)}, {n: getattr(got, n) for n in fields(got)})
        ground_truth = np.array([[[0, 0.5, 100, 0.5]]], np.float32)
        detections = np.array([[[0, 0, 99, 0]]], np.float32)
        by_default = evaluation.evaluateStructural(detections, ground_truth)
        given = evaluation.evaluateStructural(detections, ground_truth, evaluation.StructuralMatchParams())
        self.assertEqual((by_default.precision, by_default.recall), (given.precision, given.recall))
        self.assertEqual(by_default.found, 1)

    def test_createLSDAdvance_takes_a_preset(self):
        fastest = api.createLSDAdvance(api.LSDAdvance_PRESET_FASTEST)
        self.assertEqual(fastest.getBaseDetector(), api.LSDAdvance_BASE_FAST_LSD)
        self.assertEqual(fastest.getLSDParams().scale, 0.8)
        paper = api.createLSDAdvance(preset=api.LSDAdvance_PRESET_PAPER)
        self.assertEqual(paper.getLSDParams().refine, cv.LSD_REFINE_STD)
        self.assertEqual(paper.getLSDParams().scale, 0.8)
        self.assertEqual(paper.getMergeStrategy(), api.LSDAdvance_MERGE_BASELINES)
        self.assertEqual(api.createLSDAdvance(api.LSDAdvance_PRESET_SEQUENCE).getLengthFilterMode(),
                         api.LSDAdvance_LENGTH_FILTER_COUNT_TRACKING)
        self.assertEqual(api.createLSDAdvance().getLengthFilterMode(), api.LSDAdvance_LENGTH_FILTER_ADAPTIVE)
        with self.assertRaisesRegex(cv.error, "PRESET_MOST_ACCURATE"):
            api.createLSDAdvance(7)

    def test_params_round_trip_and_a_bad_field_changes_nothing(self):
        detector = api.createLSDAdvance()
        params = detector.getParams()
        params.mergeThreshold = 0.75
        params.lengthFilterMode = api.LSDAdvance_LENGTH_FILTER_NONE
        detector.setParams(params)
        self.assertEqual(detector.getMergeThreshold(), 0.75)
        self.assertEqual(detector.getLengthFilterMode(), api.LSDAdvance_LENGTH_FILTER_NONE)
        before = detector.getEndpointDistance()
        params.endpointDistance = before + 1
        params.proximityRatio = -1.0
        with self.assertRaisesRegex(cv.error, "proximityRatio"):
            detector.setParams(params)
        self.assertEqual(detector.getEndpointDistance(), before)

    def test_base_structs_round_trip_and_a_bad_field_changes_nothing(self):
        for struct in BASE_STRUCTS:
            with self.subTest(struct=struct):
                detector = api.createLSDAdvance()
                get, set_ = getattr(detector, "get" + struct), getattr(detector, "set" + struct)
                params = get()
                for name in fields(params):
                    value = getattr(params, name)
                    if isinstance(value, bool):
                        setattr(params, name, not value)
                    elif isinstance(value, float):
                        setattr(params, name, value * 0.9)
                    elif name in ("seedAlignedNeighbours", "regionGrowth", "fullScaleSmoothing"):  # 0, 1 or 2; 0 or 1
                        setattr(params, name, value - 1)
                    elif name not in ("refine", "EdgeDetectionOperator", "cannyApertureSize"):
                        setattr(params, name, value + 2 if value > 0 else 20)
                set_(params)
                got = get()
                for name in fields(got):
                    self.assertAlmostEqual(getattr(got, name), getattr(params, name), places=5, msg=name)
                bad = get()
                name = [n for n in fields(bad) if isinstance(getattr(bad, n), float)][0]
                setattr(bad, name, -5.0)
                with self.assertRaisesRegex(cv.error, name):
                    set_(bad)
                self.assertEqual({n: getattr(get(), n) for n in fields(got)}, {n: getattr(got, n) for n in fields(got)})

    def test_setters_round_trip(self):
        for name in PARAMETERS:
            values = other_values(name)
            with self.subTest(parameter=name):
                self.assertTrue(values, "no other valid value found for " + name)
                detector = api.createLSDAdvance()
                for value in values[:3]:
                    setter(detector, name)(value)
                    got = getter(detector, name)()
                    self.assertEqual(got, value)
                    self.assertIs(type(got), type(value))

    def test_every_setter_changes_detect_output(self):
        small = self.small_building()
        for name in PARAMETERS:
            with self.subTest(parameter=name):
                reference = api.createLSDAdvance()
                set_up_for(reference, name)
                expected = as_lines(reference.detect(small))
                changed_any = False
                for value in other_values(name):
                    changed = api.createLSDAdvance()
                    set_up_for(changed, name)
                    setter(changed, name)(value)
                    lines = as_lines(changed.detect(small))
                    if lines.shape != expected.shape or not np.array_equal(lines, expected):
                        changed_any = True
                        break
                self.assertTrue(changed_any, "no value of %s changes detect()'s output" % name)

    # ----------------------------------------------------------------------------------------
    # Persistence: cv2.Algorithm's save/read/write on the module's parameters

    def test_save_and_read_round_trip_every_parameter(self):
        configured = api.createLSDAdvance()
        for name in PARAMETERS:
            setter(configured, name)(other_values(name)[0])
        lsd = configured.getLSDParams()
        lsd.quant = 3.0
        configured.setLSDParams(lsd)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "params.yml")
            configured.save(path)
            loaded = api.createLSDAdvance()
            fs = cv.FileStorage(path, cv.FILE_STORAGE_READ)
            loaded.read(fs.getNode(loaded.getDefaultName()))
        for name in PARAMETERS:
            self.assertEqual(getter(loaded, name)(), getter(configured, name)(), name)
        self.assertEqual(loaded.getLSDParams().quant, 3.0)

    def test_saved_modes_are_names_and_read_takes_names_or_numbers(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "paper.yml")
            api.createLSDAdvance(api.LSDAdvance_PRESET_PAPER).save(path)
            with open(path) as f:
                text = f.read()
            for line in ("lengthFilterMode: LENGTH_FILTER_INTERFRAME", "mergeStrategy: MERGE_BASELINES",
                         "refine: LSD_REFINE_STD", "EdgeDetectionOperator: PREWITT"):
                self.assertIn(line, text)
            path = os.path.join(folder, "modes.yml")
            with open(path, "w") as f:
                f.write("%YAML:1.0\n---\nLSDAdvance:\n   stageOrder: FILTER_THEN_MERGE\n   mergeStrategy: 0\n")
            detector = api.createLSDAdvance()
            fs = cv.FileStorage(path, cv.FILE_STORAGE_READ)
            detector.read(fs.getNode("LSDAdvance"))
        self.assertEqual(detector.getStageOrder(), api.LSDAdvance_FILTER_THEN_MERGE)
        self.assertEqual(detector.getMergeStrategy(), api.LSDAdvance_MERGE_NONE)

    def test_read_warns_about_an_unknown_key_naming_the_closest(self):
        detector = api.createLSDAdvance()
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "typo.yml")
            with open(path, "w") as f:
                f.write("%YAML:1.0\n---\nLSDAdvance:\n   mergeTreshold: 0.9\n   endpointDistance: 4\n")
            fs = cv.FileStorage(path, cv.FILE_STORAGE_READ)
            with StderrOfProcess() as log:
                detector.read(fs.getNode("LSDAdvance"))
        self.assertIn("unknown key 'mergeTreshold' ignored; the closest known key is 'mergeThreshold'", log.text)
        self.assertEqual(detector.getEndpointDistance(), 4.0)
        self.assertEqual(detector.getMergeThreshold(), api.createLSDAdvance().getMergeThreshold())

    def test_write_into_a_cv2_filestorage_and_read_back(self):
        configured = api.createLSDAdvance()
        lsd = configured.getLSDParams()
        lsd.scale = 0.5
        configured.setLSDParams(lsd)
        fld = configured.getFLDParams()
        fld.doMerge = True
        configured.setFLDParams(fld)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "params.json")
            fs = cv.FileStorage(path, cv.FILE_STORAGE_WRITE)
            configured.write(fs, "detector")
            fs.release()
            loaded = api.createLSDAdvance()
            fs = cv.FileStorage(path, cv.FILE_STORAGE_READ)
            loaded.read(fs.getNode("detector"))
        self.assertEqual(loaded.getLSDParams().scale, 0.5)
        self.assertIs(loaded.getFLDParams().doMerge, True)

    def test_read_of_a_bad_value_raises_and_changes_nothing(self):
        detector = api.createLSDAdvance()
        before = detector.getLSDParams().scale
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "bad.yml")
            with open(path, "w") as f:
                f.write("%YAML:1.0\n---\nLSDAdvance:\n   lsd: { scale: 0.5 }\n   endpointDistance: -3\n")
            fs = cv.FileStorage(path, cv.FILE_STORAGE_READ)
            with self.assertRaisesRegex(cv.error, "endpointDistance"):
                detector.read(fs.getNode("LSDAdvance"))
        self.assertEqual(detector.getLSDParams().scale, before)

    # ----------------------------------------------------------------------------------------
    # Sequence, stage outputs, sources, drawing

    def test_sequence_alpha_follows_the_kept_counts_and_reset_restarts_it(self):
        detector = api.createLSDAdvance()
        detector.setLengthFilterMode(api.LSDAdvance_LENGTH_FILTER_INTERFRAME)
        frames = [random_segments(400, 1), random_segments(200, 2), random_segments(300, 3)]
        kept = []
        for segments in frames[:2]:
            detector.processSegments(segments)
            self.assertEqual(detector.getLastStats().alpha, 1.0)
            kept.append(detector.getLastStats().filteredSegments)
        detector.processSegments(frames[2])
        expected = interframe_alpha(kept[0], kept[1])
        self.assertNotEqual(expected, 1.0)
        self.assertAlmostEqual(detector.getLastStats().alpha, expected, delta=1e-12)
        detector.reset()
        detector.processSegments(frames[2])
        self.assertEqual(detector.getLastStats().alpha, 1.0)

    def test_getLastStageOutputs_final_stage_equals_detect(self):
        small = self.small_building()
        detector = api.createLSDAdvance()
        self.assertEqual(detector.getLastStageOutputs(), (None, None, None, None))
        lines = detector.detect(small)
        base, filtered, labels, merged = detector.getLastStageOutputs()
        stats = detector.getLastStats()
        self.assertEqual(base.shape, (stats.baseSegments, 1, 4))
        self.assertEqual(base.dtype, np.float32)
        self.assertEqual(labels.shape, (stats.baseSegments, 1))
        self.assertEqual(labels.dtype, np.int32)
        self.assertEqual(merged.shape, (stats.mergedSegments, 1, 4))
        # MERGE_THEN_FILTER (default): the length filter runs last, then the clipping to the image.
        unstaged = api.createLSDAdvance()
        unstaged.setLengthFilterMode(api.LSDAdvance_LENGTH_FILTER_NONE)
        unstaged.setMergeStrategy(api.LSDAdvance_MERGE_NONE)
        # The same set of lines: detect() orders them strongest first, processSegments() longest first.
        again = unstaged.processSegments(filtered, None, (small.shape[1], small.shape[0]))
        self.assertEqual(as_set(again), as_set(lines))

    def test_lines_lie_inside_the_image(self):
        building = self.building()
        lines = api.createLSDAdvance().detect(building).reshape(-1, 4)
        height, width = building.shape
        self.assertGreaterEqual(lines[:, 0::2].min(), -0.5)
        self.assertLessEqual(lines[:, 0::2].max(), width - 0.5)
        self.assertGreaterEqual(lines[:, 1::2].min(), -0.5)
        self.assertLessEqual(lines[:, 1::2].max(), height - 0.5)

    def test_getLastSources_gives_the_base_segments_of_each_line(self):
        detector = api.createLSDAdvance()
        lines = detector.detect(self.small_building())
        base = detector.getLastStageOutputs()[0]
        sources = detector.getLastSources()
        self.assertEqual(len(sources), len(lines))
        indices = np.concatenate([s.ravel() for s in sources])
        self.assertEqual(indices.dtype, np.int32)
        self.assertEqual(len(np.unique(indices)), len(indices))
        self.assertGreaterEqual(indices.min(), 0)
        self.assertLess(indices.max(), len(base))
        self.assertTrue(any(len(s) > 1 for s in sources))

    def test_drawSegments_draws_as_LineSegmentDetector_does(self):
        small = self.small_building()
        detector = api.createLSDAdvance()
        lines = detector.detect(small)
        expected = cv.createLineSegmentDetector().drawSegments(small.copy(), lines)
        drawn = detector.drawSegments(small.copy(), lines)
        self.assertEqual(drawn.shape, small.shape + (3,))
        self.assertTrue(np.array_equal(drawn, expected))
        with self.assertRaisesRegex(cv.error, "CV_8UC1 or CV_8UC3"):
            detector.drawSegments(np.zeros((8, 8), np.float32), lines)

    def test_the_default_detector_is_stateless(self):
        building = self.building()
        detector = api.createLSDAdvance()
        fresh = detector.detect(building)
        for name in ("graf1.png", "graf3.png"):
            detector.detect(self.image(name))
        self.assertTrue(np.array_equal(detector.detect(building), fresh))

    # ----------------------------------------------------------------------------------------
    # The selection: order, minimum length, budget; the front-end preset

    def test_detect_returns_the_lines_strongest_first_and_getLastResponses_their_responses(self):
        small = self.small_building()
        detector = api.createLSDAdvance()
        self.assertIsNone(detector.getLastResponses())
        lines = detector.detect(small)
        responses = detector.getLastResponses()
        self.assertEqual(responses.shape, (len(lines), 1))
        self.assertEqual(responses.dtype, np.float32)
        self.assertTrue(np.array_equal(responses, api.computeLineResponses(small, lines)))
        self.assertTrue(np.all(np.diff(responses.ravel()) <= 0))
        segments = random_segments(30, 5)
        detector.processSegments(segments)
        self.assertIsNone(detector.getLastResponses())

    def test_minimum_length_and_budget_select_from_the_ordered_lines(self):
        small = self.small_building()
        every = api.createLSDAdvance().detect(small).reshape(-1, 4)
        length = np.hypot(every[:, 2] - every[:, 0], every[:, 3] - every[:, 1])
        detector = api.createLSDAdvance()
        detector.setMinLineLength(30.0)
        self.assertTrue(np.array_equal(detector.detect(small).reshape(-1, 4), every[length >= 30]))
        detector.setMinLineLength(0.0)
        detector.setMinLineLengthRatio(0.125)
        side = min(small.shape)
        self.assertTrue(np.array_equal(detector.detect(small).reshape(-1, 4), every[length >= 0.125 * side]))
        detector.setMinLineLengthRatio(0.0)
        detector.setMaxLines(25)
        self.assertTrue(np.array_equal(detector.detect(small).reshape(-1, 4), every[:25]))
        self.assertEqual(detector.getLastStats().outputSegments, 25)
        with self.assertRaisesRegex(cv.error, "maxLines"):
            detector.setMaxLines(-1)
        self.assertEqual(detector.getMaxLines(), 25)

    def test_processSegments_returns_the_lines_longest_first(self):
        detector = api.createLSDAdvance()
        detector.setLengthFilterMode(api.LSDAdvance_LENGTH_FILTER_NONE)
        detector.setMergeStrategy(api.LSDAdvance_MERGE_NONE)
        lines = detector.processSegments(random_segments(40, 3)).reshape(-1, 4)
        length = np.hypot(lines[:, 2] - lines[:, 0], lines[:, 3] - lines[:, 1])
        self.assertTrue(np.all(np.diff(length) <= 1e-4))

    def test_front_end_preset_is_stateless_with_60_lines_across_directions(self):
        building = self.building()
        detector = api.createLSDAdvance(api.LSDAdvance_PRESET_FRONT_END)
        self.assertEqual(detector.getMaxLines(), 60)
        self.assertEqual(detector.getLineOrder(), api.LSDAdvance_LINE_ORDER_ACROSS_DIRECTIONS)
        self.assertEqual(detector.getDirectionBins(), 4)
        self.assertEqual(detector.getGridCells(), 2)
        lines = detector.detect(building)
        self.assertEqual(len(lines), 60)
        self.assertTrue(np.array_equal(detector.detect(building), lines))
        self.assertEqual(detector.getLastStats().frameInSequence, 1)

    def lines_across_bins(self, cells):
        """The small building's lines in LINE_ORDER_ACROSS_DIRECTIONS with 4 bins of direction in each of
        cells x cells cells, checked to be the defaults' set with one line of each bin present first;
        the detector, the image, the lines and the bins present."""
        small = self.small_building()
        detector = api.createLSDAdvance()
        detector.setLineOrder(api.LSDAdvance_LINE_ORDER_ACROSS_DIRECTIONS)
        detector.setDirectionBins(4)
        detector.setGridCells(cells)
        every = detector.detect(small).reshape(-1, 4)
        self.assertEqual(as_set(every), as_set(api.createLSDAdvance().detect(small)))
        height, width = small.shape[:2]
        column = np.minimum((every[:, 0] + every[:, 2]) * 0.5 * cells // width, cells - 1)
        row = np.minimum((every[:, 1] + every[:, 3]) * 0.5 * cells // height, cells - 1)
        angle = (np.degrees(np.arctan2(every[:, 3] - every[:, 1], every[:, 2] - every[:, 0])) + 22.5) % 180.0
        direction = np.minimum((angle / 45.0).astype(int), 3)  # four bins centred on 0, 45, 90 and 135 degrees
        bins = ((row * cells + column) * 4 + direction).astype(int)
        present = sorted(set(bins.tolist()))
        self.assertEqual(sorted(bins[:len(present)].tolist()), present)  # one of each bin first
        return detector, small, every, present

    def test_across_directions_takes_each_bins_strongest_first_and_a_budget_is_a_prefix(self):
        detector, small, every, _ = self.lines_across_bins(1)
        detector.setMaxLines(10)
        self.assertTrue(np.array_equal(detector.detect(small).reshape(-1, 4), every[:10]))
        with self.assertRaisesRegex(cv.error, "directionBins"):
            detector.setDirectionBins(1)
        self.assertEqual(detector.getDirectionBins(), 4)

    def test_grid_cells_give_each_quarter_of_the_image_its_strongest_lines_of_each_direction(self):
        detector, _, _, present = self.lines_across_bins(2)
        self.assertGreater(len(present), 8)  # bins of several cells
        with self.assertRaisesRegex(cv.error, "gridCells"):
            detector.setGridCells(0)
        self.assertEqual(detector.getGridCells(), 2)

    # ----------------------------------------------------------------------------------------
    # Pose evaluation (line_evaluation): the solver and the geometry behind doc/pose.md

    def synthetic_scene(self, lines):
        """3D segments 4-30 m in front of a camera, their images after a known motion."""
        K = np.array([[700.0, 0, 600], [0, 700, 180], [0, 0, 1]])
        R, _ = cv.Rodrigues(np.radians(np.array([0.5, -1.0, 0.2])))
        t = np.array([[0.1], [-0.05], [-1.2]])
        rng = np.random.default_rng(4)
        z = rng.uniform(6, 30, (lines, 2))
        pixels = np.stack([rng.uniform(100, 1100, (lines, 2)), rng.uniform(40, 320, (lines, 2))], axis=2)
        ends = np.concatenate([(pixels - K[:2, 2]) / 700.0 * z[..., None], z[..., None]], axis=2)
        moved = ends.reshape(-1, 3) @ R.T + t.ravel()
        projected = moved @ K.T
        segments2d = (projected[:, :2] / projected[:, 2:]).reshape(lines, 4).astype(np.float32)
        return K, R, t, ends.reshape(lines, 6).astype(np.float32), segments2d

    def test_estimatePose_recovers_the_motion_from_noise_free_lines(self):
        K, R, t, segments3d, segments2d = self.synthetic_scene(15)
        estimate = evaluation.estimatePose(K, segments3d, segments2d)
        self.assertTrue(estimate.solved)
        self.assertEqual(estimate.lineInliers, 15)
        self.assertEqual(list(estimate.lineInlierMask), [1] * 15)
        rotation, translation = evaluation.poseError(estimate.R, estimate.t, R, t)
        self.assertLess(rotation, 1e-3)
        self.assertLess(translation, 1e-3)
        params = evaluation.PoseEstimationParams()
        params.minInliers = 16
        self.assertFalse(evaluation.estimatePose(K, segments3d, segments2d, params=params).solved)
        with self.assertRaisesRegex(cv.error, "counts"):
            evaluation.estimatePose(K, segments3d, segments2d[:-1])

    def test_triangulateSegments_lifts_a_stereo_match_and_drops_a_horizontal_one(self):
        K = np.array([[700.0, 0, 600, 0], [0, 700, 180, 0], [0, 0, 1, 0]])
        P1 = K.copy()
        P1[0, 3] = -0.54 * 700
        A, B = np.array([1.0, -1, 10]), np.array([1.5, 1, 12])
        def image(P, X, Y):
            a, b = P @ np.append(X, 1), P @ np.append(Y, 1)
            return np.float32([a[0] / a[2], a[1] / a[2], b[0] / b[2], b[1] / b[2]])
        horizontal = (np.array([-1.0, 0.2, 8]), np.array([1.0, 0.2, 8]))
        left = np.array([image(K, A, B), image(K, *horizontal)])
        right = np.array([image(P1, A, B), image(P1, *horizontal)])
        matches = [cv.DMatch(0, 0, 0), cv.DMatch(1, 1, 0)]
        lifted, kept = evaluation.triangulateSegments(K, P1, left.reshape(-1, 1, 4), right.reshape(-1, 1, 4), matches)
        self.assertEqual(list(kept), [0])
        self.assertTrue(np.allclose(lifted.reshape(-1, 6)[0], np.concatenate([A, B]), atol=1e-3))
        F = evaluation.fundamentalFromProjections(K, P1)
        self.assertAlmostEqual(float(np.append(right[0, :2], 1) @ F @ np.append(left[0, :2], 1)), 0.0, places=6)

    def test_multi_view_and_stereo_loaders_read_the_shared_scenes(self):
        folder = os.environ.get("LSD_ADVANCE_DATA_DIR", "")
        scene = os.path.join(folder, "strecha_fountain_p11")
        kitti = os.path.join(folder, "kitti_seq1")
        if not os.path.isdir(scene) or not os.path.isdir(kitti):
            if os.environ.get("CI") == "true":
                self.fail("CI=true and the evaluation data is not in LSD_ADVANCE_DATA_DIR (doc/data.md)")
            self.skipTest("LSD_ADVANCE_DATA_DIR does not hold strecha_fountain_p11 and kitti_seq1 (doc/data.md)")
        views = evaluation.loadMultiView(scene)
        self.assertEqual(len(views.imagePaths), 11)
        self.assertEqual(views.poses[0].shape, (3, 4))
        self.assertEqual(tuple(np.ravel(views.imageSizes[0])), (3072, 2048))
        sequence = evaluation.loadSequence(kitti)
        self.assertEqual(len(sequence.rightImagePaths), len(sequence.imagePaths))

    # ----------------------------------------------------------------------------------------
    # KeyLines and LBD (cv2.line_descriptor)

    def test_keepStrongestKeyLines_keeps_the_budget_strongest_first_with_contiguous_class_ids(self):
        small = self.small_building()
        keylines = cv.line_descriptor.LSDDetector_createLSDDetector().detect(small, 1, 1)
        self.assertGreater(len(keylines), 40)
        kept = api.keepStrongestKeyLines(keylines, 40)
        self.assertEqual([k.class_id for k in kept], list(range(40)))
        self.assertEqual([k.response for k in kept], sorted((k.response for k in keylines), reverse=True)[:40])
        detector = api.createLSDAdvance()
        detector.setMaxLines(30)
        ours = detector.detectKeyLines(small)
        self.assertEqual([k.class_id for k in ours], list(range(30)))
        description = cv.line_descriptor.BinaryDescriptor_createBinaryDescriptor().compute(small, kept)[1]
        self.assertEqual(description.shape, (40, 32))

    def test_linesToKeyLines_fills_the_documented_fields(self):
        building = self.building()
        lines = api.createLSDAdvance().detect(building)
        height, width = building.shape
        keylines = api.linesToKeyLines(lines, (width, height))
        self.assertEqual(len(keylines), len(lines))
        canvas = np.zeros_like(building)
        for i, (k, line) in enumerate(zip(keylines, lines.reshape(-1, 4).astype(np.float64))):
            self.assertIsInstance(k, cv.line_descriptor.KeyLine)
            # below 0 -> 0; at or beyond the side -> side - 1; [side - 1, side) kept
            x1, x2 = (0.0 if v < 0 else (width - 1.0 if v >= width else v) for v in line[0::2])
            y1, y2 = (0.0 if v < 0 else (height - 1.0 if v >= height else v) for v in line[1::2])
            np.testing.assert_allclose((k.startPointX, k.startPointY, k.endPointX, k.endPointY), (x1, y1, x2, y2),
                                       rtol=0, atol=1e-4)
            self.assertEqual((k.sPointInOctaveX, k.sPointInOctaveY, k.ePointInOctaveX, k.ePointInOctaveY),
                             (k.startPointX, k.startPointY, k.endPointX, k.endPointY))
            np.testing.assert_allclose(k.pt, ((x1 + x2) / 2, (y1 + y2) / 2), rtol=0, atol=1e-4)
            np.testing.assert_allclose(k.lineLength, math.hypot(x2 - x1, y2 - y1), rtol=1e-5)
            np.testing.assert_allclose(k.angle, math.atan2(y2 - y1, x2 - x1), rtol=0, atol=1e-5)
            np.testing.assert_allclose(k.size, (x2 - x1) * (y2 - y1), rtol=1e-4, atol=1e-3)
            np.testing.assert_allclose(k.response, k.lineLength / max(width, height), rtol=1e-6)
            # the pixels of the 8-connected digital line between the rounded endpoints, as cv2.line draws it
            canvas[:] = 0
            cv.line(canvas, (round(x1), round(y1)), (round(x2), round(y2)), 255, 1, cv.LINE_8)
            self.assertEqual(k.numOfPixels, np.count_nonzero(canvas))
            self.assertEqual((k.octave, k.class_id), (0, i))

    def test_detectKeyLines_equals_linesToKeyLines_of_detect_with_the_responses(self):
        small = self.small_building()
        detector = api.createLSDAdvance()
        lines = detector.detect(small)
        detector.reset()
        keylines = detector.detectKeyLines(small)
        expected = api.linesToKeyLines(lines, (small.shape[1], small.shape[0]))
        self.assertEqual([(k.startPointX, k.startPointY, k.endPointX, k.endPointY, k.numOfPixels) for k in keylines],
                         [(k.startPointX, k.startPointY, k.endPointX, k.endPointY, k.numOfPixels) for k in expected])
        # response: computeLineResponses', not the length of linesToKeyLines
        self.assertEqual([k.response for k in keylines], list(api.computeLineResponses(small, lines).ravel()))

    def test_keyLinesToLines_inverts_linesToKeyLines_inside_the_image(self):
        lines = np.array([[[1.5, 2.25, 30.0, 40.5]], [[60.0, 10.0, 5.0, 70.75]]], np.float32)
        self.assertTrue(np.array_equal(api.keyLinesToLines(api.linesToKeyLines(lines, (100, 100))), lines))
        # KeyLines of OpenCV's own LSDDetector convert too.
        keylines = cv.line_descriptor.LSDDetector_createLSDDetector().detect(self.small_building(), 1, 1)
        back = api.keyLinesToLines(keylines).reshape(-1, 4)
        self.assertEqual(back.tolist(), [[k.startPointX, k.startPointY, k.endPointX, k.endPointY] for k in keylines])

    def test_computeLBD_gives_the_descriptors_of_BinaryDescriptor_compute(self):
        building = self.building()
        oracle = cv.line_descriptor.BinaryDescriptor_createBinaryDescriptor()
        for preset in (api.LSDAdvance_PRESET_MOST_ACCURATE, api.LSDAdvance_PRESET_FRONT_END):
            keylines = api.createLSDAdvance(preset).detectKeyLines(building)
            descriptors = api.computeLBD(building, keylines)
            self.assertEqual(descriptors.shape, (len(keylines), 32))
            self.assertEqual(descriptors.dtype, np.uint8)
            self.assertTrue(np.array_equal(descriptors, oracle.compute(building, keylines)[1]))
        # LSDDetector's KeyLines too, and the colour image as BinaryDescriptor converts it.
        colour = self.image("building.jpg", cv.IMREAD_COLOR)
        keylines = [k for k in cv.line_descriptor.LSDDetector_createLSDDetector().detect(building, 1, 1)
                    if k.numOfPixels > 0]
        self.assertTrue(np.array_equal(api.computeLBD(colour, keylines), oracle.compute(colour, keylines)[1]))
        self.assertIsNone(api.computeLBD(building, []))  # no KeyLine: an empty array, None as cv2 gives it

    def test_detectAndCompute_is_detectKeyLines_then_computeLBD(self):
        small = self.small_building()
        keylines, descriptors = api.createLSDAdvance().detectAndCompute(small)
        expected = api.createLSDAdvance().detectKeyLines(small)
        self.assertEqual([(k.startPointX, k.endPointY) for k in keylines], [(k.startPointX, k.endPointY) for k in expected])
        self.assertTrue(np.array_equal(descriptors, api.computeLBD(small, expected)))

    def test_computeLBD_rejects_keylines_it_cannot_describe(self):
        small = self.small_building()
        keylines = api.createLSDAdvance().detectKeyLines(small)
        keylines[2].octave = 1
        with self.assertRaises(cv.error) as info:
            api.computeLBD(small, keylines)
        self.assertIn("KeyLine 2", str(info.exception))
        self.assertIn("octave 0", str(info.exception))
        keylines[2].octave = 0
        keylines[3].endPointX = keylines[3].ePointInOctaveX = small.shape[1] + 5.0
        with self.assertRaises(cv.error) as info:
            api.computeLBD(small, keylines)
        self.assertIn("outside", str(info.exception))
        with self.assertRaises(cv.error):
            api.computeLBD(np.zeros((20, 20), np.float32), keylines[:2])

    def test_keylines_go_into_lbd_and_match_graf1_to_graf3(self):
        grays = [self.image("graf1.png"), self.image("graf3.png")]
        H = evaluation.readHomography(os.path.join(DATA, "H1to3p.xml"))
        detector = api.createLSDAdvance()
        descriptor = cv.line_descriptor.BinaryDescriptor_createBinaryDescriptor()
        lines, descriptions = [], []
        for gray in grays:
            detector.reset()
            keylines = detector.detectKeyLines(gray)
            kept, description = descriptor.compute(gray, keylines)
            self.assertEqual(description.shape, (len(kept), 32))
            self.assertEqual(description.dtype, np.uint8)
            lines.append(api.keyLinesToLines(kept))
            descriptions.append(description)
        matcher = cv.line_descriptor.BinaryDescriptorMatcher()
        matches = matcher.match(descriptions[0], descriptions[1])
        def correct(pairs):
            return evaluation.evaluateHomographyMatches(lines[0], lines[1], pairs, H, grays[0].shape[::-1],
                                                        grays[1].shape[::-1]).correct
        # The same number of pairs drawn at random: what matching without the descriptors finds.
        others = np.random.default_rng(1).permutation([m.trainIdx for m in matches])
        chance = [cv.DMatch(m.queryIdx, int(t), m.distance) for m, t in zip(matches, others)]
        self.assertGreater(len(matches), 100)
        self.assertGreater(correct(matches), 10 * max(correct(chance), 1))


if __name__ == "__main__":
    NewOpenCVTests.bootstrap()
