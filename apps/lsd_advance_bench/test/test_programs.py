# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of the programs as a user runs them.

The apps (apps/lsd_advance_bench: lsd_advance_detect, lsd_advance_benchmark, lsd_advance_sweep)
answer bad input with one "Error: ..." line and exit status 1 (no help dump, no abort), print
their options with --help (exit 0), and skip unreadable files of a folder, saying so, with exit
status 2. Their method files (methods/<name>.yml) are what LSDAdvance::write() writes, and those
named after a preset hold that preset. The samples (samples/, samples/python/) run on OpenCV's
sample data and agree with each other and with the apps.

Environment (scripts/test_python.sh sets it): LSD_ADVANCE_SAMPLE_PREFIX, the path of the C++
programs without their name (<build>/ standalone, <opencv build>/bin/example_lsd_advance_
in-tree, where the apps are not built); LSD_ADVANCE_PY_BACKEND=cv2 for the in-tree bindings;
OPENCV_SAMPLES_DATA_PATH. A missing program or data file skips its tests, except with CI=true,
where it fails them.
"""

import os
import re
import subprocess
import sys

import cv2
import numpy as np
import pytest

BENCH = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
REPO = os.path.abspath(os.path.join(BENCH, "..", ".."))
METHODS = os.path.join(BENCH, "methods")
DATA = os.environ.get("OPENCV_SAMPLES_DATA_PATH", "/usr/share/doc/opencv-doc/examples/data")
PREFIX = os.environ.get("LSD_ADVANCE_SAMPLE_PREFIX", "")
STANDALONE = os.environ.get("LSD_ADVANCE_PY_BACKEND", "standalone") == "standalone"
CI = os.environ.get("CI") == "true"

APPS = ("lsd_advance_detect", "lsd_advance_benchmark", "lsd_advance_sweep")
# What OpenCV's decoders, video backends and logger print when left alone.
NOISE = re.compile(r"\[mjpeg @|\[ WARN:|\[ERROR:|Premature end of JPEG|GStreamer|OpenCV\(")

if STANDALONE:
    import lsd_advance as api
else:
    api = cv2.ximgproc


def unavailable(what):
    if CI:
        pytest.fail(what + " (CI=true: required)")
    pytest.skip(what)


def command(program):
    """The command line that runs a program: an app, a C++ sample or a Python sample (*.py)."""
    if program.endswith(".py"):
        return [sys.executable, os.path.join(REPO, "samples", "python", program)]
    if program in APPS and not STANDALONE:
        pytest.skip("the apps are built standalone only (CMakeLists.txt)")
    path = PREFIX + program
    if not PREFIX or not os.access(path, os.X_OK):
        unavailable("no program %s (set LSD_ADVANCE_SAMPLE_PREFIX)" % path)
    return [path]


def run(program, args, cwd):
    if not os.path.isfile(os.path.join(DATA, "building.jpg")):
        unavailable("no OpenCV sample data in %s (install opencv-doc or set OPENCV_SAMPLES_DATA_PATH)" % DATA)
    env = dict(os.environ, OPENCV_SAMPLES_DATA_PATH=DATA, PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run(command(program) + list(args), cwd=str(cwd), env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=600)


def succeeded(result):
    assert result.returncode == 0, result.stderr
    return result.stdout


def number_after(text, label):
    return float(re.search(r"^%s\s*([0-9.]+)" % re.escape(label), text, re.M).group(1))


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
# The apps: bad input gives one "Error:" line naming what was wrong, and exit status 1

IMAGE = "--input=building.jpg"
APP_ERRORS = {
    "lsd_advance_detect": [
        (["--input"], ["--input", "needs a value"]),
        (["--input", "building.jpg"], ["--input", "needs a value"]),
        ([], ["--input", "required"]),
        ([IMAGE, "extra"], ["extra"]),
        ([IMAGE, "--methd=lsd"], ["--methd"]),
        ([IMAGE, "--long=-5"], ["--long", "> 0", "-5"]),
        ([IMAGE, "--long=abc"], ["--long", "abc"]),
        ([IMAGE, "--ext=gif"], ["gif"]),
        ([IMAGE, "--zoom=1,2,3"], ["--zoom", "1,2,3"]),
        ([IMAGE, "--zoom=0,0,0,5"], ["--zoom", "width and height >= 1"]),
        ([IMAGE, "--output={out}", "--draw=groups", "--zoom=5000,5000,10,10"], ["does not overlap"]),
        ([IMAGE, "--method=foo"], ["unknown method 'foo'", "lsdadvance_paper"]),
        ([IMAGE, "--method=../methods/lsdadvance"], ["unknown method"]),
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
        ([IMAGE, "--draw=lines"], ["--output"]),
        ([IMAGE, "--output={out}", "--draw=merge", "--method=lsd"], ["LSDAdvance"]),
        (["--method=lsd", "--write-params={out}/lsd.yml"], ["--write-params", "LSDAdvance method"]),
        (["--write-params={files}/no/such/m.yml"], ["--write-params", "does not exist"]),
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
        (["--dataset", "foo"], ["--dataset", "needs a value"]),
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
        (["--data={files}", "--frontend"], ["--frontend", "--dataset=sequence"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--max-lines=-1"], ["--max-lines"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--min-length-ratio=2"], ["--min-length-ratio"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--frontend-rank=best"], ["--frontend-rank", "best"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--max-angle=0"], ["--max-angle"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--max-shift=0"], ["--max-shift"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--track-frames=1"], ["--track-frames"]),
        (["--dataset=stereo", "--data={files}", "--methods=lsd"], ["--dataset=stereo needs", "image_r/"]),
        (["--dataset=multiview", "--data={files}", "--methods=lsd"], ["not a multi-view folder"]),
        (["--dataset=stereo", "--data={files}", "--budgets=60,-1"], ["--budgets", "'-1'"]),
        (["--dataset=stereo", "--data={files}", "--seeds=0"], ["--seeds"]),
        (["--dataset=multiview", "--data={files}", "--scale=0"], ["--scale"]),
        (["--dataset=stereo", "--data={files}", "--pose-hamming=257"], ["--pose-hamming"]),
        (["--dataset=sequence", "--data={files}", "--frontend", "--lbd"], ["--lbd", "--frontend"]),
        (["--dataset=homography", "--data={files}", "--lbd"], ["--lbd", "--dataset=yorkurban or sequence"]),
    ],
    "lsd_advance_sweep": [
        ([], ["--data"]),
        (["--data={files}/missing"], ["no such folder"]),
        (["--data={files}", "--tune=half"], ["--tune", "half"]),
        (["--data={files}", "--top=0"], ["--top"]),
    ],
}
ERROR_CASES = [(p, a, f) for p, cases in APP_ERRORS.items() for a, f in cases]


@pytest.mark.parametrize("program, args, fragments", ERROR_CASES,
                         ids=["%s %s" % (p, " ".join(a)) for p, a, _ in ERROR_CASES])
def test_bad_input_gives_one_error_line_and_exit_status_1(program, args, fragments, files, tmp_path):
    args = [a.format(files=files, out=tmp_path) for a in args]
    assert_one_error_line(run(program, args, tmp_path), fragments)


@pytest.mark.parametrize("program", APPS)
def test_help_lists_the_ranges_with_exit_status_0_even_beside_a_bad_option(program, tmp_path):
    for args in (["--help"], ["-h", "--no-such-option=1"]):
        result = run(program, args, tmp_path)
        assert result.returncode == 0, result.stderr
        assert "usage" in result.stdout.lower()
        assert re.search(r">= 1|> 0|0 to 256", result.stdout)


# --------------------------------------------------------------------------------------------
# A folder with an unreadable file: reported, skipped, counted, exit status 2, no decoder noise


def assert_skipped_one(result, files):
    assert result.returncode == 2, result.stderr
    assert "skipped %s: not an image OpenCV can read" % (files / "mixed" / "b.jpg") in result.stderr
    assert not NOISE.search(result.stderr), result.stderr
    assert "Error" not in result.stderr


def test_detect_skips_an_unreadable_file_of_a_folder_and_counts_it(files, tmp_path):
    result = run("lsd_advance_detect", ["--input=%s" % (files / "mixed"), "--output=out"], tmp_path)
    assert_skipped_one(result, files)
    assert "images:            2 (1 unreadable file(s) skipped)" in result.stdout
    assert sorted(os.listdir(str(tmp_path / "out"))) == ["a.txt", "c.txt"]
    assert "[detect] 3/3" in result.stderr  # the progress counts the files


def test_benchmark_skips_an_unreadable_file_of_a_folder_and_counts_it(files, tmp_path):
    result = run("lsd_advance_benchmark", ["--dataset=sequence", "--data=%s" % (files / "mixed"), "--methods=lsd",
                                           "--no-match"], tmp_path)
    assert_skipped_one(result, files)
    assert "Sequence: 2 frames" in result.stdout and "1 unreadable skipped" in result.stdout


def test_detect_reports_unreadable_single_files_without_decoder_noise(files, tmp_path):
    for name in ("garbage.jpg", "garbage.avi"):
        result = run("lsd_advance_detect", ["--input=%s" % (files / name)], tmp_path)
        assert_one_error_line(result, [name])
        assert not NOISE.search(result.stderr), result.stderr


def test_detect_writes_jpeg_drawings_with_ext_jpg(tmp_path):
    result = run("lsd_advance_detect", [IMAGE, "--output=out", "--draw=lines,merge", "--ext=jpg"], tmp_path)
    succeeded(result)
    assert sorted(os.listdir(str(tmp_path / "out"))) == ["building.jpg", "building.txt", "building_merge.jpg"]
    assert (tmp_path / "out" / "building_merge.jpg").read_bytes()[:2] == b"\xff\xd8"


# --------------------------------------------------------------------------------------------
# The benchmark's front-end mode: the budget, the matches and the tracks, on frames whose answer is known


def markdown_table(text, first_header="method", keys=1):
    """The first Markdown table of text whose first column is first_header: {row name: {column: cell}},
    a row named by its first cell, or by the tuple of its first `keys` cells."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("| %s |" % first_header))
    header = [cell.strip() for cell in lines[start].strip("|").split("|")]
    rows = {}
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        rows[cells[0] if keys == 1 else tuple(cells[:keys])] = dict(zip(header, cells))
    return rows


