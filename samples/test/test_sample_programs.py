# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of the sample programs as a user runs them: every C++ sample (samples/*.cpp) and Python
sample (samples/python/) answers bad input with one "Error: ..." line and exit status 1 (no
help dump, no abort); accepts "--name value" as "--name=value"; skips unreadable files of a
folder and says so (exit status 2); and the Python twins draw exactly what the C++ samples draw.

Environment (scripts/test_python.sh sets it): LSD_ADVANCE_SAMPLE_PREFIX, the path of the C++
programs without their name (<build>/ standalone, <opencv build>/bin/example_lsd_advance_
in-tree); LSD_ADVANCE_PY_BACKEND=cv2 for the in-tree bindings (the Python LBD sample needs the
standalone module and is skipped then); OPENCV_SAMPLES_DATA_PATH. A missing program or data
file skips its tests, except with CI=true, where it fails them.
"""

import os
import re
import subprocess
import sys

import cv2
import numpy as np
import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DATA = os.environ.get("OPENCV_SAMPLES_DATA_PATH", "/usr/share/doc/opencv-doc/examples/data")
PREFIX = os.environ.get("LSD_ADVANCE_SAMPLE_PREFIX", "")
STANDALONE = os.environ.get("LSD_ADVANCE_PY_BACKEND", "standalone") == "standalone"
CI = os.environ.get("CI") == "true"

CPP = ("lsd_advance_detect", "lsd_advance_lbd_matching", "lsd_advance_benchmark", "lsd_advance_demo",
       "lsd_advance_sweep")
PYTHON = ("lsd_advance_detect.py", "lsd_advance_lbd_matching.py")
# What OpenCV's decoders, video backends and logger print when left alone.
NOISE = re.compile(r"\[mjpeg @|\[ WARN:|\[ERROR:|Premature end of JPEG|GStreamer|OpenCV\(")


def unavailable(what):
    if CI:
        pytest.fail(what + " (CI=true: required)")
    pytest.skip(what)


def command(program):
    """The command line that runs a sample program (a C++ name or a Python file name)."""
    if program.endswith(".py"):
        if program == "lsd_advance_lbd_matching.py" and not STANDALONE:
            pytest.skip("the Python LBD sample needs the standalone module lsd_advance")
        return [sys.executable, os.path.join(REPO, "samples", "python", program)]
    path = PREFIX + program
    if not PREFIX or not os.access(path, os.X_OK):
        unavailable("no C++ sample %s (set LSD_ADVANCE_SAMPLE_PREFIX)" % path)
    return [path]


def run(program, args, cwd):
    if not os.path.isfile(os.path.join(DATA, "building.jpg")):
        unavailable("no OpenCV sample data in %s (install opencv-doc or set OPENCV_SAMPLES_DATA_PATH)" % DATA)
    env = dict(os.environ, OPENCV_SAMPLES_DATA_PATH=DATA, PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run(command(program) + list(args), cwd=str(cwd), env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=600)


def assert_one_error_line(result, fragments):
    """Exit status 1 and one "Error:" line with the fragments, the last on stderr; before it, only
    what a folder run reports (its progress, the files it skipped)."""
    lines = [line for line in result.stderr.strip().splitlines() if line]
    assert result.returncode == 1, result.stderr
    assert lines and lines[-1].startswith("Error: "), result.stderr
    assert all(re.match(r"\[\w+\] |skipped ", line) for line in lines[:-1]), result.stderr
    assert result.stdout == ""  # no help text, no partial results
    for fragment in fragments:
        assert fragment in lines[-1]


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """A folder of bad and good inputs: parameter files, a folder with an unreadable image among
    readable ones, a folder of unreadable files only, a file named as an image that is none."""
    folder = tmp_path_factory.mktemp("inputs")
    (folder / "broken.yml").write_text("%YAML:1.0\n---\nLSDAdvance:\n   lsdScale: 1.0\n   mergeThreshold 0.5\n")
    (folder / "empty.yml").write_text("")
    (folder / "text.yml").write_text("hello\n")
    (folder / "params.yml").write_text("%YAML:1.0\n---\nLSDAdvance:\n   mergeThreshold: 0.5\n")
    gray = cv2.imread(os.path.join(DATA, "building.jpg"), cv2.IMREAD_GRAYSCALE)
    if gray is None:
        unavailable("no building.jpg in " + DATA)
    (folder / "mixed").mkdir()
    cv2.imwrite(str(folder / "mixed" / "a.png"), gray[:240, :320])
    (folder / "mixed" / "b.jpg").write_text("not an image\n")
    cv2.imwrite(str(folder / "mixed" / "c.png"), gray[240:480, 320:640])
    (folder / "unreadable").mkdir()
    (folder / "unreadable" / "a.png").write_text("not an image\n")
    (folder / "unreadable" / "b.jpg").write_bytes(b"")
    (folder / "garbage.jpg").write_text("not an image\n")
    (folder / "garbage.avi").write_text("not a video\n")
    (folder / "empty_folder").mkdir()
    return folder


# --------------------------------------------------------------------------------------------
# Bad input: one "Error:" line naming what was wrong, exit status 1

IMAGE = "--input=building.jpg"
DETECT_ERRORS = [  # (arguments, fragments of the message), for the C++ and the Python detect sample
    (["--input"], ["--input"]),
    ([], ["--input"]),
    ([IMAGE, "extra"], ["extra"]),
    ([IMAGE, "--methd=lsd"], ["--methd"]),
    ([IMAGE, "--long=-5"], ["--long", "> 0", "-5"]),
    ([IMAGE, "--long", "-5"], ["--long", "> 0", "-5"]),
    ([IMAGE, "--long=abc"], ["--long", "abc"]),
    ([IMAGE, "--ext=gif"], ["gif"]),
    ([IMAGE, "--zoom=1,2,3"], ["--zoom", "1,2,3"]),
    ([IMAGE, "--zoom=0,0,0,5"], ["--zoom", "width and height >= 1"]),
    ([IMAGE, "--output={out}", "--draw=groups", "--zoom=5000,5000,10,10"], ["does not overlap"]),
    ([IMAGE, "--method=foo"], ["foo"]),
    (["--input=missing.jpg"], ["missing.jpg"]),
    (["--input={files}/garbage.jpg"], ["cannot read", "garbage.jpg"]),
    (["--input={files}/garbage.avi"], ["cannot read", "garbage.avi"]),
    (["--input={files}/empty_folder"], ["empty_folder"]),
    (["--input={files}/unreadable"], ["none of the 2 image files"]),
    ([IMAGE, "--params={files}/missing.yml"], ["missing.yml"]),
    ([IMAGE, "--params={files}/broken.yml"], ["broken.yml: line 5: Missing ':'"]),
    ([IMAGE, "--params={files}/empty.yml"], ["empty.yml", "empty"]),
    ([IMAGE, "--params={files}/text.yml"], ["text.yml"]),
    ([IMAGE, "--method=lsd", "--params={files}/params.yml"], ["lsdadvance"]),
    ([IMAGE, "--output={out}", "--draw=foo"], ["foo"]),
    ([IMAGE, "--draw"], ["--output"]),
    ([IMAGE, "--output={out}", "--draw=merge", "--method=lsd"], ["LSDAdvance"]),
]
LBD_ERRORS = [  # for the C++ and the Python LBD matching sample
    (["--max-hamming=-3"], ["--max-hamming", "-3"]),
    (["--max-hamming", "-3"], ["--max-hamming", "-3"]),
    (["--max-hamming=257"], ["--max-hamming", "257"]),
    (["--max-hamming=x"], ["--max-hamming"]),
    (["graf1.png", "graf3.png", "extra.png"], ["extra.png"]),
    (["-H"], ["homography"]),
    (["-H=missing.xml"], ["missing.xml"]),
    (["missing.png", "graf3.png"], ["missing.png"]),
    (["--draw={files}/no/such/folder/m.jpg"], ["does not exist"]),
    (["--draw={out}/m.xyz"], ["m.xyz"]),
    (["--params={files}/broken.yml"], ["broken.yml: line 5: Missing ':'"]),
    (["--method=foo"], ["foo"]),
]
CPP_ERRORS = {
    "lsd_advance_lbd_matching": [
        (["--sequence"], ["--sequence"]),
        (["--sequence={files}/unreadable"], ["none of the 2 image files"]),
        (["--sequence={files}/mixed", "-H=H1to3p.xml"], ["--homography"]),
    ],
    "lsd_advance_benchmark": [
        ([], ["--data"]),
        (["--data={files}/missing"], ["missing", "no such folder", "expected YorkUrban-LineSegment (images/, gt/"]),
        (["--methods=lsd,foo"], ["unknown method 'foo'"]),
        (["--data={files}/empty_folder"], ["empty_folder"]),
        (["--data={files}/empty_folder", "--dataset=sequence"], ["empty_folder"]),
        (["--data={files}/empty_folder", "--methods=lsd,foo"], ["foo"]),
        (["--data={files}/empty_folder", "--methods="], ["--methods"]),
        (["--dataset=foo"], ["--dataset", "foo"]),
        (["--dataset", "foo"], ["--dataset", "foo"]),
        (["--data={files}", "--max-hamming=-3"], ["--max-hamming"]),
        (["--data={files}", "--top=-1"], ["--top"]),
        (["--data={files}", "--top=100,x"], ["--top", "'x'"]),
        (["--data={files}", "--top=100,-5"], ["--top", "'-5'"]),
        (["--data={files}", "--rank=best"], ["--rank", "best"]),
        (["--data={files}", "--repeats=0"], ["--repeats"]),
        (["--data={files}", "--threads=0"], ["--threads"]),
        (["--data={files}", "--long=0"], ["--long"]),
        (["--data={files}", "--subset=half"], ["--subset", "half"]),
        (["--data={files}", "--csv={files}/no/such/table.csv"], ["--csv", "does not exist"]),
        (["--data={files}", "--chart={files}/no/such/chart"], ["--chart", "does not exist"]),
        (["--data={files}", "--params={files}/broken.yml"], ["broken.yml: line 5"]),
        (["--dataset=homography", "--image1=graf1.png"], ["--image2"]),
        (["--dataset=homography", "--image1=graf1.png", "--image2=graf3.png", "--homography=missing.xml"],
         ["missing.xml"]),
        (["--dataset=sequence", "--data={files}/unreadable", "--methods=lsd"], ["no readable frame"]),
    ],
    "lsd_advance_demo": [
        (["--repeats=0"], ["--repeats"]),
        (["--long=-1"], ["--long"]),
        (["--image=missing.jpg"], ["missing.jpg"]),
        (["--output={files}/no/such/demo.png"], ["does not exist"]),
        (["--output={out}/demo.xyz"], ["demo.xyz"]),
        (["--params={files}/broken.yml"], ["broken.yml: line 5"]),
        (["--image={files}/unreadable"], ["none of the 2 image files"]),
        (["extra"], ["extra"]),
    ],
    "lsd_advance_sweep": [
        ([], ["--data"]),
        (["--data={files}/missing"], ["no such folder"]),
        (["--data={files}", "--tune=half"], ["--tune", "half"]),
        (["--data={files}", "--top=0"], ["--top"]),
    ],
}

ERROR_CASES = (
    [(p, a, f) for p in ("lsd_advance_detect", "lsd_advance_detect.py") for a, f in DETECT_ERRORS] +
    [(p, a, f) for p in ("lsd_advance_lbd_matching", "lsd_advance_lbd_matching.py") for a, f in LBD_ERRORS] +
    [(p, a, f) for p, cases in CPP_ERRORS.items() for a, f in cases])


@pytest.mark.parametrize("program, args, fragments", ERROR_CASES,
                         ids=["%s %s" % (p, " ".join(a)) for p, a, _ in ERROR_CASES])
def test_bad_input_gives_one_error_line_and_exit_status_1(program, args, fragments, files, tmp_path):
    args = [a.format(files=files, out=tmp_path) for a in args]
    assert_one_error_line(run(program, args, tmp_path), fragments)


@pytest.mark.parametrize("program", CPP + PYTHON)
def test_help_is_printed_with_exit_status_0_even_beside_a_bad_option(program, tmp_path):
    for args in (["--help"], ["-h", "--no-such-option=1"]):
        result = run(program, args, tmp_path)
        assert result.returncode == 0, result.stderr
        assert "usage" in (result.stdout + result.stderr).lower()


# --------------------------------------------------------------------------------------------
# "--name value" is "--name=value", in C++ as in Python


def summary_without_time(result):
    assert result.returncode == 0, result.stderr
    return [line for line in result.stdout.splitlines() if not line.startswith("ms / image")]


@pytest.mark.parametrize("program", ["lsd_advance_detect", "lsd_advance_detect.py"])
def test_detect_reads_a_value_after_a_space_as_after_equals(program, tmp_path):
    forms = [["--input=building.jpg"], ["--input", "building.jpg"], ["-i", "building.jpg"], ["-i=building.jpg"],
             ["--input", "building.jpg", "--long", "30"]]
    outputs = [summary_without_time(run(program, f, tmp_path)) for f in forms]
    assert outputs[1:4] == [outputs[0]] * 3
    assert any(line.startswith("segments / image:") for line in outputs[0])
    assert any(line.startswith("long share:") and "(>= 30 px" in line for line in outputs[4])


@pytest.mark.parametrize("program", ["lsd_advance_lbd_matching", "lsd_advance_lbd_matching.py"])
def test_lbd_matching_reads_the_homography_after_a_space_as_after_equals(program, tmp_path):
    forms = [["-H=H1to3p.xml"], ["-H", "H1to3p.xml"], ["--homography", "H1to3p.xml"]]
    outputs = []
    for form in forms:
        result = run(program, ["graf1.png", "graf3.png"] + form, tmp_path)
        assert result.returncode == 0, result.stderr
        outputs.append(re.search(r"^correct: .*$", result.stdout, re.M).group(0))
    assert outputs == [outputs[0]] * len(forms)


# --------------------------------------------------------------------------------------------
# A folder with an unreadable file: reported, skipped, counted, exit status 2, no decoder noise


def assert_skipped_one(result, files):
    assert result.returncode == 2, result.stderr
    assert "skipped %s: not an image OpenCV can read" % (files / "mixed" / "b.jpg") in result.stderr
    assert not NOISE.search(result.stderr), result.stderr
    assert "Error" not in result.stderr


@pytest.mark.parametrize("program", ["lsd_advance_detect", "lsd_advance_detect.py"])
def test_detect_skips_an_unreadable_file_of_a_folder_and_counts_it(program, files, tmp_path):
    result = run(program, ["--input=%s" % (files / "mixed"), "--output=out"], tmp_path)
    assert_skipped_one(result, files)
    assert "images:            2 (1 unreadable file(s) skipped)" in result.stdout
    assert sorted(os.listdir(str(tmp_path / "out"))) == ["a.txt", "c.txt"]
    # the progress counts the files, as in the C++ sample
    assert "[detect] 3/3" in result.stderr


def test_demo_skips_an_unreadable_file_of_a_folder_and_counts_it(files, tmp_path):
    result = run("lsd_advance_demo", ["--image=%s" % (files / "mixed"), "--repeats=1"], tmp_path)
    assert_skipped_one(result, files)
    assert "images: 2 in %s (1 unreadable skipped)" % (files / "mixed") in result.stdout


def test_benchmark_skips_an_unreadable_file_of_a_folder_and_counts_it(files, tmp_path):
    result = run("lsd_advance_benchmark", ["--dataset=sequence", "--data=%s" % (files / "mixed"), "--methods=lsd",
                                           "--no-match"], tmp_path)
    assert_skipped_one(result, files)
    assert "Sequence: 2 frames" in result.stdout and "1 unreadable skipped" in result.stdout


def test_lbd_matching_sequence_skips_an_unreadable_frame_and_keeps_the_frame_numbers(files, tmp_path):
    result = run("lsd_advance_lbd_matching", ["--sequence=%s" % (files / "mixed")], tmp_path)
    assert_skipped_one(result, files)
    assert re.search(r"^frames 0-2: ", result.stdout, re.M)
    assert "skipped:           1 unreadable file(s)" in result.stdout


@pytest.mark.parametrize("program", ["lsd_advance_detect", "lsd_advance_detect.py"])
def test_unreadable_single_files_give_no_decoder_noise(program, files, tmp_path):
    for name in ("garbage.jpg", "garbage.avi"):
        result = run(program, ["--input=%s" % (files / name)], tmp_path)
        assert_one_error_line(result, [name])


# --------------------------------------------------------------------------------------------
# The Python twins draw what the C++ samples draw


def same_pixels(path1, path2):
    a, b = cv2.imread(str(path1)), cv2.imread(str(path2))
    assert a is not None and b is not None
    return a.shape == b.shape and np.array_equal(a, b)


@pytest.mark.parametrize("zoom", [[], ["--zoom=150,60,300,200"]])
def test_python_detect_draws_the_stages_as_the_cpp_sample(zoom, tmp_path):
    drawn = {}
    for program in ("lsd_advance_detect", "lsd_advance_detect.py"):
        out = tmp_path / program
        result = run(program, ["--input=building.jpg", "--output=%s" % out, "--draw=lines,stages", "--no-segments"] +
                     zoom, tmp_path)
        assert result.returncode == 0, result.stderr
        drawn[program] = out
        assert sorted(os.listdir(str(out))) == ["building.png", "building_filter.png", "building_groups.png",
                                               "building_merge.png"]
    for name in os.listdir(str(drawn["lsd_advance_detect"])):
        assert same_pixels(drawn["lsd_advance_detect"] / name, drawn["lsd_advance_detect.py"] / name), name


@pytest.mark.parametrize("program", ["lsd_advance_detect", "lsd_advance_detect.py"])
def test_detect_writes_jpeg_drawings_with_ext_jpg(program, tmp_path):
    result = run(program, ["--input=building.jpg", "--output=out", "--draw=lines,merge", "--ext=jpg"], tmp_path)
    assert result.returncode == 0, result.stderr
    assert sorted(os.listdir(str(tmp_path / "out"))) == ["building.jpg", "building.txt", "building_merge.jpg"]
    assert (tmp_path / "out" / "building_merge.jpg").read_bytes()[:2] == b"\xff\xd8"


def test_lbd_drawing_colours_correct_matches_green_and_wrong_ones_red(tmp_path):
    drawings = []
    for program in ("lsd_advance_lbd_matching", "lsd_advance_lbd_matching.py"):
        path = tmp_path / (program + ".png")
        result = run(program, ["graf1.png", "graf3.png", "-H=H1to3p.xml", "--draw=%s" % path], tmp_path)
        assert result.returncode == 0, result.stderr
        drawings.append(path)
        matches = int(re.search(r"^matches:\s+(\d+)", result.stdout, re.M).group(1))
        correct = int(re.search(r"^correct:\s+(\d+)", result.stdout, re.M).group(1))
        assert 0 < correct < matches
    assert same_pixels(*drawings)
    picture = cv2.imread(str(drawings[0]))
    green, red = (60, 200, 60), (60, 60, 255)
    # the matched segments are drawn 2 px wide, without anti-aliasing: in their exact colour
    assert np.count_nonzero(np.all(picture == green, axis=2)) > 1000
    assert np.count_nonzero(np.all(picture == red, axis=2)) > 1000
    # the counts on a black box in the top-left corner, written in the colours of their matches
    corner = picture[:40, :120]
    assert np.count_nonzero(np.all(corner == 0, axis=2)) > corner.shape[0] * corner.shape[1] // 2
    assert np.any(corner[:, :, 1] > 150)


def test_lbd_drawing_of_a_sequence_with_poses_colours_the_epipolar_verdicts(tmp_path):
    data = os.environ.get("LSD_ADVANCE_DATA_DIR", "")
    kitti = os.path.join(data, "kitti_seq1")
    if not os.path.isdir(kitti):
        unavailable("no kitti_seq1 in LSD_ADVANCE_DATA_DIR")
    frames = tmp_path / "kitti"
    (frames / "image_l").mkdir(parents=True)
    (frames / "calib.txt").write_text(open(os.path.join(kitti, "calib.txt")).read())
    (frames / "poses.txt").write_text("".join(open(os.path.join(kitti, "poses.txt")).readlines()[:2]))
    for k in range(2):
        os.symlink(os.path.join(kitti, "image_l", "%06d.png" % k), str(frames / "image_l" / ("%06d.png" % k)))
    result = run("lsd_advance_lbd_matching", ["--sequence=%s" % frames, "--draw=m.png"], tmp_path)
    assert result.returncode == 0, result.stderr
    consistent = int(re.search(r"consistent (\d+)", result.stdout).group(1))
    inconsistent = int(re.search(r"inconsistent (\d+)", result.stdout).group(1))
    picture = cv2.imread(str(tmp_path / "m.png"))
    assert consistent > 0 and np.count_nonzero(np.all(picture == (60, 200, 60), axis=2)) > 0
    assert (inconsistent > 0) == (np.count_nonzero(np.all(picture == (60, 60, 255), axis=2)) > 0)
