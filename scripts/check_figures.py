#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Usage: /usr/bin/python3 scripts/check_figures.py [--update] [REPO]

Every measured number lives in one page, doc/results.md, which scripts/benchmark.sh generates
from one run. README.md and the other pages of doc/ quote a figure of it by naming its cell: an
HTML comment with the table, the row and the column, separated by semicolons, right before the
figure (a comment after it would swallow the space that follows in Doxygen's pages):

    F <!-- cell: YorkUrban-LineSegment, all 51 images; LSDAdvance, fastest preset; F -->0.452

- the table is the heading of its section of doc/results.md (without "## "); when the section
  holds several tables with that row and column, add " (table N)", N counting the section's
  tables from 1;
- the row is given by its first cell, or by its first cells, each followed by a semicolon, when
  the first is not enough (a budget table: `LSDAdvance; 200`);
- the column is the text of its header.

A whole table is copied between `<!-- copy: TABLE -->` and `<!-- /copy -->` (TABLE as above).
The check fails (exit status 1, one line per problem: file, line, what to write instead) when a
quoted figure differs from its cell, when a key names no cell or several, when a copy differs
from its table, and when a page types a figure without a key; for a figure without a key it
prints the keys of the cells that hold it, ready to paste. `--update` rewrites every quoted
figure and every copy from doc/results.md (scripts/benchmark.sh runs it after a run) and prints
each figure it changed, whose sentence then needs a reading.

A figure is a number of two or more significant digits (leading zeros and the trailing zeros
of an integer do not count: 0.229, 1564, 3.7, 98 and 0.25x are figures; 0.5, 60, 400 and 2x are
not), written in prose, a heading, a table cell, a comment of a code block or a block of program
output (a fenced block without a language; a figure there has no place for a key: quote it in
prose). Not figures: the commands and code of a fenced block with a language and `inline code`
(parameters, options: write a parameter's value as code, `maxPerpendicularOffset` `1.5`), digits
inside a name (graf1, H1to3p, x86_64, P1020831.jpg, 640x480), versions with two dots (4.6.0),
link targets and HTML comments, the sizes of the data sets (51 images, 95 frames) and the few
numbers of ALLOWED, each with its reason.
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
    (r"\w#\d+\b", "upstream pull-request numbers (opencv#29349)"),
    (r"\b\d+-bit\b|/ 255\b|\b256 bits\b", "data formats: bit widths, 8-bit gray levels, LBD's 256-bit descriptor"),
    (r"\b\d+ (?:(?:odd|even|consecutive) )?(?:images|frames|pairs|views)\b", "sizes of the data sets"),
]
UNITS = r"(?:x|px|ms|kB|MB|GB|M|k|s|°)"
# A number, with an optional unit, as a whole word; a word with other letters is a name.
NUMBER = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?)%s?(?![\w.]*\w)" % UNITS)
# A quoted figure: the key of its cell, then the number (and its attached unit).
QUOTE = re.compile(r"<!--\s*cell:\s*(.*?)\s*-->(\d+(?:\.\d+)?)(%s?)(?![\w.]*\w)" % UNITS)
COPY_BEGIN = re.compile(r"^\s*<!--\s*copy:\s*(.*?)\s*-->\s*$")
COPY_END = re.compile(r"^\s*<!--\s*/copy\s*-->\s*$")
TABLE_NUMBER = re.compile(r"^(.*?)\s*\(table (\d+)\)$")
FENCE = re.compile(r"^\s*```\s*([\w+-]*)")
COMMENT = {"sh": "#", "bash": "#", "shell": "#", "python": "#", "cmake": "#", "yaml": "#", "cpp": "//", "c++": "//",
           "c": "//"}
HOW = "(scripts/check_figures.py says how to quote a cell)"


def significant_digits(number):
    digits = number.replace(".", "").lstrip("0")
    return len(digits if "." in number else digits.rstrip("0"))