def front_end(folder, tmp_path, *args):
    result = run("lsd_advance_benchmark", ["--dataset=sequence", "--data=%s" % folder, "--frontend"] + list(args),
                 tmp_path)
    return markdown_table(succeeded(result))


@pytest.fixture(scope="module")
def still_frames(tmp_path_factory):
    """Folders of 4 and of 6 copies of one image: a still camera."""
    gray = cv2.imread(os.path.join(DATA, "building.jpg"), cv2.IMREAD_GRAYSCALE)
    if gray is None:
        unavailable("no building.jpg in " + DATA)
    folders = {}
    for count in (4, 6):
        folder = tmp_path_factory.mktemp("still%d" % count)
        for k in range(count):
            cv2.imwrite(str(folder / ("%06d.png" % k)), gray)
        folders[count] = folder
    return folders


def test_front_end_tracks_every_kept_line_of_a_still_camera_through_all_frames(still_frames, tmp_path):
    """Each kept line's nearest LBD neighbour in the same image is itself (distance 0, no shift):
    every kept line is matched in every pair, and makes one track of all the frames."""
    for method in ("PL-VINS LSD", "LSD"):
        six = front_end(still_frames[6], tmp_path, "--methods=plvins,lsd", "--max-lines=25")[method]
        kept = int(six["lines kept"])
        assert 0 < kept <= 25
        assert int(six["matches"]) == kept
        assert int(six["tracks >= 5 frames"]) == kept
        assert float(six["track length (frames, mean)"]) == 6
    four = front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=25")["LSD"]
    assert int(four["matches"]) == int(four["lines kept"]) > 0
    assert int(four["tracks >= 5 frames"]) == 0  # 4 frames make no track of 5
    assert int(front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=25",
                         "--track-frames=4")["LSD"]["tracks >= 4 frames"]) == int(four["lines kept"])


