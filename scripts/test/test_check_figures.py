# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of scripts/check_figures.py, the check that the docs quote only figures of doc/results.md."""

import os
import sys

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "scripts"))
import check_figures  # noqa: E402

RESULTS = """# Results
| method | F | ms / image (median) | time / LSD (median) |
|---|---:|---:|---:|
| LSD | 0.435 | 22.5 | 1.000 |
| LSDAdvance | 0.526 | 5.2 | 0.229 |

```
LSDAdvance: 393 segments, 33.7 ms
```
"""


def check(tmp_path, page, results=RESULTS):
    """(status, reported lines) of the check on a repository whose README is page."""
    (tmp_path / "doc").mkdir(exist_ok=True)
    (tmp_path / "doc" / "results.md").write_text(results)
    (tmp_path / "README.md").write_text(page)
    return check_figures.main(["check_figures.py", str(tmp_path)]), check_figures.drift(str(tmp_path / "README.md"),
                                                                                      check_figures.results_figures(str(tmp_path / "doc" / "results.md")))


def test_a_figure_of_the_results_page_passes(tmp_path):
    assert check(tmp_path, "LSDAdvance reaches F 0.526 in 0.229 of LSD's time; 393 segments.\n") == (0, [])


def test_a_figure_not_on_the_results_page_fails_with_its_line(tmp_path):
    status, found = check(tmp_path, "Fine.\n\nLSD takes 98 % of the time.\n")
    assert status == 1 and found == [(3, "98")]


def test_a_rounded_figure_is_drift(tmp_path):
    assert check(tmp_path, "about 0.23 of LSD's time\n")[1] == [(1, "0.23")]


def test_a_figure_with_a_unit_is_a_figure(tmp_path):
    assert check(tmp_path, "0.25x LSD, 2.5 px, 12.9 ms, 3.2 GB\n")[1] == [(1, "0.25"), (1, "2.5"), (1, "12.9"), (1, "3.2")]


def test_numbers_of_one_significant_digit_are_not_figures(tmp_path):
    assert check(tmp_path, "scale 0.5, 60 px, budgets of 100, 200 and 400, 2x, 0.08\n") == (0, [])


def test_table_cells_and_headings_are_checked(tmp_path):
    found = check(tmp_path, "## F is 0.61\n\n| a | b |\n|---|---|\n| LSD | 0.435 |\n| FLD | 0.447 |\n")[1]
    assert found == [(1, "0.61"), (6, "0.447")]


def test_code_is_not_checked_but_its_comments_and_program_output_are(tmp_path):
    page = ("```sh\nlsd_advance_detect --zoom=150,60,300,200 --long=45  # prints 417 segments\n# 393 segments\n```\n"
            "```cpp\nd->setMergeThreshold(0.65);  // 0.526 on YorkUrban, 0.44 on the rest\n```\n"
            "```\nsegments / image:  393.0\n```\n")
    assert check(tmp_path, page)[1] == [(2, "417"), (6, "0.44"), (9, "393.0")]


def test_inline_code_link_targets_comments_names_and_versions_are_not_figures(tmp_path):
    page = ("`setLengthThresholdScale(0.75)`, [the table](doc/results.md#f-0.61), <!-- 0.99 -->\n"
            "graf1.png, H1to3p.xml, P1020831.jpg, x86_64, 640x480, 000030.png, OpenCV 4.6.0, g++ 12.2.0\n")
    assert check(tmp_path, page) == (0, [])


def test_allowed_numbers_are_years_versions_and_references(tmp_path):
    page = ("Guan et al., *Electronics* 2026, 15, 1006; OpenCV 4.10 on Debian 13 (issue 22, opencv/opencv#23210), "
            "from 2012; 16-bit vectors, contrast / 255, LBD's 256 bits.\n")
    assert check(tmp_path, page) == (0, [])


def test_the_results_page_itself_is_not_checked(tmp_path):
    status, _ = check(tmp_path, "no figure here\n", results=RESULTS + "\nand 0.77 of something\n")
    assert status == 0


def test_without_the_results_page_the_check_fails(tmp_path):
    (tmp_path / "doc").mkdir()
    (tmp_path / "README.md").write_text("0.526\n")
    assert check_figures.main(["check_figures.py", str(tmp_path)]) == 1


def test_the_repository_quotes_only_figures_of_its_results_page():
    assert check_figures.main(["check_figures.py", REPO]) == 0