def cells_of(line):
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


def number_of(cell):
    """The number a cell holds, or None when it holds no number or several."""
    numbers = NUMBER.findall(cell)
    return numbers[0] if len(numbers) == 1 else None


class Table(object):
    """A table of doc/results.md: its section's heading, its place among the section's tables (from
    1), its header, its rows (lists of cells) and the page's lines it spans."""

    def __init__(self, heading, number, header, rows, lines):
        self.heading, self.number, self.header, self.rows, self.lines = heading, number, header, rows, lines

    def name(self, numbered):
        return "%s (table %d)" % (self.heading, self.number) if numbered else self.heading


def results_tables(markdown):
    """The tables of a results page (a header row, a separator row, then rows), in page order."""
    tables, heading, number = [], "", 0
    lines = markdown.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("## "):
            heading, number = lines[i][3:].strip(), 0
        if (lines[i].startswith("|") and i + 1 < len(lines)
                and re.match(r"^\|(\s*:?-+:?\s*\|)+\s*$", lines[i + 1])):
            end = i + 2
            while end < len(lines) and lines[end].startswith("|"):
                end += 1
            number += 1
            tables.append(Table(heading, number, cells_of(lines[i]), [cells_of(l) for l in lines[i + 2:end]],
                                lines[i:end]))
            i = end
            continue
        i += 1
    return tables


class Results(object):
    """doc/results.md: finds the cell of a key, and the key of a cell."""

    def __init__(self, markdown):
        self.tables = results_tables(markdown)

    def section(self, heading):
        return [t for t in self.tables if t.heading == heading]

    def resolve(self, key):
        """(table, row index, column index), or raises ValueError with what is wrong and what to write."""
        found = self.cells_named(key)
        if len(found) > 1:
            raise ValueError("the key '%s' names %d cells; name one: %s"
                             % (key, len(found), " or ".join("'%s'" % self.key(*f) for f in found[:4])))
        return found[0]

    def cells_named(self, key):
        """The cells a key names (at least one), or raises ValueError with what names none."""
        parts = [p.strip() for p in key.split(";")]
        if len(parts) < 3 or not all(parts):
            raise ValueError("the key '%s' is not 'TABLE; ROW; COLUMN'" % key)
        name, row_key, column = parts[0], parts[1:-1], parts[-1]
        numbered = TABLE_NUMBER.match(name)
        heading = numbered.group(1) if numbered and self.section(numbered.group(1)) else name
        section = self.section(heading)
        if not section:
            raise ValueError("doc/results.md has no section '%s'; its sections: %s"
                             % (heading, "; ".join(sorted(set(t.heading for t in self.tables)))))
        if heading != name:
            section = [t for t in section if t.number == int(numbered.group(2))]
            if not section:
                raise ValueError("section '%s' has no table %s" % (heading, numbered.group(2)))
        found = []
        for table in section:
            if column not in table.header:
                continue
            rows = [r for r, cells in enumerate(table.rows) if cells[:len(row_key)] == row_key]
            found += [(table, r, table.header.index(column)) for r in rows]
        if not found:
            columns = sorted(set(c for t in section for c in t.header[1:]))
            rows = sorted(set(cells[0] for t in section for cells in t.rows))
            if column not in columns:
                raise ValueError("no column '%s' in section '%s'; its columns: %s" % (column, heading, "; ".join(columns)))
            raise ValueError("no row '%s' in section '%s'; its rows: %s" % ("; ".join(row_key), heading, "; ".join(rows)))
        return found

    def key(self, table, row, column):
        """The shortest key of a cell: the fewest leading cells that tell its row, the table's number
        only when the section needs it."""
        cells = table.rows[row]
        for count in range(1, len(cells)):
            for numbered in (False, True):
                key = "%s; %s; %s" % (table.name(numbered), "; ".join(cells[:count]), table.header[column])
                try:
                    if self.cells_named(key) == [(table, row, column)]:
                        return key
                except ValueError:
                    pass
        return None

    def cells_holding(self, figure):
        return [(t, r, c) for t in self.tables for r, cells in enumerate(t.rows) for c, cell in enumerate(cells)
                if c > 0 and c < len(t.header) and number_of(cell) == figure]

    def copy(self, name):
        """The lines of the table a copy block names."""
        numbered = TABLE_NUMBER.match(name)
        heading, number = (numbered.group(1), int(numbered.group(2))) if numbered else (name, 1)
        tables = [t for t in self.section(heading) if t.number == number]
        if not tables:
            raise ValueError("doc/results.md has no table '%s'; its sections: %s"
                             % (name, "; ".join(sorted(set(t.heading for t in self.tables)))))
        return tables[0].lines


