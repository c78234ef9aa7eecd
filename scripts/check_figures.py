#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Usage: /usr/bin/python3 scripts/check_figures.py [REPO]

Every measured number lives in one page, doc/results.md, which scripts/benchmark.sh generates
from one run. This check fails (exit status 1, one line per figure: file, line, figure) when
README.md or another page of doc/ quotes a figure that doc/results.md does not hold, so a
figure typed into the docs cannot drift from the measurements.

A figure is a number of two or more significant digits (leading zeros and the trailing zeros
of an integer do not count: 0.229, 1564, 3.7, 98 and 0.25x are figures; 0.5, 60, 400 and 2x are
not), written in prose, a heading, a table cell, a comment of a code block or a block of program
output (a fenced block without a language). It must appear in doc/results.md exactly as
written: 0.23 where the page says 0.229 is drift. Not figures: the commands and code of a
fenced block with a language and `inline code` (parameters, options: write a parameter's value
as code, `maxPerpendicularOffset` `1.5`), digits inside a name
(graf1, H1to3p, x86_64, P1020831.jpg, 640x480), versions with two dots (4.6.0), link targets
and HTML comments, and the few numbers of ALLOWED, each with its reason.
"""

import os
import re
import sys

# Numbers that are not measurements, as the text around them shows it (regular expressions).
ALLOWED = [
    (r"\bElectronics\W* 2026, 15, 1006\b", "the paper's year, volume and article number"),
    (r"\b(?:19[5-9]\d|20[0-4]\d)\b", "years (publications, data sets)"),
    (r"\b(?:OpenCV|opencv) 4\.\d+\b", "OpenCV versions"),
    (r"\bDebian 1[23]\b", "Debian releases"),
    (r"\bissues? \d+\b|#\d+\b", "issue and pull-request numbers"),
    (r"\b\d+-bit\b|/ 255\b|\b256 bits\b", "data formats: bit widths, 8-bit gray levels, LBD's 256-bit descriptor"),
]
# A number, with an optional unit, as a whole word; a word with other letters is a name.
NUMBER = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?)(?:x|px|ms|kB|MB|GB|M|k|s|°)?(?![\w.]*\w)")
FENCE = re.compile(r"^\s*```\s*([\w+-]*)")
COMMENT = {"sh": "#", "bash": "#", "shell": "#", "python": "#", "cmake": "#", "yaml": "#", "cpp": "//", "c++": "//",
           "c": "//"}


def significant_digits(number):
    digits = number.replace(".", "").lstrip("0")
    return len(digits if "." in number else digits.rstrip("0"))


def figures_in(text):
    """The figures of a piece of prose."""
    text = re.sub(r"`[^`]*`", " ", text)                       # inline code
    text = re.sub(r"\]\([^)]*\)", "] ", text)                   # link targets
    text = re.sub(r"\{#[\w-]+\}|@cite \w+", " ", text)          # Doxygen anchors and citations
    for pattern, _ in ALLOWED:
        text = re.sub(pattern, " ", text)
    return [m.group(1) for m in NUMBER.finditer(text) if significant_digits(m.group(1)) >= 2]


def checked_lines(markdown):
    """(line number, the part of the line that is prose, output or a comment) of a Markdown page."""
    markdown = re.sub(r"<!--.*?-->", lambda m: "\n" * m.group(0).count("\n"), markdown, flags=re.S)
    language = None  # inside a fenced block: its language ("" for output)
    for number, line in enumerate(markdown.splitlines(), 1):
        fence = FENCE.match(line)
        if fence:
            language = fence.group(1).lower() if language is None else None
            continue
        if language is None or language in ("", "text", "output", "console"):
            yield number, line
        elif language in COMMENT:
            marker = COMMENT[language]
            position = line.find(marker) if line.lstrip().startswith(marker) else line.find(" " + marker + " ")
            if position >= 0:
                yield number, line[position:]


def results_figures(results_page):
    with open(results_page, encoding="utf-8") as f:
        return set(m.group(1) for m in NUMBER.finditer(f.read()))


def drift(page, known):
    """(line number, figure) of the figures of page that are not in known."""
    with open(page, encoding="utf-8") as f:
        markdown = f.read()
    return [(number, figure) for number, text in checked_lines(markdown) for figure in figures_in(text)
            if figure not in known]


def pages(repo):
    doc = os.path.join(repo, "doc")
    return [os.path.join(repo, "README.md")] + sorted(
        os.path.join(doc, name) for name in os.listdir(doc) if name.endswith(".md") and name != "results.md")


def main(argv):
    repo = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    results_page = os.path.join(repo, "doc", "results.md")
    if not os.path.isfile(results_page):
        print("ERROR: check_figures: no %s (bash scripts/benchmark.sh writes it)" % results_page, file=sys.stderr)
        return 1
    known = results_figures(results_page)
    problems = [(os.path.relpath(page, repo), number, figure) for page in pages(repo)
                for number, figure in drift(page, known)]
    for path, number, figure in problems:
        print("%s:%d: %s is not in doc/results.md: link to the measurement there instead of typing it "
              "(scripts/check_figures.py says what a figure is)" % (path, number, figure), file=sys.stderr)
    checked = len(pages(repo))
    print("check_figures: %d page(s), %d figure(s) not in doc/results.md" % (checked, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
