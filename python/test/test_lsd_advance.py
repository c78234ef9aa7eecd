# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of the Python bindings, run against either
 * the standalone module (default): `import lsd_advance` (PYTHONPATH=<build>/python), or
 * the in-tree bindings: LSD_ADVANCE_PY_BACKEND=cv2 (cv2.ximgproc of an OpenCV built with the module).
Tests of what only the standalone module has (KeyLine helpers) are skipped with the cv2 backend.

Environment: OPENCV_SAMPLES_DATA_PATH (default Debian's opencv-doc data folder);
LSD_ADVANCE_DETECT_SAMPLE / LSD_ADVANCE_LBD_SAMPLE: the built C++ samples lsd_advance_detect and
lsd_advance_lbd_matching, whose output the Python results must equal. Missing data or samples
skip the tests that need them, except with CI=true, where they fail.
"""

import math
import os
import re
import subprocess
import sys
import tempfile

import cv2
import numpy as np
import pytest

BACKEND = os.environ.get("LSD_ADVANCE_PY_BACKEND", "standalone")
if BACKEND == "cv2":
    api = cv2.ximgproc
elif BACKEND == "standalone":
    import lsd_advance as api
else:
    raise RuntimeError("LSD_ADVANCE_PY_BACKEND must be 'standalone' or 'cv2', not %r" % BACKEND)
evaluation = api.line_evaluation

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
HEADER = os.path.join(REPO, "include", "opencv2", "lsd_advance", "lsd_advance.hpp")
DATA = os.environ.get("OPENCV_SAMPLES_DATA_PATH", "/usr/share/doc/opencv-doc/examples/data")
CI = os.environ.get("CI") == "true"
# Keys of write() that are not parameters.
NOT_PARAMETERS = {"format"}

standalone_only = pytest.mark.skipif(BACKEND != "standalone", reason="the KeyLine helpers are standalone-only "
                                     "(linesToKeyLines is not CV_EXPORTS_W, so cv2 in-tree has no binding)")


def unavailable(what):
    if CI:
        pytest.fail(what + " (CI=true: required)")
    pytest.skip(what)


def data_path(name):
    path = os.path.join(DATA, name)
    if not os.path.isfile(path):
        unavailable("missing %s (install opencv-doc or set OPENCV_SAMPLES_DATA_PATH)" % path)
    return path


def sample(variable):
    path = os.environ.get(variable, "")
    if not os.path.isfile(path):
        unavailable("%s is not set to the built C++ sample" % variable)
    return path


def read_gray(name):
    return cv2.imread(data_path(name), cv2.IMREAD_GRAYSCALE)


def as_lines(lines):
    """detect()'s result as an (N, 1, 4) array, N = 0 for None."""
    return np.zeros((0, 1, 4), np.float32) if lines is None else lines


def saved_text(detector):
    """What detector.save() writes."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "params.yml")
        detector.save(path)
        with open(path) as f:
            return f.read()


def saved_parameters(detector):
    """The names of LSDAdvance's own parameters detector.save() writes (the base detectors' are in maps)."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "params.yml")
        detector.save(path)
        fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
        node = fs.getNode(detector.getDefaultName())
        return [k for k in node.keys() if k not in NOT_PARAMETERS and not node.getNode(k).isMap()]


PARAMETERS = sorted(saved_parameters(api.createLSDAdvance()))
# The fields of the base detectors' structs, as the getters of the structs return them.
BASE_STRUCTS = {"LSDParams": api.LSDAdvance_BASE_LSD, "FLDParams": api.LSDAdvance_BASE_FLD,
                "EDLinesParams": api.LSDAdvance_BASE_EDLINES}


def fields(struct):
    return sorted(a for a in dir(struct) if not a.startswith("_"))


def getter(detector, name):
    return getattr(detector, "get" + name[0].upper() + name[1:])


def setter(detector, name):
    return getattr(detector, "set" + name[0].upper() + name[1:])


