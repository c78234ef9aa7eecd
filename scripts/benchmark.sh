#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/benchmark.sh [DATA_DIR]
#
# Measures everything the documentation quotes, in one run, and writes it to doc/results.md, the
# one page of measured numbers (scripts/check_figures.py fails CI when another page's figure is
# not the cell of that page it names): every method in one run per data set, one thread, on
# YorkUrban (all images, then the odd images the defaults were not tuned on), KITTI and EuRoC;
# LBD line matching on the HPatches graffiti pairs, OpenCV's graf1/graf3 and KITTI
# (doc/matching.md), with all lines and at line budgets of 100, 200 and 400 per image, and the
# tracks the matches chain into on KITTI and EuRoC; a point-line SLAM front end's figures
# (PL-VINS's rules: minimum length, a budget of 60 lines, one-way gated LBD matching, tracks) on
# KITTI and EuRoC (doc/matching.md, "In a SLAM front end"); computeLBD against line_descriptor's
# BinaryDescriptor::compute on the same lines at one and two threads; the pose evaluation
# (doc/pose.md: the stereo pairs of KITTI and the Strecha fountain's views at full and half size,
# lines only, points and points + lines, at line budgets of 60, 100, 150 and all) with its summary
# table; the parameter sweep of
# doc/parameter_sweep.md; the time of the defaults at one and two threads against LSD and ELSED,
# and the tiles' instructions with the estimate for more threads (scripts/tile_work.py, valgrind;
# doc/performance.md); the samples on OpenCV's images. It also writes the YorkUrban charts
# (doc/pics/results_yorkurban_*.svg), then takes the docs' quotes again from the new page
# (scripts/check_figures.py --update: README's copies of the YorkUrban and KITTI front-end tables,
# every figure quoted by its cell). The page says on which machine, commit and date it was made,
# and names the data folder $LSD_ADVANCE_DATA_DIR.
# DATA_DIR defaults to $LSD_ADVANCE_DATA_DIR, else ../shared/data beside the repository. Builds
# (or brings up to date) the programs first. With ELSED's sources beside the repository
# (../shared/peers/elsed) or in LSD_ADVANCE_ELSED_DIR, ELSED is built as an optional peer and
# measured in every table. Takes a few minutes on an idle 2-core machine, longer on a busy one;
# the page is replaced only when every step succeeded.
#
# Environment:
#   LSD_ADVANCE_BUILD_DIR  build directory (default: <repo>/build)
#   LSD_ADVANCE_JOBS       parallel build jobs (default 2)
#   LSD_ADVANCE_ELSED_DIR  ELSED's sources (see scripts/elsed_peer.sh; set it empty to leave ELSED out)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_BUILD_DIR:-$REPO/build}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
DATA="$(cd "${1:-${LSD_ADVANCE_DATA_DIR:-$REPO/../shared/data}}" && pwd)"
[ -d "$DATA/yorkurban" ] || { echo "ERROR: no yorkurban/ in $DATA" >&2; exit 1; }

PROGRAMS=(lsd_advance_benchmark lsd_advance_sweep lsd_advance_demo lsd_advance_lbd_matching lsd_advance_video)
[ -x "$BUILD/lsd_advance_benchmark" ] || bash "$REPO/scripts/install_deps.sh"
PEER_ARG="$(bash "$REPO/scripts/elsed_peer.sh")"
if [ -f "$BUILD/CMakeCache.txt" ]; then
  cmake "$BUILD" "$PEER_ARG" -DBUILD_APPS=ON -DBUILD_EXAMPLES=ON >/dev/null   # keeps the build's other options
else
  cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF "$PEER_ARG"
fi
cmake --build "$BUILD" -j"$JOBS" --target "${PROGRAMS[@]}"
export OPENCV_SAMPLES_DATA_PATH="${OPENCV_SAMPLES_DATA_PATH:-/usr/share/doc/opencv-doc/examples/data}"

B="$BUILD/lsd_advance_benchmark"
PEER=""
[ "$PEER_ARG" = "-DLSD_ADVANCE_ELSED_DIR=" ] || PEER=",elsed"
STILL="lsd,fld,fld_merge,edlines$PEER,plvins,lsdadvance_paper,lsdadvance_base,lsdadvance_fastest,lsdadvance_opencv_full,lsdadvance"
MATCHING="lsd,fld,edlines$PEER,lsdadvance_paper,lsdadvance_merge,lsdadvance"
SEQUENCE="lsd,fld,edlines$PEER,lsdadvance_paper,lsdadvance_filter,lsdadvance_fastest,lsdadvance,lsdadvance_interframe,lsdadvance_continuous,lsdadvance_tracking,lsdadvance_sequence"
BUDGET="lsd,fld,edlines$PEER,lsdadvance_paper,lsdadvance,lsdadvance_sequence"
# The front-end mode's methods: the baselines front ends run (PL-VINS's LSD front end first: the
# time ratios are to it), then LSDAdvance's; one word adds a method.
FRONTEND="plvins,lsd,fld_half$PEER,lsdadvance,lsdadvance_sequence,lsdadvance_fastest,lsdadvance_front_end"
# The pose evaluation's methods: OpenCV's LSD first (the rows compare with it), the other
# detectors front ends use, then LSDAdvance's.
POSE="lsd,plvins,fld,edlines$PEER,lsdadvance,lsdadvance_fastest,lsdadvance_sequence,lsdadvance_front_end"