def figures_in(text):
    """The figures of a piece of prose that has no quoted figure left in it."""
    text = re.sub(r"`[^`]*`", " ", text)                       # inline code
    text = re.sub(r"\]\([^)]*\)", "] ", text)                   # link targets
    text = re.sub(r"\{#[\w-]+\}|@cite \w+", " ", text)          # Doxygen anchors and citations
    for pattern, _ in ALLOWED:
        text = re.sub(pattern, " ", text)
    return [m.group(1) for m in NUMBER.finditer(text) if significant_digits(m.group(1)) >= 2]


def scanned_lines(markdown):
    """(line number, text, kind) of a Markdown page: kind "prose" (with its quotes still in it),
    "code" (a comment of a code block or program output) or "copy" (the lines of a copy block,
    text being the copied table's name, once, at its first line)."""
    lines = markdown.splitlines()
    in_comment = False
    language = None  # inside a fenced block: its language ("" for output)
    copying = None
    for number, line in enumerate(lines, 1):
        if copying is not None:
            if COPY_END.match(line):
                copying = None
            continue
        begin = COPY_BEGIN.match(line)
        if begin and language is None:
            copying = begin.group(1)
            yield number, copying, "copy"
            continue
        # HTML comments other than keys, also across lines
        text = ""
        rest = line
        while rest:
            if in_comment:
                end = rest.find("-->")
                if end < 0:
                    rest = ""
                else:
                    in_comment, rest = False, rest[end + 3:]
                continue
            start = rest.find("<!--")
            if start < 0:
                text, rest = text + rest, ""
            elif rest[start:].lstrip("<!- \t").startswith("cell:") and "-->" in rest[start:]:
                end = rest.index("-->", start) + 3
                text, rest = text + rest[:end], rest[end:]
            else:
                text, rest, in_comment = text + rest[:start] + " ", rest[start + 4:], True
        fence = FENCE.match(text)
        if fence:
            language = fence.group(1).lower() if language is None else None
            continue
        if language is None:
            yield number, text, "prose"
        elif language in ("", "text", "output", "console"):
            yield number, text, "code"
        elif language in COMMENT:
            marker = COMMENT[language]
            position = text.find(marker) if text.lstrip().startswith(marker) else text.find(" " + marker + " ")
            if position >= 0:
                yield number, text[position:], "code"


def problems_of(markdown, results):
    """(line number, message) of every figure of a page that does not quote its cell."""
    problems = []
    lines = markdown.splitlines()
    for number, text, kind in scanned_lines(markdown):
        if kind == "copy":
            try:
                table = results.copy(text)
            except ValueError as e:
                problems.append((number, "copy: %s" % e))
                continue
            copied = lines[number:number + len(table)]
            if copied != table or number + len(table) >= len(lines) or not COPY_END.match(lines[number + len(table)]):
                problems.append((number, "the copy of '%s' is not doc/results.md's table: "
                                         "scripts/check_figures.py --update copies it again" % text))
            continue
        for quote in QUOTE.finditer(text):
            key, figure = quote.group(1), quote.group(2)
            try:
                table, row, column = results.resolve(key)
            except ValueError as e:
                problems.append((number, "%s%s: %s %s" % (figure, quote.group(3), e, HOW)))
                continue
            held = number_of(table.rows[row][column])
            if held != figure:
                problems.append((number, "%s quotes '%s', which holds %s in doc/results.md: write %s (or run "
                                         "scripts/check_figures.py --update)"
                                 % (figure, key, table.rows[row][column] or "nothing", held or "no figure")))
        for figure in figures_in(QUOTE.sub(" ", text)):
            problems.append((number, unquoted(figure, kind, results)))
    return problems


