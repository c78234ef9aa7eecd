#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Usage: /usr/bin/python3 scripts/check_docs.py [REPO]

README.md and doc/ speak to a user of the repository, who has the repository and nothing else of
ours. This check fails (exit status 1, one line per problem: file, line, what is wrong) when

- they name an issue ("issue 12", "#12"; an upstream pull request, opencv#29349, is fine);
- they name a path outside the repository: one that climbs out of it (../shared/data; a link is
  resolved from its page, any other path from the repository's root) or an absolute path other
  than the system's (/usr, /etc, /opt, /tmp, /dev, /proc, /bin, /lib, /var and /path/to/...
  placeholders); the evaluation data is `$LSD_ADVANCE_DATA_DIR` (doc/data.md);
- their prose names a path of the repository that is not in the tree: a path whose first folder
  is a folder of the tree or of the file map (below), with `*` and `<name>` for any name, or a
  page (NAME.md) that is neither in doc/ nor at the root (commands in code blocks may name files
  they create, and are not checked for this);
- the file map, the table of doc/contributing.md's section "Where things are", does not match the
  tree. Its first column names folders (`test/`), files (`src/lsd_advance.cpp`) and patterns
  (`src/fast_lsd.*`). A folder stands for everything under it, except that every file directly in
  one of ITEMIZED (the library's sources and public headers, each a part a contributor looks for)
  must be named itself or by a pattern. The check names each entry that matches nothing in the
  tree (and where else the pages name it), and each file or folder that no entry covers.

The tree is git's list of files (tracked, and untracked ones that .gitignore does not ignore), or,
outside a git checkout, the files under REPO but build folders.
"""

import fnmatch
import os
import re
import subprocess
import sys

MAP_PAGE, MAP_SECTION = os.path.join("doc", "contributing.md"), "Where things are"
ITEMIZED = ("src", "include/opencv2", "include/opencv2/lsd_advance")
UNMAPPED = (".gitignore",)
SYSTEM_ROOTS = ("usr", "etc", "opt", "tmp", "dev", "proc", "sys", "bin", "lib", "var", "path")

ISSUE = re.compile(r"\b[Ii]ssues?\s+#?\d+|(?<![\w/.-])#\d+\b")
URL = re.compile(r"\b[a-z][a-z0-9+.-]*://\S+")
LINK = re.compile(r"\]\(([^)\s]*)[^)]*\)")
CLIMBING = re.compile(r"(?<![\w.~$}/-])((?:\.\./)+[\w.*<>-]*(?:/[\w.*<>-]+)*)")
ABSOLUTE = re.compile(r"(?<![\w.~$}\])>/-])(/[A-Za-z_][\w.-]*(?:/[\w.*<>-]+)*/?)")
RELATIVE = r"(?<![\w.~$}/-])(%s/[\w.*<>{},/-]*)"
PAGE_NAME = re.compile(r"(?<![\w./-])([\w-]+\.md)\b")
FENCE = re.compile(r"^\s*(```|~~~)")
OUTSIDE = ("names a path outside the repository (%s), which a user does not have (the evaluation data is "
           "$LSD_ADVANCE_DATA_DIR: doc/data.md)")


def tree_files(repo):
    try:
        out = subprocess.run(["git", "-C", repo, "ls-files", "--cached", "--others", "--exclude-standard"],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=True, universal_newlines=True)
        return sorted(f for f in set(out.stdout.splitlines()) if os.path.isfile(os.path.join(repo, f)))
    except (OSError, subprocess.CalledProcessError):
        files = []
        for root, dirs, names in os.walk(repo):
            dirs[:] = [d for d in dirs if d != ".git" and not d.startswith("build")]
            files += [os.path.relpath(os.path.join(root, n), repo).replace(os.sep, "/") for n in names]
        return sorted(files)


def pages(repo):
    doc = os.path.join(repo, "doc")
    names = sorted(n for n in os.listdir(doc) if os.path.isfile(os.path.join(doc, n))
                   and (n.endswith((".md", ".bib")) or n == "Doxyfile"))
    return [os.path.join(repo, "README.md")] + [os.path.join(doc, n) for n in names]


def page_lines(path):
    """(line number, text, in a fenced code block) of a page."""
    with open(path, encoding="utf-8") as f:
        fenced = False
        for number, line in enumerate(f.read().splitlines(), 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            yield number, line, fenced and path.endswith(".md")


def expand(pattern):
    """The glob patterns of a path as the docs write it: <name> and * for any name, {a,b} for either."""
    pattern = re.sub(r"<[^<>/]*>", "*", pattern)
    braces = re.search(r"\{([^{}]*)\}", pattern)
    if not braces:
        return [pattern]
    return [p for choice in braces.group(1).split(",")
            for p in expand(pattern[:braces.start()] + choice + pattern[braces.end():])]


def matches(pattern, files):
    """The files a path names: a folder (with or without its /) names the files under it."""
    found = []
    for p in expand(pattern.rstrip("/")):
        found += [f for f in files if fnmatch.fnmatchcase(f, p) or fnmatch.fnmatchcase(f, p + "/*")]
    return found


def escapes(path, base):
    """Whether path, read from the folder base (relative to the repository), leaves the repository."""
    depth = len([p for p in base.split("/") if p])
    for part in path.split("/"):
        if part == "..":
            depth -= 1
            if depth < 0:
                return True
        elif part not in ("", "."):
            depth += 1
    return False


def reference_problems(repo, files, roots):
    """(page, line, message) of issue numbers, paths outside the repository and paths not in the tree."""
    relative = re.compile(RELATIVE % "(?:%s)" % "|".join(re.escape(r) for r in sorted(roots)))
    problems = []
    for page in pages(repo):
        rel = os.path.relpath(page, repo)
        base = os.path.dirname(rel)
        for number, line, fenced in page_lines(page):
            text = re.sub(r"<!--.*?-->", " ", URL.sub(" ", line))
            for m in ISSUE.finditer(text):
                problems.append((rel, number, "names an issue ('%s'): say what the reader needs instead" % m.group(0)))
            links = [m.group(1) for m in LINK.finditer(text)] if rel.endswith(".md") else []
            for target in links:
                path = target.split("#")[0]
                if escapes(path, base):
                    problems.append((rel, number, "links outside the repository (%s)" % target))
                elif path and not re.match(r"^[a-z][a-z0-9+.-]*:", path) and not fenced:
                    inside = os.path.normpath(os.path.join(base, path)).replace(os.sep, "/")
                    if not matches(inside, files):
                        problems.append((rel, number, "links to %s, which is not in the tree" % inside))
            prose = LINK.sub("] ", text)
            for m in CLIMBING.finditer(prose):
                problems.append((rel, number, OUTSIDE % m.group(1)))
            for m in ABSOLUTE.finditer(prose):
                if m.group(1).split("/")[1] not in SYSTEM_ROOTS:
                    problems.append((rel, number, OUTSIDE % m.group(1)))
            if fenced:
                continue
            for m in relative.finditer(prose):
                path = m.group(1).rstrip(".,;:")
                if path.count(">") > path.count("<"):  # <folder with ELSED's src/>
                    path = path[:path.index(">")]
                if not matches(path, files):
                    problems.append((rel, number, "names %s, which is not in the tree" % path))
            for m in PAGE_NAME.finditer(prose):
                if m.group(1) not in files and "doc/" + m.group(1) not in files:
                    problems.append((rel, number, "names the page %s, which is neither in doc/ nor at the root"
                                                  % m.group(1)))
    return problems


def file_map(repo):
    """(line number, entry) of the file map's first column."""
    path = os.path.join(repo, MAP_PAGE)
    entries, inside = [], False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f.read().splitlines(), 1):
            if line.startswith("## "):
                inside = line[3:].strip() == MAP_SECTION
            elif inside and line.startswith("|") and not re.match(r"^\|[\s:|-]*$", line):
                first = line.strip().strip("|").split("|")[0]
                entries += [(number, e) for e in re.findall(r"`([^`]+)`", first)]
    return entries


def map_problems(repo, files):
    """(page, line, message) of the file map's stale entries and of what it leaves out."""
    entries = file_map(repo)
    if not entries:
        return [(MAP_PAGE, 1, "has no file map (a table in its section '%s')" % MAP_SECTION)]
    problems = []
    covered = set()
    for number, entry in entries:
        named = matches(entry, files)
        if not named:
            stem = re.split(r"[*<{]", entry)[0]
            elsewhere = ["%s:%d" % (os.path.relpath(page, repo), n) for page in pages(repo)
                         for n, line, _ in page_lines(page) if stem in line
                         and not (page.endswith(MAP_PAGE) and n == number)]
            problems.append((MAP_PAGE, number, "the file map names %s, which is not in the tree%s" % (
                entry, "; the pages name it also at " + ", ".join(elsewhere) if elsewhere else "")))
        for f in named:
            folder = os.path.dirname(f)
            if folder not in ITEMIZED or not entry.endswith("/") or entry.rstrip("/") != folder:
                covered.add(f)
    missing = [f for f in files if f not in covered and f not in UNMAPPED]
    itemized = [f for f in missing if os.path.dirname(f) in ITEMIZED]
    if itemized:
        problems.append((MAP_PAGE, entries[0][0], "the file map leaves out %s: name each file of %s in a row (a "
                                                 "pattern such as `src/name.*` names several)"
                         % (", ".join(itemized), " and ".join("%s/" % f for f in ITEMIZED))))
    others = {}
    for f in missing:
        if os.path.dirname(f) not in ITEMIZED:
            # the shallowest folder of the file that no entry covers at all
            parts = f.split("/")
            folder = next((("/".join(parts[:i]) + "/") for i in range(1, len(parts))
                           if not any(c.startswith("/".join(parts[:i]) + "/") for c in covered)), f)
            others.setdefault(folder, []).append(f)
    for folder, lost in sorted(others.items()):
        what = "%s (%d file(s): %s)" % (folder, len(lost), ", ".join(lost[:3]) + (", ..." if len(lost) > 3 else "")) \
            if folder.endswith("/") else folder
        problems.append((MAP_PAGE, entries[0][0], "the file map leaves out %s: add a row for it" % what))
    return problems


def main(argv):
    repo = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    files = tree_files(repo)
    roots = set(f.split("/")[0] for f in files if "/" in f)
    roots |= set(e.split("/")[0] for _, e in file_map(repo) if "/" in e)
    # an entry of the map that is not in the tree is reported once, by the map's check
    entries = set((MAP_PAGE, n, "names %s, which is not in the tree" % e) for n, e in file_map(repo))
    problems = [p for p in reference_problems(repo, files, roots) if p not in entries] + map_problems(repo, files)
    for path, number, message in problems:
        print("%s:%d: %s" % (path, number, message), file=sys.stderr)
    print("check_docs: %d page(s), %d file(s) in the tree, %d problem(s)" % (len(pages(repo)), len(files), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