def test_front_end_budget_and_minimum_length_cut_the_kept_lines(still_frames, tmp_path):
    rows = front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=0", "--min-length-ratio=0")
    everything = rows["LSD"]
    assert everything["lines kept"] == everything["lines detected"]
    shorter = front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=0", "--min-length=60",
                        "--min-length-ratio=0")["LSD"]
    assert 0 < int(shorter["lines kept"]) < int(everything["lines kept"])
    budget = front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=7", "--min-length-ratio=0")["LSD"]
    assert int(budget["lines kept"]) == 7


def test_front_end_clahe_equalises_the_frames_before_detection(still_frames, tmp_path):
    plain = front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=0", "--min-length-ratio=0")["LSD"]
    equalised = front_end(still_frames[4], tmp_path, "--methods=lsd", "--max-lines=0", "--min-length-ratio=0",
                          "--clahe")["LSD"]
    assert int(equalised["lines detected"]) != int(plain["lines detected"])


def test_front_end_on_kitti_keeps_at_most_the_budget_and_matches_at_most_its_lines(tmp_path):
    """Five KITTI frames with their poses: lines kept <= budget, consistent <= matches <= lines kept,
    a time ratio of 1 for the reference front end."""
    kitti = os.path.join(os.environ.get("LSD_ADVANCE_DATA_DIR", ""), "kitti_seq1")
    if not os.path.isfile(os.path.join(kitti, "poses.txt")):
        unavailable("no kitti_seq1 in LSD_ADVANCE_DATA_DIR")
    frames = sorted(os.listdir(os.path.join(kitti, "image_l")))[:5]
    (tmp_path / "seq" / "image_l").mkdir(parents=True)
    for name in frames:
        os.symlink(os.path.join(kitti, "image_l", name), str(tmp_path / "seq" / "image_l" / name))
    with open(os.path.join(kitti, "poses.txt")) as poses:
        (tmp_path / "seq" / "poses.txt").write_text("".join(poses.readlines()[:5]))
    with open(os.path.join(kitti, "calib.txt")) as calib:
        (tmp_path / "seq" / "calib.txt").write_text(calib.read())
    rows = front_end(tmp_path / "seq", tmp_path, "--methods=plvins,lsd,fld_half,lsdadvance", "--max-lines=30")
    assert set(rows) == {"PL-VINS LSD", "LSD", "FLD, half size", "LSDAdvance"}
    for row in rows.values():
        assert int(row["lines kept"]) <= min(30, int(row["lines detected"]))
        assert 0 <= int(row["consistent matches"]) <= int(row["matches"]) <= int(row["lines kept"])
        assert 0 <= float(row["consistent share (pooled)"]) <= 1
        assert int(row["tracks >= 5 frames"]) <= int(row["lines kept"])
    assert rows["PL-VINS LSD"]["total / PL-VINS LSD"] == "1.00"
    assert int(rows["PL-VINS LSD"]["matches"]) > 0
    # Both LBDs timed on the same lines; the total counts line_descriptor's for the other detectors.
    for row in rows.values():
        assert float(row["computeLBD ms"]) > 0 and float(row["line_descriptor LBD ms"]) > 0
    plvins = rows["PL-VINS LSD"]
    assert float(plvins["line_descriptor LBD ms"]) <= float(plvins["total ms"])