def other_values(detector, name):
    """Values other than the current one that the setter accepts, nearest first."""
    value = getter(detector, name)()
    if isinstance(value, bool):
        candidates = [not value]
    elif isinstance(value, int):
        candidates = [value + 1, value - 1, value * 2, value // 2, value + 2, 0, 1, 2, 3, 4, 10, 20, 40]
    else:
        candidates = [value * 0.5, value * 0.9, value * 1.1, value * 2, value + 1, value - 1, 0.3, 3.0]
    accepted = []
    for v in candidates:
        if v == value or v in accepted:
            continue
        probe = api.createLSDAdvance()
        try:
            setter(probe, name)(v)
        except cv2.error:
            continue
        accepted.append(v)
    return accepted


# Parameters that act only in another configuration: what to set first (on both detectors).
def set_up_for(detector, name):
    if name == "baselineRatio":
        detector.setMergeStrategy(api.LSDAdvance_MERGE_BASELINES)


@pytest.fixture(scope="module")
def building():
    return read_gray("building.jpg")


@pytest.fixture(scope="module")
def small_building(building):
    return cv2.resize(building, None, fx=0.5, fy=0.5, interpolation=cv2.INTER_AREA)


# --------------------------------------------------------------------------------------------
# detect

def test_detect_returns_n_by_1_by_4_float32(building):
    lines = api.createLSDAdvance().detect(building)
    assert isinstance(lines, np.ndarray)
    assert lines.dtype == np.float32
    assert lines.ndim == 3 and lines.shape[1:] == (1, 4) and lines.shape[0] > 0


def test_detect_returns_what_cv2_detectors_return_for_no_segment():
    blank = np.zeros((64, 64), np.uint8)
    expected = cv2.ximgproc.createFastLineDetector().detect(blank)
    lines = api.createLSDAdvance().detect(blank)
    assert type(lines) is type(expected)
    assert lines is None


def test_detect_equals_the_cpp_sample_output(building, tmp_path):
    program = sample("LSD_ADVANCE_DETECT_SAMPLE")
    subprocess.run([program, "--input=" + data_path("building.jpg"), "--output=" + str(tmp_path)], check=True,
                   stdout=subprocess.DEVNULL)
    expected = np.loadtxt(str(tmp_path / "building.txt"), ndmin=2)
    lines = as_lines(api.createLSDAdvance().detect(building)).reshape(-1, 4)
    assert lines.shape == expected.shape
    # The sample writes 3 decimals.
    np.testing.assert_allclose(lines, expected, rtol=0, atol=0.0005 + 1e-6)


def test_detect_equals_processSegments_of_opencv_lsd(building):
    detector = api.createLSDAdvance()
    detector.setBaseDetector(api.LSDAdvance_BASE_LSD)
    p = detector.getLSDParams()
    lsd = cv2.createLineSegmentDetector(p.refine, p.scale, p.sigmaScale, p.quant, p.angleTolerance, p.logEps,
                                        p.densityThreshold, p.numBins)
    base = lsd.detect(building)[0]
    lines = detector.detect(building)
    assert detector.getLastStats().baseSegments == len(base)
    size = (building.shape[1], building.shape[0])
    assert np.array_equal(detector.processSegments(base, None, size), lines)
    assert np.array_equal(detector.processSegments(base, imageSize=size), lines)


def test_computeLineResponses_is_length_times_squared_contrast_of_the_brighter_left():
    # A step of 150 gray levels under a 120 px segment pointing up (bright side on its left).
    step = np.full((200, 300), 50, np.uint8)
    step[:, :150] = 200
    up = np.array([[[149.5, 160, 149.5, 40]]], np.float32)
    responses = api.computeLineResponses(step, up)
    assert responses.shape == (1, 1) and responses.dtype == np.float32
    assert responses[0, 0] == pytest.approx(120 / 300 * (150 / 255) ** 2, rel=1e-5)
    assert api.computeLineResponses(step, up[:, :, [2, 3, 0, 1]])[0, 0] == 0
    with pytest.raises(cv2.error):
        api.computeLineResponses(np.zeros((0, 0), np.uint8), up)


def test_keepStrongSegments_is_off_by_default_and_on_in_the_sequence_preset(building):
    assert not api.createLSDAdvance().getKeepStrongSegments()
    sequence = api.createLSDAdvance(api.LSDAdvance_PRESET_SEQUENCE)
    assert sequence.getKeepStrongSegments()
    assert len(sequence.detect(building)) > len(api.createLSDAdvance().detect(building))
    assert sequence.getLastStats().minResponse > 0


def test_gray_bgr_and_bgra_input_agree(building):
    detector = api.createLSDAdvance()
    gray = detector.detect(building)
    bgr_image = cv2.cvtColor(building, cv2.COLOR_GRAY2BGR)
    detector.reset()
    bgr = detector.detect(bgr_image)
    detector.reset()
    bgra = detector.detect(cv2.cvtColor(bgr_image, cv2.COLOR_BGR2BGRA))
    assert np.array_equal(gray, bgr)
    assert np.array_equal(gray, bgra)


def test_non_contiguous_views_give_the_lines_of_a_contiguous_copy(small_building):
    detector = api.createLSDAdvance()
    expected = detector.detect(small_building)
    wide = np.zeros((small_building.shape[0], small_building.shape[1] * 2), np.uint8)
    wide[:, ::2] = small_building
    views = {
        "column stride 2": wide[:, ::2],
        "flipped twice": np.ascontiguousarray(small_building[::-1, ::-1])[::-1, ::-1],
        "Fortran order": np.asfortranarray(small_building),
        "channel of a BGR image": cv2.cvtColor(small_building, cv2.COLOR_GRAY2BGR)[:, :, 1],
    }
    for name, view in views.items():
        detector.reset()
        assert np.array_equal(detector.detect(view), expected), name


def test_output_array_that_fits_is_filled_in_place(small_building):
    detector = api.createLSDAdvance()
    expected = detector.detect(small_building)
    out = np.zeros_like(expected)
    detector.reset()
    returned = detector.detect(small_building, out)
    assert returned is out
    assert np.array_equal(out, expected)


def test_getLastStats_counts_the_last_call(small_building):
    detector = api.createLSDAdvance()
    lines = detector.detect(small_building)
    stats = detector.getLastStats()
    assert stats.outputSegments == len(lines)
    assert stats.baseSegments >= stats.mergedSegments >= stats.outputSegments
    assert stats.alpha == 1.0
    assert stats.minLength > 0


# --------------------------------------------------------------------------------------------
# Bad input: OpenCV's own messages, as cv2.error

@pytest.mark.parametrize("image, message", [
    (np.zeros((0, 0), np.uint8), "the input image is empty"),
    (np.zeros((32, 32), np.float64), "unsupported image type CV_64FC1"),
    (np.zeros((32, 32, 2), np.uint8), "unsupported image type CV_8UC2"),
    (None, "the input image is empty"),
], ids=["empty", "float64", "2-channel", "None"])
def test_bad_image_raises_cv2_error_with_opencv_message(image, message):
    with pytest.raises(cv2.error) as info:
        api.createLSDAdvance().detect(image)
    assert message in str(info.value)
    assert str(info.value).startswith("OpenCV(")
    assert message in info.value.err


def test_unsupported_numpy_dtype_raises():
    with pytest.raises((TypeError, cv2.error)) as info:
        api.createLSDAdvance().detect(np.zeros((8, 8), bool))
    assert "not supported" in str(info.value)


def test_non_finite_segments_raise_cv2_error():
    segments = np.array([[[0, 0, math.nan, 5]]], np.float32)
    with pytest.raises(cv2.error, match="finite"):
        api.createLSDAdvance().processSegments(segments)


def test_rejected_setter_raises_and_keeps_the_value():
    detector = api.createLSDAdvance()
    with pytest.raises(cv2.error) as info:
        detector.setMergeThreshold(math.nan)
    assert "mergeThreshold must be a finite number in [0, 1], got nan" in str(info.value)
    assert detector.getMergeThreshold() == 0.6


@pytest.mark.parametrize("name", [p for p in PARAMETERS if isinstance(getter(api.createLSDAdvance(), p)(), float)])
def test_real_setter_rejects_nan(name):
    detector = api.createLSDAdvance()
    before = getter(detector, name)()
    with pytest.raises(cv2.error) as info:
        setter(detector, name)(math.nan)
    assert name in str(info.value) and "nan" in str(info.value)
    assert getter(detector, name)() == before


# --------------------------------------------------------------------------------------------
# Parameters: every C++ getter/setter, every saved parameter

def header_methods():
    with open(HEADER) as f:
        return sorted(set(re.findall(r"CV_WRAP\s+virtual\s+[\w:<>]+\s+(\w+)\s*\(", f.read())))


def header_constants():
    """{cv2 name: value} of the enum constants of class LSDAdvance."""
    with open(HEADER) as f:
        text = f.read()
    body = text[text.index("class CV_EXPORTS_W LSDAdvance"):]
    constants = {}
    for enum in re.findall(r"\benum\s+\w+\s*\{(.*?)\}", body, re.S):
        enum = re.sub(r"/\*.*?\*/|//[^\n]*", "", enum, flags=re.S)  # comments name other enums' values
        constants.update(("LSDAdvance_" + n, int(v)) for n, v in re.findall(r"\b([A-Z][A-Z0-9_]+)\s*=\s*(\d+)", enum))
    return constants


def test_every_cpp_method_of_the_header_is_exposed():
    detector = api.createLSDAdvance()
    methods = header_methods()
    assert len(methods) > 40 and "drawSegments" in methods and "getLastSources" in methods
    missing = [m for m in methods if not hasattr(detector, m)]
    assert missing == []


def test_every_enum_constant_is_exposed_with_its_cpp_value():
    constants = header_constants()
    assert "LSDAdvance_LENGTH_FILTER_INTERFRAME" in constants and "LSDAdvance_PRESET_PAPER" in constants
    assert {n: getattr(api, n, None) for n in constants} == constants


def test_every_saved_parameter_has_a_getter_and_a_setter():
    detector = api.createLSDAdvance()
    assert PARAMETERS == fields(api.LSDAdvance.Params())
    for name in PARAMETERS:
        assert callable(getter(detector, name)), name
        assert callable(setter(detector, name)), name


def test_createLSDAdvance_takes_a_preset():
    fastest = api.createLSDAdvance(api.LSDAdvance_PRESET_FASTEST)
    assert fastest.getBaseDetector() == api.LSDAdvance_BASE_FAST_LSD and fastest.getLSDParams().scale == 0.8
    paper = api.createLSDAdvance(preset=api.LSDAdvance_PRESET_PAPER)
    assert paper.getLSDParams().refine == cv2.LSD_REFINE_STD and paper.getLSDParams().scale == 0.8
    assert paper.getMergeStrategy() == api.LSDAdvance_MERGE_BASELINES
    assert api.createLSDAdvance(api.LSDAdvance_PRESET_SEQUENCE).getLengthFilterMode() == \
        api.LSDAdvance_LENGTH_FILTER_COUNT_TRACKING
    assert api.createLSDAdvance().getLengthFilterMode() == api.LSDAdvance_LENGTH_FILTER_ADAPTIVE
    with pytest.raises(cv2.error, match="PRESET_MOST_ACCURATE"):
        api.createLSDAdvance(7)


def header_params_defaults():
    """{struct: {field: documented default}} of the parameter structs of the header."""
    with open(HEADER) as f:
        text = f.read()
    defaults = {}
    for struct, body in re.findall(r"\n    struct CV_EXPORTS_W_SIMPLE (\w+)\s*\{(.*?)\n    \};", text, re.S):
        defaults[struct] = dict(re.findall(r"CV_PROP_RW \w+ (\w+);\s*//!<.*Default ([\w.]+)\.", body))
    return defaults


def documented(value):
    """A default as the header writes it: a number, true/false, or an enum constant's name."""
    if value in ("true", "false"):
        return value == "true"
    if re.match(r"^-?[0-9.]+$", value):
        return float(value)
    return getattr(api, "LSDAdvance_" + value, None) if hasattr(api, "LSDAdvance_" + value) else getattr(cv2, value)


def test_params_structs_have_the_documented_defaults():
    defaults = header_params_defaults()
    structs = {"Params": api.LSDAdvance.Params(), "LSDParams": api.LSDAdvance.LSDParams(),
               "FLDParams": api.LSDAdvance.FLDParams()}
    assert sorted(defaults) == sorted(structs)
    for name, struct in structs.items():
        assert sorted(defaults[name]) == fields(struct), name
        for field, value in defaults[name].items():
            assert getattr(struct, field) == documented(value), (name, field)
    detector = api.createLSDAdvance()
    for name in PARAMETERS:
        assert getter(detector, name)() == getattr(structs["Params"], name), name


def test_params_round_trip_and_a_bad_field_changes_nothing():
    detector = api.createLSDAdvance()
    params = detector.getParams()
    params.mergeThreshold = 0.75
    params.lengthFilterMode = api.LSDAdvance_LENGTH_FILTER_NONE
    detector.setParams(params)
    assert detector.getMergeThreshold() == 0.75
    assert detector.getLengthFilterMode() == api.LSDAdvance_LENGTH_FILTER_NONE
    params.endpointDistance = 3.0
    params.proximityRatio = -1.0
    with pytest.raises(cv2.error, match="proximityRatio"):
        detector.setParams(params)
    assert detector.getEndpointDistance() == 10.0


@pytest.mark.parametrize("struct", sorted(BASE_STRUCTS))
def test_base_struct_round_trips_and_a_bad_field_changes_nothing(struct):
    detector = api.createLSDAdvance()
    get, set_ = getattr(detector, "get" + struct), getattr(detector, "set" + struct)
    params = get()
    for name in fields(params):
        value = getattr(params, name)
        if isinstance(value, bool):
            setattr(params, name, not value)
        elif isinstance(value, float):
            setattr(params, name, value * 0.9)
        elif name == "seedAlignedNeighbours":  # 0, 1 or 2
            setattr(params, name, value - 1)
        elif name not in ("refine", "EdgeDetectionOperator", "cannyApertureSize"):
            setattr(params, name, value + 2 if value > 0 else 20)
    set_(params)
    got = get()
    assert {n: getattr(got, n) for n in fields(got)} == pytest.approx({n: getattr(params, n) for n in fields(params)})
    bad = get()
    name = [n for n in fields(bad) if isinstance(getattr(bad, n), float)][0]
    setattr(bad, name, -5.0)
    with pytest.raises(cv2.error, match=name):
        set_(bad)
    assert {n: getattr(get(), n) for n in fields(got)} == {n: getattr(got, n) for n in fields(got)}


@pytest.mark.parametrize("name", PARAMETERS)
def test_setter_round_trips(name):
    detector = api.createLSDAdvance()
    values = other_values(detector, name)
    assert values, "no other valid value found for " + name
    for value in values[:3]:
        setter(detector, name)(value)
        got = getter(detector, name)()
        assert got == value and type(got) is type(value)


@pytest.mark.parametrize("name", PARAMETERS)
def test_setter_changes_detect_output(name, small_building):
    reference = api.createLSDAdvance()
    set_up_for(reference, name)
    expected = as_lines(reference.detect(small_building))
    for value in other_values(reference, name):
        changed = api.createLSDAdvance()
        set_up_for(changed, name)
        setter(changed, name)(value)
        lines = as_lines(changed.detect(small_building))
        if lines.shape != expected.shape or not np.array_equal(lines, expected):
            return
    pytest.fail("no value of %s changes detect()'s output" % name)


def test_save_and_read_round_trip_every_parameter(tmp_path):
    configured = api.createLSDAdvance()
    for name in PARAMETERS:
        setter(configured, name)(other_values(configured, name)[0])
    lsd = configured.getLSDParams()
    lsd.quant = 3.0
    configured.setLSDParams(lsd)
    path = str(tmp_path / "params.yml")
    configured.save(path)
    loaded = api.createLSDAdvance()
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
    loaded.read(fs.getNode(loaded.getDefaultName()))
    for name in PARAMETERS:
        assert getter(loaded, name)() == getter(configured, name)(), name
    assert loaded.getLSDParams().quant == 3.0


def test_saved_modes_are_names_and_read_takes_names_or_numbers(tmp_path):
    text = saved_text(api.createLSDAdvance(api.LSDAdvance_PRESET_PAPER))
    for line in ("lengthFilterMode: LENGTH_FILTER_INTERFRAME", "mergeStrategy: MERGE_BASELINES",
                 "refine: LSD_REFINE_STD", "EdgeDetectionOperator: PREWITT"):
        assert line in text
    path = str(tmp_path / "modes.yml")
    with open(path, "w") as f:
        f.write("%YAML:1.0\n---\nLSDAdvance:\n   stageOrder: FILTER_THEN_MERGE\n   mergeStrategy: 0\n")
    detector = api.createLSDAdvance()
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
    detector.read(fs.getNode("LSDAdvance"))
    assert detector.getStageOrder() == api.LSDAdvance_FILTER_THEN_MERGE
    assert detector.getMergeStrategy() == api.LSDAdvance_MERGE_NONE


def test_read_warns_about_an_unknown_key_naming_the_closest(tmp_path, capfd):
    path = str(tmp_path / "typo.yml")
    with open(path, "w") as f:
        f.write("%YAML:1.0\n---\nLSDAdvance:\n   mergeTreshold: 0.9\n   endpointDistance: 4\n")
    detector = api.createLSDAdvance()
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
    capfd.readouterr()
    detector.read(fs.getNode("LSDAdvance"))
    err = capfd.readouterr().err
    assert "unknown key 'mergeTreshold' ignored; the closest known key is 'mergeThreshold'" in err
    assert detector.getEndpointDistance() == 4.0 and detector.getMergeThreshold() == 0.6


def test_write_into_cv2_filestorage_and_read_back(tmp_path):
    configured = api.createLSDAdvance()
    lsd = configured.getLSDParams()
    lsd.scale = 0.5
    configured.setLSDParams(lsd)
    fld = configured.getFLDParams()
    fld.doMerge = True
    configured.setFLDParams(fld)
    path = str(tmp_path / "params.json")
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_WRITE)
    configured.write(fs, "detector")
    fs.release()
    loaded = api.createLSDAdvance()
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)  # alive while its nodes are used
    loaded.read(fs.getNode("detector"))
    assert loaded.getLSDParams().scale == 0.5
    assert loaded.getFLDParams().doMerge is True