def unquoted(figure, kind, results):
    """What to do with a figure typed without the key of its cell."""
    if kind == "code":
        return ("%s, in a code block, cannot name its cell of doc/results.md: quote it in the prose, or "
                "leave the measured number out" % figure)
    cells = results.cells_holding(figure)
    if not cells:
        return ("%s is no cell of doc/results.md: quote the cell it comes from as <!-- cell: TABLE; ROW; "
                "COLUMN -->%s %s, or write a parameter's value as `code`" % (figure, figure, HOW))
    keys = ["<!-- cell: %s -->%s" % (results.key(*cell), figure) for cell in cells[:4]]
    more = " (and %d more cells)" % (len(cells) - 4) if len(cells) > 4 else ""
    return "%s has no key: write the one of its cell, %s%s" % (figure, " or ".join(keys), more)


def updated(markdown, results):
    """The page with every quoted figure and copy taken again from doc/results.md, and the list of
    (line number, old figure, new figure, key) of the figures that changed."""
    changes = []
    out = []
    lines = markdown.splitlines(True)
    copying = False
    for number, line in enumerate(lines, 1):
        if copying:
            if COPY_END.match(line):
                copying = False
                out.append(line)
            continue
        begin = COPY_BEGIN.match(line)
        if begin:
            try:
                table = results.copy(begin.group(1))
            except ValueError:
                out.append(line)
                continue
            copying = True
            out.append(line)
            out.extend(l + "\n" for l in table)
            continue

        def requote(m):
            try:
                table, row, column = results.resolve(m.group(1))
            except ValueError:
                return m.group(0)
            held = number_of(table.rows[row][column])
            if held is None or held == m.group(2):
                return m.group(0)
            changes.append((number, m.group(2), held, m.group(1)))
            return m.group(0)[:m.start(2) - m.start(0)] + held + m.group(3)
        out.append(QUOTE.sub(requote, line))
    return "".join(out), changes


def pages(repo):
    doc = os.path.join(repo, "doc")
    return [os.path.join(repo, "README.md")] + sorted(
        os.path.join(doc, name) for name in os.listdir(doc) if name.endswith(".md") and name != "results.md")


def main(argv):
    args = argv[1:]
    update = "--update" in args
    args = [a for a in args if a != "--update"]
    repo = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    results_page = os.path.join(repo, "doc", "results.md")
    if not os.path.isfile(results_page):
        print("ERROR: check_figures: no %s (bash scripts/benchmark.sh writes it)" % results_page, file=sys.stderr)
        return 1
    with open(results_page, encoding="utf-8") as f:
        results = Results(f.read())
    problems = []
    for page in pages(repo):
        with open(page, encoding="utf-8") as f:
            markdown = f.read()
        path = os.path.relpath(page, repo)
        if update:
            markdown, changes = updated(markdown, results)
            with open(page, "w", encoding="utf-8") as f:
                f.write(markdown)
            for number, old, new, key in changes:
                print("%s:%d: %s -> %s (%s): read the sentence again" % (path, number, old, new, key))
        problems += [(path, number, message) for number, message in problems_of(markdown, results)]
    for path, number, message in problems:
        print("%s:%d: %s" % (path, number, message), file=sys.stderr)
    print("check_figures: %d page(s), %d figure(s) that do not quote their cell of doc/results.md"
          % (len(pages(repo)), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