def test_lbd_mode_times_both_descriptors_on_each_methods_lines(still_frames, tmp_path):
    result = run("lsd_advance_benchmark", ["--dataset=sequence", "--data=%s" % still_frames[4], "--lbd",
                                           "--methods=lsd,lsdadvance_front_end", "--repeats=2"], tmp_path)
    rows = markdown_table(succeeded(result))
    assert set(rows) == {"LSD", "LSDAdvance (front-end preset)"}
    assert int(rows["LSDAdvance (front-end preset)"]["lines / image (median)"]) == 60
    for row in rows.values():
        ours, theirs = float(row["computeLBD ms / image (median)"]), float(row["line_descriptor LBD ms / image (median)"])
        assert ours > 0 and theirs > 0
        assert float(row["computeLBD / line_descriptor (median)"]) > 0


# --------------------------------------------------------------------------------------------
# The pose evaluation: a stereo sequence folder, malformed or cut to a few frames

def kitti_folder():
    kitti = os.path.join(os.environ.get("LSD_ADVANCE_DATA_DIR", ""), "kitti_seq1")
    if not os.path.isfile(os.path.join(kitti, "poses.txt")) or not os.path.isdir(os.path.join(kitti, "image_r")):
        unavailable("no kitti_seq1 with image_r/ in LSD_ADVANCE_DATA_DIR")
    return kitti