def test_read_of_a_bad_value_raises_and_changes_nothing(tmp_path):
    path = str(tmp_path / "bad.yml")
    with open(path, "w") as f:
        f.write("%YAML:1.0\n---\nLSDAdvance:\n   lsd: { scale: 0.5 }\n   endpointDistance: -3\n")
    detector = api.createLSDAdvance()
    with pytest.raises(cv2.error, match="endpointDistance"):
        fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
        detector.read(fs.getNode("LSDAdvance"))
    assert detector.getLSDParams().scale == 1.0


# --------------------------------------------------------------------------------------------
# Sequence: the inter-frame factor alpha and reset()

def interframe_alpha(kept_before_last, kept_last):
    """The documented LENGTH_FILTER_INTERFRAME rule."""
    r = (kept_last - kept_before_last) / kept_before_last if kept_before_last else 0.0
    if r < -0.1:
        return 1 - 0.2 * (1 + r)
    if r > 0.1:
        return min(1 + 0.1 * (r - 0.1), 1.2)
    return 1.0


def random_segments(count, seed):
    rng = np.random.default_rng(seed)
    start = rng.uniform(0, 500, (count, 2))
    angle = rng.uniform(0, math.pi, count)
    length = rng.uniform(2, 80, count)
    end = start + np.stack([np.cos(angle), np.sin(angle)], 1) * length[:, None]
    return np.concatenate([start, end], 1).astype(np.float32).reshape(-1, 1, 4)


