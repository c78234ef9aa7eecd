#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Usage: /usr/bin/python3 scripts/tile_work.py BUILD_DIR NAME=IMAGE_FOLDER [NAME=IMAGE_FOLDER ...]

The work of BASE_FAST_LSD's tiles, in instructions (valgrind's callgrind, which counts the same
on a busy machine), and from it an estimate of the time of the defaults at 1, 2, 4 and 8 threads
(doc/performance.md, "Threads"). Per image set: every fifth image of the folder (at most five),
detected with the defaults by lsd_advance_benchmark at one thread, twice under callgrind: once for
the instructions of the whole detection, of the work parallel over many small tasks (the
test of aliasing, the smoothing and the gradient pass over rows, the rectangles of the regions joined across the
seams, stage 3 over groups, the line responses over segments) and of the tiles (parallel over
tiles), once with a dump at the start of each tile, for each tile's own. The estimate for T
threads adds, per image, the serial rest, the small tasks' work divided by T and the tiles
scheduled in order each onto the first free thread; it counts no cost of the threads themselves.
Prints Markdown: one table of the shares and estimates, one of the instructions of each tile
(mean over the images). Needs valgrind and callgrind_annotate.
"""

import glob
import os
import re
import subprocess
import sys
import tempfile

DETECT = "*LSDAdvanceImpl::detect*"
# The functions whose work is parallel over many small tasks (runTasks; their serial set-up is small).
SMALL_TASKS = ("FullScaleSmoothing::apply", "computeGradient(", "Tiling::validateJoined", "lsda::mergeGroups(",
               "lsda::unknownResponses(")
# The tiles' work (a task per tile), and the function each tile starts with.
TILES = "Tiling::growTiles"
TILE_START = "orderSeeds"
THREADS = (1, 2, 4, 8)


def callgrind(benchmark, data, out, extra):
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out] + extra +
                   [benchmark, "--dataset=sequence", "--data=" + data, "--methods=lsdadvance", "--no-match",
                    "--threads=1"], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def summary(path):
    with open(path) as f:
        for line in f:
            if line.startswith("summary:"):
                return int(line.split()[1])
    raise RuntimeError("no summary in " + path)


def inclusive(path, names, optional=()):
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path], check=True,
                          capture_output=True, text=True).stdout
    found = {}
    for line in text.splitlines():
        m = re.match(r"\s*([\d,]+) .*?:(.*)", line)
        if not m:
            continue
        for name in names:
            if name in m.group(2) and name not in found:
                found[name] = int(m.group(1).replace(",", ""))
    missing = [n for n in names if n not in found and n not in optional]
    if missing:
        raise RuntimeError("callgrind_annotate lists no %s in %s" % (", ".join(missing), path))
    return found


def makespan(tiles, threads):
    free = [0] * threads
    for work in tiles:
        k = free.index(min(free))
        free[k] += work
    return max(free)


def measure(benchmark, name, folder, work):
    images = sorted(p for p in glob.glob(os.path.join(folder, "*")) if p.lower().endswith((".png", ".jpg")))[::5][:5]
    if not images:
        raise RuntimeError("no image in " + folder)
    data = os.path.join(work, name)
    os.makedirs(os.path.join(data, "image_l"))
    for i, path in enumerate(images):
        os.symlink(os.path.abspath(path), os.path.join(data, "image_l", "%06d%s" % (i, os.path.splitext(path)[1])))
    whole = os.path.join(work, name + ".whole")
    callgrind(benchmark, data, whole, ["--toggle-collect=" + DETECT])
    counts = inclusive(whole, ["LSDAdvanceImpl::detect", TILES] + list(SMALL_TASKS), optional=SMALL_TASKS)
    split = os.path.join(work, name + ".tiles")
    # The pattern ends at growTiles' last parameter: the name of its task's body contains "growTiles(" too,
    # and a second toggle inside the first would stop the collection.
    callgrind(benchmark, data, split, ["--collect-atstart=no", "--toggle-collect=*" + TILES + "(*int)",
                                       "--dump-before=*" + TILE_START + "*"])
    # Dump k (from 2) holds tile k - 1, the final file the last tile; dump 1 what preceded the first.
    parts = sorted(glob.glob(split + ".*"), key=lambda p: int(p.rsplit(".", 1)[1]))
    tiles = [summary(p) for p in parts[1:]] + [summary(split)]
    if len(tiles) % len(images):
        raise RuntimeError("%d tiles for %d images" % (len(tiles), len(images)))
    perImage = len(tiles) // len(images)
    frames = [tiles[k * perImage:(k + 1) * perImage] for k in range(len(images))]
    total, tileSum = counts["LSDAdvanceImpl::detect"], counts[TILES]
    smallTasks = sum(counts.get(name, 0) for name in SMALL_TASKS)
    serial = total - smallTasks - tileSum
    times = {}
    for t in THREADS:
        times[t] = sum(serial / len(images) + smallTasks / len(images) / t + makespan(f, t) for f in frames)
    means = [sum(f[k] for f in frames) / len(frames) for k in range(perImage)]
    return dict(name=name, images=len(images), total=total / len(images), serial=serial / total,
                smallTasks=smallTasks / total, tiles=tileSum / total, largest=max(max(f) / sum(f) for f in frames),
                times=times, means=means)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    benchmark = os.path.join(sys.argv[1], "lsd_advance_benchmark")
    with tempfile.TemporaryDirectory() as work:
        results = [measure(benchmark, *arg.split("=", 1), work) for arg in sys.argv[2:]]
    print("| images | frames | instructions / frame (M) | serial | small tasks | tiles | largest tile / tiles |"
          + "".join(" %d threads / 1 |" % t for t in THREADS[1:]))
    print("|---|---:|---:|---:|---:|---:|---:|" + "---:|" * (len(THREADS) - 1))
    for r in results:
        print("| %s | %d | %.1f | %.3f | %.3f | %.3f | %.3f |" % (r["name"], r["images"], r["total"] / 1e6, r["serial"],
                                                                  r["smallTasks"], r["tiles"], r["largest"])
              + "".join(" %.2f |" % (r["times"][t] / r["times"][1]) for t in THREADS[1:]))
    print()
    width = max(len(r["means"]) for r in results)
    print("| images |" + "".join(" tile %d |" % k for k in range(width)))
    print("|---|" + "---:|" * width)
    for r in results:
        print("| %s |" % r["name"] + "".join(" %.2f M |" % (m / 1e6) for m in r["means"]) + " |" * (width - len(r["means"])))


if __name__ == "__main__":
    main()