def stereo_folder(tmp_path, frames, right=True, calib_rows=2, pose_rows=None, p0_moved=False, still=False):
    """The first frames of kitti_seq1 as a stereo sequence folder, optionally malformed (p0_moved: the left
    camera not at the origin; still: every pose the first)."""
    kitti = kitti_folder()
    names = sorted(os.listdir(os.path.join(kitti, "image_l")))[:frames]
    folder = tmp_path / "stereo"
    for side in ("image_l", "image_r") if right else ("image_l",):
        (folder / side).mkdir(parents=True)
        for name in names:
            os.symlink(os.path.join(kitti, side, name), str(folder / side / name))
    with open(os.path.join(kitti, "calib.txt")) as calib:
        rows = calib.read().splitlines(True)[:calib_rows]
    if p0_moved:
        fields = rows[0].split()
        fields[3] = "100"  # P0 row by row: its first row's last element
        rows[0] = " ".join(fields) + "\n"
    (folder / "calib.txt").write_text("".join(rows))
    with open(os.path.join(kitti, "poses.txt")) as poses:
        rows = poses.read().splitlines()[:pose_rows or frames]
    (folder / "poses.txt").write_text("\n".join(rows[:1] * len(rows) if still else rows) + "\n")
    return folder


@pytest.mark.parametrize("defect, fragments", [
    ({"right": False}, ["--dataset=stereo needs", "image_r/"]),
    ({"calib_rows": 1}, ["--dataset=stereo needs", "P0 and P1"]),
    ({"pose_rows": 2}, ["poses.txt has 2 poses for 3 images"]),
    ({"p0_moved": True}, ["P0 must be K [I | 0]"]),
    ({"still": True}, ["frames 0 and 1: no translation between them"]),
])
def test_stereo_pose_on_a_malformed_folder_gives_one_error_line(defect, fragments, tmp_path):
    result = run("lsd_advance_benchmark", ["--dataset=stereo", "--data=%s" % stereo_folder(tmp_path, 3, **defect),
                                           "--methods=lsd"], tmp_path)
    assert result.returncode == 1, result.stdout
    errors = [line for line in result.stderr.splitlines() if line.startswith("Error:")]
    assert len(errors) == 1, result.stderr
    for fragment in fragments:
        assert fragment in errors[0]


def test_stereo_pose_scores_every_row_against_lsd_on_the_same_pairs(tmp_path):
    """Three KITTI frames (two pairs), one seed, a budget of 60: a row per method and features, counts
    within their bounds, LSD's row the reference of the others."""
    folder = stereo_folder(tmp_path, 3)
    result = run("lsd_advance_benchmark", ["--dataset=stereo", "--data=%s" % folder, "--methods=lsd,lsdadvance_front_end",
                                           "--budgets=60", "--seeds=1", "--orb=300"], tmp_path)
    rows = markdown_table(succeeded(result), keys=3)  # (method, features, budget)
    front_end = "LSDAdvance (front-end preset)"
    assert set(rows) == {("ORB", "points", "-"), ("LSD", "lines", "60"), ("LSD", "points + lines", "60"),
                         (front_end, "lines", "60"), (front_end, "points + lines", "60"),
                         (front_end, "lines, by length", "60")}
    for key, row in rows.items():
        solved, trials = (int(n) for n in row["solved"].split("/"))
        successes = int(row["success"].split("/")[0])
        assert trials == 2 and 0 <= successes <= solved <= trials, key
        assert 0.0 <= float(row["pose AUC"]) <= 1.0, key
        if key[1] != "points":
            assert float(row["lines / image"]) <= 60, key
            assert float(row["3D lines / pair"]) <= float(row["lines / image"]), key
            assert 0.0 <= float(row["line matches the true pose fits"]) <= 1.0, key
            assert float(row["matched line length, px (median)"]) > 0, key
        else:
            assert row["line matches the true pose fits"] == row["matched line length, px (median)"] == "-"
    assert rows[("LSD", "lines", "60")]["AUC / LSD"] == "-"
    assert rows[(front_end, "lines", "60")]["wins : losses vs LSD (sign test p)"] != "-"
    assert float(rows[("ORB", "points", "-")]["matches / pair"]) > 0