def test_sequence_alpha_follows_the_kept_counts_and_reset_restarts_it():
    detector = api.createLSDAdvance()
    detector.setLengthFilterMode(api.LSDAdvance_LENGTH_FILTER_INTERFRAME)
    frames = [random_segments(400, 1), random_segments(200, 2), random_segments(300, 3)]
    kept = []
    for segments in frames[:2]:
        detector.processSegments(segments)
        assert detector.getLastStats().alpha == 1.0
        kept.append(detector.getLastStats().filteredSegments)
    detector.processSegments(frames[2])
    expected = interframe_alpha(kept[0], kept[1])
    assert expected != 1.0
    assert detector.getLastStats().alpha == pytest.approx(expected, abs=1e-12)
    detector.reset()
    detector.processSegments(frames[2])
    assert detector.getLastStats().alpha == 1.0


@pytest.mark.skipif(not hasattr(api.createLSDAdvance(), "getLastStageOutputs"), reason="no getLastStageOutputs")
def test_getLastStageOutputs_final_stage_equals_detect(small_building):
    detector = api.createLSDAdvance()
    assert detector.getLastStageOutputs() == (None, None, None, None)
    lines = detector.detect(small_building)
    base, filtered, labels, merged = detector.getLastStageOutputs()
    stats = detector.getLastStats()
    assert base.shape == (stats.baseSegments, 1, 4) and base.dtype == np.float32
    assert labels.shape == (stats.baseSegments, 1) and labels.dtype == np.int32
    assert merged.shape == (stats.mergedSegments, 1, 4)
    # MERGE_THEN_FILTER (default): the length filter runs last, then the clipping to the image.
    size = (small_building.shape[1], small_building.shape[0])
    unstaged = api.createLSDAdvance()
    unstaged.setLengthFilterMode(api.LSDAdvance_LENGTH_FILTER_NONE)
    unstaged.setMergeStrategy(api.LSDAdvance_MERGE_NONE)
    assert np.array_equal(unstaged.processSegments(filtered, None, size), lines)


