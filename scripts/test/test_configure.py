# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""The README's two commands share build/: scripts/demo.sh configures it without OpenCV's source
tree (none is fetched for the demo), scripts/test.sh then with it. No choice the first configure
made for want of the tree may stay in the cache and leave the Python module out of the second."""

import os
import re
import subprocess

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def cache(build):
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        return dict(re.match(r"^([^:#/]+):[A-Z]*=(.*)$", line).groups() for line in f
                    if re.match(r"^[^:#/]+:[A-Z]*=", line))


def configure(build, env, *args):
    subprocess.run(["cmake", "-S", REPO, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_EXAMPLES=OFF",
                    "-DBUILD_APPS=OFF", "-DLSD_ADVANCE_ELSED_DIR="] + list(args),
                   env=env, check=True, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)


def opencv_source_tree():
    """The OpenCV source tree of the build the tests run on (its CMakeCache.txt), if any."""
    prefix = os.environ.get("LSD_ADVANCE_SAMPLE_PREFIX", "")
    path = os.path.join(os.path.dirname(prefix), "CMakeCache.txt") if prefix else ""
    return cache(os.path.dirname(path)).get("OPENCV_SOURCE_DIR", "") if os.path.isfile(path) else ""


def test_a_configure_without_the_opencv_source_leaves_the_python_module_to_the_next_one(tmp_path):
    build = str(tmp_path / "build")
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path / "empty_cache"))   # no fetched tree there
    env.pop("OPENCV_SOURCE_DIR", None)
    configure(build, env, "-DBUILD_TESTS=OFF")                              # as scripts/demo.sh
    assert "LSD_ADVANCE_PYTHON" not in cache(build)
    tree = opencv_source_tree()
    if tree:
        configure(build, env, "-DBUILD_TESTS=OFF", "-DOPENCV_SOURCE_DIR=" + tree)   # the tree is there now
        assert cache(build)["LSD_ADVANCE_PYTHON"] == "ON"