def test_multiview_pose_scores_the_line_matches_by_the_true_pose(tmp_path):
    """The fountain at half size, two triplets: most of LSD's line matches into the third view fit its
    true pose (the translation the wrong way round fits none of them), and their lengths are measured."""
    fountain = os.path.join(os.environ.get("LSD_ADVANCE_DATA_DIR", ""), "strecha_fountain_p11")
    if not os.path.isdir(os.path.join(fountain, "gt_dense_cameras")):
        unavailable("no strecha_fountain_p11 in LSD_ADVANCE_DATA_DIR")
    result = run("lsd_advance_benchmark", ["--dataset=multiview", "--data=" + fountain, "--scale=0.5", "--pairs=2",
                                           "--methods=lsd", "--budgets=60", "--seeds=1"], tmp_path)
    row = markdown_table(succeeded(result), keys=3)[("LSD", "lines", "60")]
    assert float(row["matches / pair"]) > 0
    assert float(row["line matches the true pose fits"]) >= 0.5
    assert float(row["matched line length, px (median)"]) > 0


def test_stereo_pose_subset_takes_the_even_or_the_odd_pairs(tmp_path):
    """Five KITTI frames (four pairs): --subset=even and odd each estimate two of them, different ones
    (LSD's lines give other errors), and none left is an error."""
    folder = stereo_folder(tmp_path, 5)
    tables = {}
    for subset in ("all", "even", "odd"):
        result = run("lsd_advance_benchmark", ["--dataset=stereo", "--data=%s" % folder, "--methods=lsd", "--budgets=0",
                                               "--seeds=1", "--orb=300", "--subset=" + subset], tmp_path)
        tables[subset] = markdown_table(succeeded(result), keys=3)
        assert "%d pairs of consecutive frames" % (4 if subset == "all" else 2) in result.stdout
    for subset, pairs in (("all", 4), ("even", 2), ("odd", 2)):
        assert tables[subset][("LSD", "lines", "all")]["solved"].endswith("/%d" % pairs)
    assert tables["even"][("LSD", "lines", "all")] != tables["odd"][("LSD", "lines", "all")]
    result = run("lsd_advance_benchmark", ["--dataset=stereo", "--data=%s" % folder, "--methods=lsd", "--pairs=1",
                                           "--subset=odd"], tmp_path)
    assert result.returncode == 1 and "leave no pair" in result.stderr


# --------------------------------------------------------------------------------------------
# The method files: LSDAdvance's variants as data, in the form write() gives them

METHOD_FILES = sorted(f[:-4] for f in os.listdir(METHODS) if f.endswith(".yml"))
PRESET_FILES = {"lsdadvance": "MOST_ACCURATE", "lsdadvance_fastest": "FASTEST", "lsdadvance_paper": "PAPER",
                "lsdadvance_sequence": "SEQUENCE", "lsdadvance_front_end": "FRONT_END"}


def test_the_presets_and_the_variants_of_the_tables_have_method_files():
    assert set(PRESET_FILES) <= set(METHOD_FILES)
    assert {"lsdadvance_base", "lsdadvance_edlines", "lsdadvance_fld", "lsdadvance_opencv_full"} <= set(METHOD_FILES)