def test_lines_lie_inside_the_image(building):
    lines = api.createLSDAdvance().detect(building).reshape(-1, 4)
    height, width = building.shape
    assert lines[:, 0::2].min() >= -0.5 and lines[:, 0::2].max() <= width - 0.5
    assert lines[:, 1::2].min() >= -0.5 and lines[:, 1::2].max() <= height - 0.5


def test_getLastSources_gives_the_base_segments_of_each_line(small_building):
    detector = api.createLSDAdvance()
    lines = detector.detect(small_building)
    base = detector.getLastStageOutputs()[0]
    sources = detector.getLastSources()
    assert len(sources) == len(lines)
    indices = np.concatenate([s.ravel() for s in sources])
    assert indices.dtype == np.int32 and len(np.unique(indices)) == len(indices)
    assert indices.min() >= 0 and indices.max() < len(base)
    assert any(len(s) > 1 for s in sources)


def test_drawSegments_draws_as_LineSegmentDetector_does(small_building):
    detector = api.createLSDAdvance()
    lines = detector.detect(small_building)
    expected = cv2.createLineSegmentDetector().drawSegments(small_building.copy(), lines)
    drawn = detector.drawSegments(small_building.copy(), lines)
    assert drawn.shape == small_building.shape + (3,)
    assert np.array_equal(drawn, expected)
    with pytest.raises(cv2.error, match="CV_8UC1 or CV_8UC3"):
        detector.drawSegments(np.zeros((8, 8), np.float32), lines)


