# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of scripts/check_docs.py: README.md and doc/ name no issue and no path outside the
repository, and the file map of doc/contributing.md matches the tree."""

import os
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "scripts"))
import check_docs  # noqa: E402

MAP = """# Contributing

## Where things are

| path | what it holds |
|---|---|
| `README.md`, `CMakeLists.txt` | the front page, the build |
| `src/stages.hpp` | the internal interface |
| `src/fast_lsd.*` | the default base |
| `test/` | unit tests |
| `doc/` | the pages |

## A new stage
"""
TREE = ["README.md", "CMakeLists.txt", "src/stages.hpp", "src/fast_lsd.cpp", "src/fast_lsd.hpp",
        "test/test_main.cpp", "test/data/list.txt", "doc/contributing.md"]


def repository(tmp_path, readme="# README\n", contributing=MAP, tree=TREE):
    """A repository (not a git checkout: the tree is its files) with these pages and files."""
    for name in tree:
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("x\n")
    (tmp_path / "README.md").write_text(readme)
    (tmp_path / "doc" / "contributing.md").write_text(contributing)
    return str(tmp_path)


def problems(repo):
    files = check_docs.tree_files(repo)
    roots = set(f.split("/")[0] for f in files if "/" in f)
    return check_docs.reference_problems(repo, files, roots) + check_docs.map_problems(repo, files)


def messages(repo):
    return ["%s:%d: %s" % p for p in problems(repo)]


def test_a_repository_whose_map_matches_its_tree_passes(tmp_path):
    repo = repository(tmp_path)
    assert problems(repo) == []
    assert check_docs.main(["check_docs.py", repo]) == 0


def test_issue_numbers_fail_upstream_pull_requests_do_not(tmp_path):
    repo = repository(tmp_path, readme="Chosen in issue 19 (#21), see issues 3 and 4.\n"
                                       "Moved by opencv#29349 and opencv_contrib#4158.\n")
    found = messages(repo)
    assert len(found) == 3 and all(m.startswith("README.md:1: names an issue") for m in found)
    assert check_docs.main(["check_docs.py", repo]) == 1


def test_paths_outside_the_repository_fail_system_paths_and_links_inside_do_not(tmp_path):
    readme = ("Data: `../shared/data`, docs in /work/shared/docs/SPEC.md and [spec](../SPEC.md).\n"
              "Fine: /usr/share/doc/opencv-doc/examples/data, /path/to/opencv, ~/lsd_advance, "
              "https://github.com/a/b/../c, segments / image.\n"
              "```sh\nbash scripts/benchmark.sh ../shared/data\n```\n")
    contributing = MAP + "Back to the [README](../README.md); out of it: [x](../../x.md).\n"
    repo = repository(tmp_path, readme=readme, contributing=contributing)
    found = messages(repo)
    assert [m.split(":")[0] + ":" + m.split(":")[1] for m in found] == [
        "README.md:1", "README.md:1", "README.md:1", "README.md:4", "doc/contributing.md:14"]
    assert "links outside the repository (../SPEC.md)" in found[0]
    assert "(../shared/data)" in found[1] and "$LSD_ADVANCE_DATA_DIR" in found[1]
    assert "(/work/shared/docs/SPEC.md)" in found[2]
    assert "links outside the repository (../../x.md)" in found[4]


def test_a_repository_path_or_page_named_in_prose_must_be_in_the_tree(tmp_path):
    readme = ("See `src/fast_lsd.cpp`, `src/<stage>.cpp`, `test/data/`, `src/{stages,fast_lsd}.hpp` and "
              "[the map](doc/contributing.md).\n"
              "Gone: `src/old_stage.cpp`, test/gone/, [data](doc/data.md), SPEC.md.\n"
              "```sh\ncp x src/new_file.cpp   # code may name what it creates\n```\n")
    found = messages(repository(tmp_path, readme=readme))
    assert found == ["README.md:2: links to doc/data.md, which is not in the tree",
                     "README.md:2: names src/old_stage.cpp, which is not in the tree",
                     "README.md:2: names test/gone/, which is not in the tree",
                     "README.md:2: names the page SPEC.md, which is neither in doc/ nor at the root"]


def test_a_file_of_src_missing_from_the_map_is_named(tmp_path):
    repo = repository(tmp_path, tree=TREE + ["src/full_scale_smoothing.cpp", "src/full_scale_smoothing.hpp"])
    found = messages(repo)
    assert len(found) == 1
    assert "leaves out src/full_scale_smoothing.cpp, src/full_scale_smoothing.hpp" in found[0]


def test_a_folder_missing_from_the_map_is_named_with_its_files(tmp_path):
    repo = repository(tmp_path, tree=TREE + ["compat/lsd/include/a.hpp", "compat/lsd/b.cpp"])
    found = messages(repo)
    assert len(found) == 1 and "leaves out compat/ (2 file(s): compat/lsd/b.cpp, compat/lsd/include/a.hpp)" in found[0]


def test_a_subfolder_of_src_is_covered_by_its_folder_entry(tmp_path):
    tree = [f for f in TREE if not f.startswith("src/fast_lsd")] + ["src/fast_lsd/regions.cpp", "src/fast_lsd/grow.cpp"]
    contributing = MAP.replace("`src/fast_lsd.*`", "`src/fast_lsd/`")
    assert problems(repository(tmp_path, contributing=contributing, tree=tree)) == []


def test_the_folder_src_alone_does_not_cover_the_files_directly_in_it(tmp_path):
    contributing = MAP.replace("| `src/stages.hpp` | the internal interface |\n", "| `src/` | the library |\n")
    found = messages(repository(tmp_path, contributing=contributing))
    assert len(found) == 1 and "leaves out src/stages.hpp" in found[0]


def test_a_stale_entry_is_named_with_the_other_places_that_name_it(tmp_path):
    # the default base split into a folder: the map's src/fast_lsd.* and the README's mention go stale
    tree = [f for f in TREE if not f.startswith("src/fast_lsd")] + ["src/fast_lsd/regions.cpp"]
    repo = repository(tmp_path, readme="The base is in `src/fast_lsd.cpp`.\n", tree=tree)
    found = messages(repo)
    assert "README.md:1: names src/fast_lsd.cpp, which is not in the tree" in found
    assert any("doc/contributing.md:9: the file map names src/fast_lsd.*, which is not in the tree; "
               "the pages name it also at README.md:1" in m for m in found)
    assert any("leaves out src/fast_lsd/ (1 file(s): src/fast_lsd/regions.cpp)" in m for m in found)


def test_without_a_file_map_the_check_fails(tmp_path):
    repo = repository(tmp_path, contributing="# Contributing\n")
    assert any("has no file map" in m for m in messages(repo))


def test_the_repository_names_only_what_it_has_and_its_file_map_matches_its_tree():
    assert check_docs.main(["check_docs.py", REPO]) == 0