@pytest.mark.parametrize("name", METHOD_FILES)
def test_a_method_file_is_what_write_writes_of_it(name, tmp_path):
    """Read by the apps, written again by LSDAdvance::write(): unchanged, so a file cannot keep a
    key that is gone, miss one that is new, or hold a value out of range (read() would throw)."""
    written = tmp_path / ("%s.yml" % name)
    result = run("lsd_advance_detect", ["--method=" + name, "--write-params=%s" % written], tmp_path)
    succeeded(result)
    assert written.read_text() == open(os.path.join(METHODS, name + ".yml")).read(), \
        "methods/%s.yml is not what write() writes: rewrite it with lsd_advance_detect --method=%s --write-params=" \
        "<file> (doc/contributing.md)" % (name, name)


@pytest.mark.parametrize("name", sorted(PRESET_FILES))
def test_a_method_file_named_after_a_preset_holds_the_preset(name, tmp_path):
    """The file names its preset and sets no parameter of its own: what the apps read is the
    preset's full set, compared as what this build writes of each."""
    path = os.path.join(METHODS, name + ".yml")
    storage = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
    assert storage.getNode("preset").string() == "PRESET_" + PRESET_FILES[name]
    assert storage.getNode("LSDAdvance").empty()
    assert storage.getNode("title").string()
    storage.release()


@pytest.mark.parametrize("name", METHOD_FILES)
def test_a_method_file_is_a_preset_and_the_parameters_that_differ(name, tmp_path):
    """At most 15 lines: a preset, the keys of LSDAdvance::write() whose values differ from it,
    the title. Read on top of its preset, the file gives every value the apps use (a key equal
    to the preset's would be left out by --write-params, and the test above fails)."""
    path = os.path.join(METHODS, name + ".yml")
    assert len(open(path).read().splitlines()) <= 15
    storage = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
    preset = storage.getNode("preset").string()
    assert preset.startswith("PRESET_")
    detector = api.createLSDAdvance(getattr(api, "LSDAdvance_" + preset))
    detector.save(str(tmp_path / "preset.yml"))
    if not storage.getNode("LSDAdvance").empty():
        detector.read(storage.getNode("LSDAdvance"))
    storage.release()
    detector.save(str(tmp_path / "file.yml"))
    assert ((tmp_path / "file.yml").read_text() == (tmp_path / "preset.yml").read_text()) == (name in PRESET_FILES)


def test_write_params_writes_a_method_file_that_params_reads_back(tmp_path):
    """--write-params of a variant, read with --params on top of the defaults, detects as the variant."""
    succeeded(run("lsd_advance_detect", ["--method=lsdadvance_paper", "--write-params=paper.yml"], tmp_path))
    by_name = succeeded(run("lsd_advance_detect", [IMAGE, "--method=lsdadvance_paper"], tmp_path))
    by_file = succeeded(run("lsd_advance_detect", [IMAGE, "--params=paper.yml"], tmp_path))
    defaults = succeeded(run("lsd_advance_detect", [IMAGE], tmp_path))
    count = lambda text: number_after(text, "segments / image:")
    assert count(by_file) == count(by_name) != count(defaults)


# --------------------------------------------------------------------------------------------
# The samples: one use each, on OpenCV's sample data; they agree with each other and the apps


def detect_app_count(tmp_path, *args):
    return number_after(succeeded(run("lsd_advance_detect", [IMAGE] + list(args), tmp_path)), "segments / image:")


def test_demo_draws_lsd_and_lsdadvance_side_by_side(tmp_path):
    printed = succeeded(run("lsd_advance_demo", ["--output=demo.png"], tmp_path))
    lsd = int(re.search(r"^LSD: +(\d+) segments", printed, re.M).group(1))
    advance = int(re.search(r"^LSDAdvance: (\d+) segments", printed, re.M).group(1))
    picture = cv2.imread(str(tmp_path / "demo.png"))
    building = cv2.imread(os.path.join(DATA, "building.jpg"))
    assert picture.shape == (building.shape[0], 2 * building.shape[1], 3)
    assert advance < lsd
    if STANDALONE:
        assert advance == detect_app_count(tmp_path)
        assert lsd == detect_app_count(tmp_path, "--method=lsd")


