# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Tests of scripts/check_figures.py, the check that every figure of the docs quotes its cell of
doc/results.md."""

import os
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "scripts"))
import check_figures  # noqa: E402

RESULTS = """# Results

## YorkUrban, all images

| method | F | ms / image (median) | time / LSD (median) |
|---|---:|---:|---:|
| LSD | 0.435 | 22.5 | 1.000 |
| LSDAdvance, fastest preset | 0.452 | 2.4 | 0.110 |
| LSDAdvance | 0.526 | 5.2 | 0.229 |

## Budgets

| method | lines (budget) | matches | consistent |
|---|---:|---:|---:|
| LSD | 100 | 7.4 | 4.8 |
| LSDAdvance | 100 | 9.6 | 9.4 |
| LSD | 200 | 16.8 | 12.4 |
| LSDAdvance | 200 | 20.8 | 18.2 |

## Two threads

YorkUrban, 1 thread:

| method | ms / image (median) |
|---|---:|
| LSDAdvance | 3.3 |

YorkUrban, 2 threads:

| method | ms / image (median) |
|---|---:|
| LSDAdvance | 1.9 |

```
LSDAdvance: 393 segments, 33.7 ms
```
"""
ALL = "YorkUrban, all images"


def check(tmp_path, page, results=RESULTS):
    """(status, [(line, message)]) of the check on a repository whose README is page."""
    (tmp_path / "doc").mkdir(exist_ok=True)
    (tmp_path / "doc" / "results.md").write_text(results)
    (tmp_path / "README.md").write_text(page)
    return (check_figures.main(["check_figures.py", str(tmp_path)]),
            check_figures.problems_of(page, check_figures.Results(results)))


def lines_of(problems):
    return [line for line, _ in problems]


def test_a_figure_quoted_with_the_key_of_its_cell_passes(tmp_path):
    page = "F <!-- cell: %s; LSDAdvance; F -->0.526 in <!-- cell: %s; LSDAdvance; time / LSD (median) -->0.229\n" % (
        ALL, ALL)
    assert check(tmp_path, page) == (0, [])


def test_a_figure_that_differs_from_its_cell_fails_and_says_what_the_cell_holds(tmp_path):
    # the stale figure of doc/algorithm.md: 0.449 quoted for PRESET_FASTEST, whose cell says 0.452
    status, found = check(tmp_path, "fine\n\nF <!-- cell: %s; LSDAdvance, fastest preset; F -->0.449\n" % ALL)
    assert status == 1 and lines_of(found) == [3]
    assert "holds 0.452" in found[0][1] and "write 0.452" in found[0][1]


def test_a_figure_of_another_cell_fails_even_when_the_page_holds_it_elsewhere(tmp_path):
    # 0.435 is on the page (LSD's F), but not in the cell this key names
    status, found = check(tmp_path, "F <!-- cell: %s; LSDAdvance; F -->0.435\n" % ALL)
    assert status == 1 and "holds 0.526" in found[0][1]


def test_a_figure_without_a_key_fails_and_the_message_gives_the_key_of_each_cell_that_holds_it(tmp_path):
    status, found = check(tmp_path, "LSDAdvance reaches F 0.526.\n")
    assert status == 1 and lines_of(found) == [1]
    assert "<!-- cell: %s; LSDAdvance; F -->0.526" % ALL in found[0][1]


def test_a_figure_in_no_cell_fails_and_says_how_to_quote(tmp_path):
    status, found = check(tmp_path, "LSD takes 98 % of the time, 0.23 of it in stage 0\n")
    assert status == 1 and lines_of(found) == [1, 1]
    assert "is no cell of doc/results.md" in found[0][1] and "<!-- cell: TABLE; ROW; COLUMN -->" in found[0][1]


def test_a_row_is_told_by_its_first_cells_when_the_first_is_not_enough(tmp_path):
    good = "<!-- cell: Budgets; LSDAdvance; 200; matches -->20.8 matches\n"
    assert check(tmp_path, good) == (0, [])
    status, found = check(tmp_path, "<!-- cell: Budgets; LSDAdvance; matches -->20.8 matches\n")
    assert status == 1 and "names 2 cells" in found[0][1]
    assert "'Budgets; LSDAdvance; 100; matches' or 'Budgets; LSDAdvance; 200; matches'" in found[0][1]


def test_a_table_is_told_by_its_number_when_its_section_has_several(tmp_path):
    assert check(tmp_path, "<!-- cell: Two threads (table 2); LSDAdvance; ms / image (median) -->1.9 ms\n") == (0, [])
    status, found = check(tmp_path, "<!-- cell: Two threads; LSDAdvance; ms / image (median) -->1.9 ms\n")
    assert status == 1 and "(table 1)" in found[0][1] and "(table 2)" in found[0][1]


def test_a_key_that_names_no_cell_says_which_part_is_wrong(tmp_path):
    problems = check(tmp_path, "<!-- cell: Kitti; LSD; F -->0.435\n<!-- cell: %s; LSD; G -->0.435\n"
                               "<!-- cell: %s; ELSED; F -->0.435\n<!-- cell: %s; F -->0.435\n" % (ALL, ALL, ALL))[1]
    assert [m.split(":")[0] for _, m in problems] == ["0.435"] * 4
    assert "no section 'Kitti'" in problems[0][1] and ALL in problems[0][1]
    assert "no column 'G'" in problems[1][1]
    assert "no row 'ELSED'" in problems[2][1] and "LSDAdvance, fastest preset" in problems[2][1]
    assert "is not 'TABLE; ROW; COLUMN'" in problems[3][1]


def test_the_suggested_key_of_each_cell_names_that_cell(tmp_path):
    results = check_figures.Results(RESULTS)
    for table in results.tables:
        for row in range(len(table.rows)):
            for column in range(1, len(table.header)):
                assert results.resolve(results.key(table, row, column)) == (table, row, column)


def test_a_copied_table_must_equal_its_table_and_update_copies_it_again(tmp_path):
    table = RESULTS.split("## YorkUrban, all images\n\n")[1].split("\n\n")[0]
    page = "Results:\n\n<!-- copy: %s -->\n%s\n<!-- /copy -->\n\nmore\n" % (ALL, table)
    assert check(tmp_path, page) == (0, [])
    stale = page.replace("| 0.526 |", "| 0.529 |")
    status, found = check(tmp_path, stale)
    assert status == 1 and lines_of(found) == [3] and "--update" in found[0][1]
    assert check_figures.main(["check_figures.py", "--update", str(tmp_path)]) == 0
    assert (tmp_path / "README.md").read_text() == page


def test_update_takes_every_quoted_figure_again_from_its_cell(tmp_path, capsys):
    page = "F <!-- cell: %s; LSDAdvance, fastest preset; F -->0.449 and 12 ms\n" % ALL
    check(tmp_path, page)
    assert check_figures.main(["check_figures.py", "--update", str(tmp_path)]) == 1   # 12 has no key
    assert (tmp_path / "README.md").read_text() == page.replace("0.449", "0.452")
    assert "README.md:1: 0.449 -> 0.452" in capsys.readouterr().out


def test_numbers_of_one_significant_digit_parameters_in_code_and_data_set_sizes_are_not_figures(tmp_path):
    page = ("scale 0.5, 60 px, budgets of 100, 200 and 400, 2x, 0.08; `maxPerpendicularOffset` `1.5` px;\n"
            "all 51 images, the 25 odd images, 95 frames, 50 pairs, 11 views\n")
    assert check(tmp_path, page) == (0, [])


def test_table_cells_and_headings_are_checked(tmp_path):
    found = check(tmp_path, "## F is 0.61\n\n| a | b |\n|---|---|\n| LSD | 0.435 |\n")[1]
    assert lines_of(found) == [1, 5]


def test_code_is_not_checked_but_its_comments_and_program_output_are(tmp_path):
    page = ("```sh\nlsd_advance_detect --zoom=150,60,300,200 --long=45  # prints 417 segments\n```\n"
            "```cpp\nd->setMergeThreshold(0.65);  // 0.526 on YorkUrban\n```\n"
            "```\nsegments / image:  393.0\n```\n")
    found = check(tmp_path, page)[1]
    assert lines_of(found) == [2, 5, 8] and "in a code block" in found[0][1]


def test_inline_code_link_targets_comments_names_and_versions_are_not_figures(tmp_path):
    page = ("`setLengthThresholdScale(0.75)`, [the table](doc/results.md#f-0.61), <!-- 0.99 -->\n"
            "<!-- a comment\nover 0.99 lines -->\n"
            "graf1.png, H1to3p.xml, P1020831.jpg, x86_64, 640x480, 000030.png, OpenCV 4.6.0, g++ 12.2.0\n")
    assert check(tmp_path, page) == (0, [])


def test_allowed_numbers_are_years_versions_and_references(tmp_path):
    page = ("Guan et al., *Electronics* 2026, 15, 1006; OpenCV 4.10 on Debian 13 (opencv/opencv#23210), "
            "from 2012; 16-bit vectors, contrast / 255, LBD's 256 bits.\n")
    assert check(tmp_path, page) == (0, [])


def test_the_results_page_itself_is_not_checked(tmp_path):
    status, _ = check(tmp_path, "no figure here\n", results=RESULTS + "\nand 0.77 of something\n")
    assert status == 0


def test_without_the_results_page_the_check_fails(tmp_path):
    (tmp_path / "doc").mkdir()
    (tmp_path / "README.md").write_text("0.526\n")
    assert check_figures.main(["check_figures.py", str(tmp_path)]) == 1


def test_the_repository_quotes_each_figure_from_its_cell():
    assert check_figures.main(["check_figures.py", REPO]) == 0