PAGE="$REPO/doc/results.md"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
OUT="$WORK/results.md"
CHARTS="$WORK/results_yorkurban"
# Markdown for the page on stdout; commands and progress on stderr.
section() { printf '\n## %s\n\n' "$1"; }
run() { echo "+ ${*/#$REPO\//}" >&2; "$@"; }
output() { echo '```'; run "$@" | grep -v '^wrote '; echo '```'; }

opencv_dir="$(sed -n 's/^OpenCV_DIR:[A-Z]*=//p' "$BUILD/CMakeCache.txt")"
opencv_version="$(sed -n 's/.*set(OpenCV_VERSION \([0-9.]*\)).*/\1/p' "$opencv_dir/OpenCVConfig-version.cmake")"
compiler="$("$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$BUILD/CMakeCache.txt")" --version | head -n1)"
commit="$(git -C "$REPO" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$REPO" status --porcelain -- src include apps samples 2>/dev/null)" ]; then
  commit="$commit with uncommitted changes to src/, include/, apps/ or samples/"
fi
{
  echo "# Results"
  echo
  echo "Every measured number of this repository's documentation, from one run of"
  echo "\`bash scripts/benchmark.sh\`: generated, not edited (another page quotes a figure by naming its"
  echo "cell here, and \`scripts/check_figures.py\` fails CI when the figure is not the cell's)."
  echo
  echo "| | |"
  echo "|---|---|"
  echo "| date | $(date -u +%Y-%m-%d) |"
  echo "| commit | $commit |"
  echo "| machine | $(lscpu | sed -n 's/^Model name: *//p' | head -n1), $(nproc) cores, $(free -g | awk '/^Mem:/ { print $2 }') GiB |"
  echo "| system | $(. /etc/os-release && echo "$PRETTY_NAME"), $compiler, OpenCV $opencv_version |"
  echo "| ELSED | $([ -n "$PEER" ] && echo "built from its own sources (scripts/elsed_peer.sh)" || echo "not built: no ELSED rows") |"
  echo
  echo "One thread; times are medians on a machine that may be shared while it measures: compare them"
  echo "as ratios within one table (\"time / LSD\" is the median over images of each image's time"
  echo "divided by OpenCV LSD's on the same image), never across tables or runs. Every other column"
  echo "is the same on any machine. YorkUrban is scored with the structural protocol of [algorithm.md](algorithm.md) (detections"
  echo "shifted by +0.5 px; AP and AR are means over images, F = 2 AP AR / (AP + AR)); \"long share\""
  echo "is the share of segments of 60 px or more; the matching columns follow [matching.md](matching.md)."
  echo "The methods are those of \`apps/lsd_advance_bench/line_methods.hpp\`, LSDAdvance's variants the"
  echo "files \`apps/lsd_advance_bench/methods/<name>.yml\` (their titles are the rows' names)."

  section "YorkUrban-LineSegment, all 51 images"
  run "$B" --dataset=yorkurban --data="$DATA/yorkurban" --methods="$STILL" --repeats=3 --chart="$CHARTS"
  echo
  echo "![F per method on YorkUrban](pics/results_yorkurban_f.svg)"
  echo
  echo "![Time per image, and its ratio to LSD's in the same run](pics/results_yorkurban_time.svg)"
  echo
  echo "![Share of segments of 60 px or more](pics/results_yorkurban_long.svg)"
  section "YorkUrban-LineSegment, the 25 odd images (not used to choose the defaults)"
  run "$B" --dataset=yorkurban --data="$DATA/yorkurban" --subset=odd --methods="$STILL" --repeats=3
  section "KITTI, 51 consecutive frames (a sequence: inter-frame factors active)"
  run "$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$SEQUENCE" --no-match
  section "EuRoC V1_01 before take-off, 95 frames of a still camera"
  run "$B" --dataset=sequence --data="$DATA/euroc_v101_static" --methods="$SEQUENCE" --no-match
  section "LBD matching, HPatches v_graffiti (pairs 1-2 ... 1-6, exact homographies)"
  run "$B" --dataset=homography --data="$DATA/hpatches_v_graffiti" --methods="$MATCHING"
  section "LBD matching, OpenCV's graf1.png / graf3.png with H1to3p.xml"
  run "$B" --dataset=homography --image1=graf1.png --image2=graf3.png --homography=H1to3p.xml --methods="$MATCHING"
  section "LBD matching, KITTI consecutive frames (epipolar check, 50 pairs)"
  run "$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$MATCHING"
  section "LBD matching at equal line budgets (each method's N lines of highest KeyLine response): HPatches v_graffiti"
  run "$B" --dataset=homography --data="$DATA/hpatches_v_graffiti" --methods="$BUDGET" --top=100,200,400
  section "LBD matching at equal line budgets: OpenCV's graf1.png / graf3.png"
  run "$B" --dataset=homography --image1=graf1.png --image2=graf3.png --homography=H1to3p.xml --methods="$BUDGET" \
    --top=100,200,400
  section "LBD matching and tracks at equal line budgets: KITTI"
  run "$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$BUDGET" --top=100,200,400
  section "Tracks at equal line budgets: EuRoC V1_01, still camera"
  run "$B" --dataset=sequence --data="$DATA/euroc_v101_static" --methods="$BUDGET" --top=100,200,400

  section "A SLAM front end (PL-VINS's rules, doc/matching.md): KITTI, 51 frames with poses"
  run "$B" --dataset=sequence --data="$DATA/kitti_seq1" --frontend --methods="$FRONTEND"
  section "A SLAM front end: EuRoC V1_01, still camera, 95 frames (tracks)"
  run "$B" --dataset=sequence --data="$DATA/euroc_v101_static" --frontend --methods="$FRONTEND"

  section "LBD: computeLBD and line_descriptor's BinaryDescriptor::compute on the same lines (doc/matching.md)"
  echo "Each image's lines as KeyLines, described by the module's \`computeLBD\` and by \`line_descriptor\`'s"
  echo "\`BinaryDescriptor::compute\` (the same descriptors, checked), three times each, alternating, at"
  echo "\`--threads=1\` then \`--threads=2\` (\`BinaryDescriptor\` runs on one thread but for OpenCV's own"
  echo "filters); the last column is the median over images of each image's ratio of the two times."
  for threads in 1 2; do
    echo
    echo "KITTI, 51 frames, the 60 lines of \`PRESET_FRONT_END\`, $threads thread(s):"
    echo
    run "$B" --dataset=sequence --data="$DATA/kitti_seq1" --lbd --methods=lsdadvance_front_end --repeats=3 \
      --threads=$threads
    echo
    echo "YorkUrban, all 51 images, every line of the defaults, $threads thread(s):"
    echo
    run "$B" --dataset=yorkurban --data="$DATA/yorkurban" --lbd --methods=lsdadvance --repeats=3 --threads=$threads
  done

  section "Pose: stereo, KITTI, 50 pairs of consecutive frames (doc/pose.md)"
  run "$B" --dataset=stereo --data="$DATA/kitti_seq1" --methods="$POSE" --csv="$WORK/pose_stereo.csv"
  section "Pose: multi-view, Strecha fountain-P11, full size (doc/pose.md)"
  run "$B" --dataset=multiview --data="$DATA/strecha_fountain_p11" --methods="$POSE" --csv="$WORK/pose_full.csv"
  section "Pose: multi-view, Strecha fountain-P11, half size (doc/pose.md)"
  run "$B" --dataset=multiview --data="$DATA/strecha_fountain_p11" --scale=0.5 --methods="$POSE" \
    --csv="$WORK/pose_half.csv"
  section "Pose: summary (doc/pose.md)"
  echo "The pose AUC of lines alone at each budget, each method's own ranking, from the three tables above;"
  echo "then the median rotation error (degrees) of ORB's 500 points alone and with each method's 60 lines."
  echo
  /usr/bin/python3 - "$WORK" <<'PY'
import csv, sys
SETS = (("stereo", "stereo"), ("full", "multi-view"), ("half", "multi-view, half size"))
tables = {name: list(csv.DictReader(open("%s/pose_%s.csv" % (sys.argv[1], name)))) for name, _ in SETS}
rotation = "rotation error, deg (median [95 % CI])"
methods = [row["method"] for row in tables["stereo"] if row["features"] == "lines" and row["budget"] == "60"]
budgets = ("60", "100", "150")
print("| method | " + " | ".join("%s, %s" % (title, b) for _, title in SETS for b in budgets) +
      " | " + " | ".join("%s, points + 60 lines" % title for _, title in SETS) + " |")
print("|---|" + "---:|" * (len(SETS) * (len(budgets) + 1)))
def cell(name, method, features, budget, column):
    return next(r[column] for r in tables[name] if r["method"] == method and r["features"] == features and r["budget"] == budget)
print("| ORB points alone | " + " | ".join("-" for _ in SETS for b in budgets) + " | " +
      " | ".join(cell(name, "ORB", "points", "-", rotation).split(" ")[0] for name, _ in SETS) + " |")
for m in methods:
    print("| %s | " % m + " | ".join(cell(name, m, "lines", b, "pose AUC") for name, _ in SETS for b in budgets) + " | " +
          " | ".join(cell(name, m, "points + lines", "60", rotation).split(" ")[0] for name, _ in SETS) + " |")
PY

  section "Performance: one and two threads (doc/performance.md)"
  echo "OpenCV's LSD, ELSED (when built) and the defaults at \`--threads=1\` then \`--threads=2\`, one run each,"
  echo "back to back; then each two-thread time of the defaults divided by the one-thread time of each"
  echo "other method (ratios of the medians)."
  PERF_METHODS="lsd$PEER,lsdadvance"
  for threads in 1 2; do
    echo
    echo "YorkUrban, all 51 images, $threads thread(s):"
    echo
    run "$B" --dataset=yorkurban --data="$DATA/yorkurban" --methods="$PERF_METHODS" --repeats=3 --threads=$threads \
      --csv="$WORK/perf_yorkurban_$threads.csv"
    echo
    echo "KITTI, 51 frames, $threads thread(s):"
    echo
    run "$B" --dataset=sequence --data="$DATA/kitti_seq1" --methods="$PERF_METHODS" --no-match --threads=$threads \
      --csv="$WORK/perf_kitti_$threads.csv"
  done
  echo
  /usr/bin/python3 - "$WORK" <<'PY'
import csv, sys
def times(path):
    rows = list(csv.reader(open(path)))
    column = next(i for i, name in enumerate(rows[0]) if name.startswith("ms /") and "median" in name)
    return [(row[0], float(row[column])) for row in rows[1:]]
print("| data | defaults, 2 threads, ms | " + " | ".join("/ %s, 1 thread" % name for name, _ in times(sys.argv[1] + "/perf_kitti_1.csv")) + " |")
print("|---|---:|" + "---:|" * len(times(sys.argv[1] + "/perf_kitti_1.csv")))
for data, title in (("yorkurban", "YorkUrban"), ("kitti", "KITTI")):
    one, two = times("%s/perf_%s_1.csv" % (sys.argv[1], data)), times("%s/perf_%s_2.csv" % (sys.argv[1], data))
    defaults = two[-1][1]
    print("| %s | %.1f | %s |" % (title, defaults, " | ".join("%.2f" % (defaults / ms) for _, ms in one)))
PY
  echo
  echo "The tiles' work in instructions (callgrind) and the estimate it gives for more threads, from"
  echo "\`scripts/tile_work.py\` (every fifth image, at most five per set; shares of the instructions of a"
  echo "detection; \"largest tile / tiles\" is the largest tile's share of the tiles' work, the worst frame):"
  echo
  run /usr/bin/python3 "$REPO/scripts/tile_work.py" "$BUILD" YorkUrban="$DATA/yorkurban/images" KITTI="$DATA/kitti_seq1/image_l"

  section "Parameter sweep (doc/parameter_sweep.md)"
  run "$BUILD/lsd_advance_sweep" --data="$DATA/yorkurban"

  section "The samples on OpenCV's images"
  echo "\`lsd_advance_demo\` (building.jpg; one timed detection each):"
  echo
  output "$BUILD/lsd_advance_demo" --output="$WORK/demo.png"
  echo
  echo "\`lsd_advance_lbd_matching graf1.png graf3.png -H=H1to3p.xml\`:"
  echo
  output "$BUILD/lsd_advance_lbd_matching" graf1.png graf3.png -H=H1to3p.xml
  echo
  echo "\`lsd_advance_video\` (vtest.avi, \`PRESET_SEQUENCE\`):"
  echo
  output "$BUILD/lsd_advance_video" --output="$WORK/video.png"
} >"$OUT"
# The page names the data by the variable that points at it (doc/data.md), not by this machine's path.
page="$(cat "$OUT")"
printf '%s\n' "${page//"$DATA/"/\$LSD_ADVANCE_DATA_DIR/}" >"$OUT"

mkdir -p "$REPO/doc/pics"
for kind in f time long; do
  cp "${CHARTS}_$kind.svg" "$REPO/doc/pics/results_yorkurban_$kind.svg"
done
mv "$OUT" "$PAGE"

echo "[benchmark] wrote $PAGE and doc/pics/results_yorkurban_*.svg" >&2
# The docs' quotes of the page: every figure quoted by its cell and every copied table (README's
# YorkUrban and front-end tables) taken again from the new page; it prints each figure that
# changed (read its sentence again) and fails on a quote whose cell is gone.
/usr/bin/python3 "$REPO/scripts/check_figures.py" --update "$REPO"