def test_the_default_detector_is_stateless(building):
    detector = api.createLSDAdvance()
    fresh = detector.detect(building)
    for name in ("graf1.png", "graf3.png"):
        detector.detect(read_gray(name))
    assert np.array_equal(detector.detect(building), fresh)


# --------------------------------------------------------------------------------------------
# KeyLines and LBD matching (cv2.line_descriptor)

@standalone_only
def test_linesToKeyLines_fills_the_documented_fields(building):
    lines = api.createLSDAdvance().detect(building)
    height, width = building.shape
    keylines = api.linesToKeyLines(lines, (width, height))
    assert len(keylines) == len(lines)
    canvas = np.zeros_like(building)
    for i, (k, line) in enumerate(zip(keylines, lines.reshape(-1, 4).astype(np.float64))):
        assert isinstance(k, cv2.line_descriptor.KeyLine)
        # below 0 -> 0; at or beyond the side -> side - 1; [side - 1, side) kept
        x1, x2 = (0.0 if v < 0 else (width - 1.0 if v >= width else v) for v in line[0::2])
        y1, y2 = (0.0 if v < 0 else (height - 1.0 if v >= height else v) for v in line[1::2])
        assert (k.startPointX, k.startPointY, k.endPointX, k.endPointY) == pytest.approx((x1, y1, x2, y2), abs=1e-4)
        assert (k.sPointInOctaveX, k.sPointInOctaveY, k.ePointInOctaveX, k.ePointInOctaveY) == \
            (k.startPointX, k.startPointY, k.endPointX, k.endPointY)
        assert k.pt == pytest.approx(((x1 + x2) / 2, (y1 + y2) / 2), abs=1e-4)
        assert k.lineLength == pytest.approx(math.hypot(x2 - x1, y2 - y1), rel=1e-5)
        assert k.angle == pytest.approx(math.atan2(y2 - y1, x2 - x1), abs=1e-5)
        assert k.size == pytest.approx((x2 - x1) * (y2 - y1), rel=1e-4, abs=1e-3)
        assert k.response == pytest.approx(k.lineLength / max(width, height), rel=1e-6)
        # the pixels of the 8-connected digital line between the rounded endpoints, as cv2.line draws it
        canvas[:] = 0
        cv2.line(canvas, (round(x1), round(y1)), (round(x2), round(y2)), 255, 1, cv2.LINE_8)
        assert k.numOfPixels == np.count_nonzero(canvas)
        assert (k.octave, k.class_id) == (0, i)