@pytest.mark.parametrize("preset", ["most_accurate", "paper"])
def test_python_detect_counts_what_the_module_detects(preset, tmp_path):
    printed = succeeded(run("lsd_advance_detect.py", ["building.jpg", "--preset=" + preset, "--output=lines.png"],
                            tmp_path))
    count = int(re.match(r"(\d+) line segments in building.jpg", printed).group(1))
    gray = cv2.imread(os.path.join(DATA, "building.jpg"), cv2.IMREAD_GRAYSCALE)
    expected = api.createLSDAdvance(getattr(api, "LSDAdvance_PRESET_" + preset.upper())).detect(gray)
    assert count == len(expected)
    drawn = cv2.imread(str(tmp_path / "lines.png"))
    assert np.count_nonzero(np.all(drawn == (0, 0, 255), axis=2)) > 1000  # drawSegments' red


@pytest.mark.parametrize("program", ["lsd_advance_demo", "lsd_advance_lbd_matching", "lsd_advance_video",
                                     "lsd_advance_detect.py", "lsd_advance_lbd_matching.py"])
def test_a_sample_reports_a_missing_input_with_an_error_line_and_exit_status_1(program, tmp_path):
    result = run(program, ["missing.jpg"], tmp_path)
    assert result.returncode == 1, result.stderr
    assert result.stderr.strip().splitlines()[-1].startswith("Error: ")
    assert "missing.jpg" in result.stderr


def lbd_counts(printed):
    return [int(re.search(r"^%s:\s+(\d+)" % label, printed, re.M).group(1)) for label in ("matches", "correct")]


def test_lbd_matching_in_python_counts_what_the_cpp_sample_counts(tmp_path):
    args = ["graf1.png", "graf3.png", "--homography=H1to3p.xml"]
    cpp = lbd_counts(succeeded(run("lsd_advance_lbd_matching", args, tmp_path)))
    python = lbd_counts(succeeded(run("lsd_advance_lbd_matching.py", args, tmp_path)))
    assert cpp == python
    assert 0 < cpp[1] < cpp[0]


def test_lbd_drawing_colours_correct_matches_green_and_wrong_ones_red(tmp_path):
    def pixels(picture, colour):
        # the matched segments are drawn 2 px wide without anti-aliasing: in their exact colour
        return np.count_nonzero(np.all(picture == colour, axis=2))

    green, red, yellow = (60, 200, 60), (60, 60, 255), (0, 210, 255)
    matches, correct = lbd_counts(succeeded(run("lsd_advance_lbd_matching", ["-H=H1to3p.xml", "-d=m.png"], tmp_path)))
    assert 0 < correct < matches
    checked = cv2.imread(str(tmp_path / "m.png"))
    assert pixels(checked, green) > 1000 and pixels(checked, red) > 1000 and pixels(checked, yellow) == 0
    succeeded(run("lsd_advance_lbd_matching", ["-d=unchecked.png"], tmp_path))
    unchecked = cv2.imread(str(tmp_path / "unchecked.png"))
    assert pixels(unchecked, yellow) > 1000 and pixels(unchecked, green) == pixels(unchecked, red) == 0
    assert unchecked.shape == checked.shape


def test_video_sample_runs_one_detector_over_the_frames(tmp_path):
    result = run("lsd_advance_video", ["vtest.avi", "--frames=12", "--output=last.png"], tmp_path)
    if result.returncode != 0 and "as a video" in result.stderr and not STANDALONE:
        pytest.skip("this OpenCV build has no video backend for vtest.avi (the in-tree check builds none)")
    printed = succeeded(result)
    assert re.search(r"^frames: 12, segments per frame: [0-9.]+ mean", printed, re.M)
    assert re.search(r"^frame 0: \d+ segments, length threshold [0-9.]+ px \(alpha 1.00\)", printed, re.M)
    assert cv2.imread(str(tmp_path / "last.png")) is not None