@standalone_only
def test_detectKeyLines_equals_linesToKeyLines_of_detect(small_building):
    detector = api.createLSDAdvance()
    lines = detector.detect(small_building)
    detector.reset()
    keylines = detector.detectKeyLines(small_building)
    size = (small_building.shape[1], small_building.shape[0])
    expected = api.linesToKeyLines(lines, size)
    assert [(k.startPointX, k.startPointY, k.endPointX, k.endPointY, k.numOfPixels) for k in keylines] == \
        [(k.startPointX, k.startPointY, k.endPointX, k.endPointY, k.numOfPixels) for k in expected]
    # response: computeLineResponses', not the length of linesToKeyLines
    assert [k.response for k in keylines] == list(api.computeLineResponses(small_building, lines).ravel())


@standalone_only
def test_keyLinesToLines_inverts_linesToKeyLines_inside_the_image():
    lines = np.array([[[1.5, 2.25, 30.0, 40.5]], [[60.0, 10.0, 5.0, 70.75]]], np.float32)
    back = api.keyLinesToLines(api.linesToKeyLines(lines, (100, 100)))
    assert np.array_equal(back, lines)


@standalone_only
def test_lbd_matching_of_graf1_graf3_equals_the_cpp_sample():
    program = sample("LSD_ADVANCE_LBD_SAMPLE")
    paths = [data_path(n) for n in ("graf1.png", "graf3.png", "H1to3p.xml")]
    printed = subprocess.run([program, paths[0], paths[1], "--homography=" + paths[2]], check=True,
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, universal_newlines=True).stdout
    expected_matches = int(re.search(r"^matches:\s+(\d+)", printed, re.M).group(1))
    expected_correct = int(re.search(r"^correct:\s+(\d+)", printed, re.M).group(1))

    # The Python sample's pipeline: KeyLines from this module, LBD and its matcher from cv2.
    sys.path.insert(0, os.path.join(REPO, "samples", "python"))
    try:
        import lsd_advance_lbd_matching as matching
    finally:
        sys.path.pop(0)
    detector = api.createLSDAdvance()
    grays = [cv2.imread(p, cv2.IMREAD_GRAYSCALE) for p in paths[:2]]
    lines = []
    for gray in grays:
        detector.reset()
        lines.append(detector.detect(gray))
    described = [matching.describe_lines(g, l) for g, l in zip(grays, lines)]
    assert all(d.shape == (len(k), 32) and d.dtype == np.uint8 for k, d in described)
    matches = matching.match_lines(described[0][1], described[1][1])
    score = evaluation.evaluateHomographyMatches(lines[0], lines[1], matches, evaluation.readHomography(paths[2]),
                                                 grays[0].shape[::-1], grays[1].shape[::-1])
    assert (len(matches), score.correct) == (expected_matches, expected_correct)
    assert score.correct > 0
