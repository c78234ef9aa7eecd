#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: scripts/docs.sh [output dir]        (default: <repo>/build-docs)
#
# Builds the HTML API pages of lsd_advance with doxygen (doc/Doxyfile): the public headers,
# README.md as the main page and every doc/*.md page, with the citations of doc/lsd_advance.bib.
# Any doxygen warning fails the build: the warnings are printed (file:line: text, paths relative
# to the repository) and the script exits with status 1. Takes about a second.
#
# Needs: doxygen, and bibtex + perl for the citations (Debian: doxygen texlive-binaries).
# OpenCV's tag file (opencv-doc) is not used: reading it takes 20 s and gives ~900 warnings of
# its own.
set -euo pipefail

REPO="$(cd "$(dirname "$0")/.." && pwd)"
OUT="${1:-$REPO/build-docs}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
cd "$REPO"

for tool in doxygen perl bibtex; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "[docs] ERROR: '$tool' not found. On Debian: apt-get install doxygen texlive-binaries" >&2
    exit 1
  fi
done

# Without texlive-base, bibtex has no search path at all: let it find the .bib copy and the
# style file that doxygen writes into its output folder (the trailing ':' keeps any default).
export BIBINPUTS=".:${BIBINPUTS:-}" BSTINPUTS=".:${BSTINPUTS:-}"

# Start from an empty html/ so that no page of an earlier run survives.
rm -rf "$OUT/html"
LOG="$OUT/doxygen-warnings.log"
: > "$LOG"

EXTRA=("OUTPUT_DIRECTORY = \"$OUT\"" "WARN_LOGFILE = \"$LOG\"")

t0=$(date +%s%N)
status=0
{ cat doc/Doxyfile; printf '%s\n' "${EXTRA[@]}"; } | doxygen - > "$OUT/doxygen.out" 2>&1 || status=$?
t1=$(date +%s%N)

# Readable warnings: paths relative to the repository; doxygen reports some of them at
# "<symbol>:1:" (documentation it copied), which are mapped to the symbol's header line.
readable_warnings() {
  sed -e "s|$REPO/||g" "$LOG" | while IFS= read -r line; do
    if [[ "$line" =~ ^\<([A-Za-z_][A-Za-z0-9_]*)\>:1:(.*)$ ]]; then
      where="$(grep -rn -m1 -E "\\b${BASH_REMATCH[1]}\\s*\\(" include | head -n1 | cut -d: -f1,2 || true)"
      echo "${where:-<${BASH_REMATCH[1]}>:1}:${BASH_REMATCH[2]}"
    else
      echo "$line"
    fi
  done | awk '!seen[$0]++'
}

# Doxygen does not report a markdown image it cannot find (it writes a dead <img>), nor a dead
# link to a file that is not a page: check every relative link and image of README.md and
# doc/*.md (outside code) against the file system, as GitHub resolves them, and require images
# to be under doc/ (doxygen's IMAGE_PATH).
check_markdown_links() {
  awk '
    /^[ \t]*(```|~~~)/ { fence = !fence; next }
    fence { next }
    {
      line = $0
      gsub(/`[^`]*`/, "", line)
      while (match(line, /\]\([^)]*\)/)) {
        image = RSTART > 1 && index(substr(line, 1, RSTART - 1), "![") > 0
        target = substr(line, RSTART + 2, RLENGTH - 3)
        line = substr(line, RSTART + RLENGTH)
        sub(/[ \t].*$/, "", target)
        sub(/#.*$/, "", target)
        if (target == "" || target ~ /^[A-Za-z][A-Za-z0-9+.-]*:/) continue
        print FILENAME "\t" FNR "\t" image "\t" target
      }
    }' README.md doc/*.md |
  while IFS=$'\t' read -r file line image target; do
    resolved="$(dirname "$file")/$target"
    if [ ! -e "$resolved" ]; then
      echo "$file:$line: error: link target '$target' does not exist (looked for $resolved)"
    elif [ "$image" = 1 ] && [[ "$(realpath "$resolved")" != "$REPO/doc/"* ]]; then
      echo "$file:$line: error: image '$target' is not under doc/ (doxygen's IMAGE_PATH): put it in doc/pics/"
    fi
  done
}
check_markdown_links >> "$LOG"

count=$(grep -c . "$LOG" || true)
if [ "$status" -ne 0 ] || [ "$count" -ne 0 ]; then
  echo "[docs] FAILED: doxygen exit status $status, $count warning line(s) (every warning is an error):" >&2
  readable_warnings >&2
  if [ -s "$OUT/doxygen.out" ]; then
    echo "[docs] doxygen output:" >&2
    sed -e "s|$REPO/||g" "$OUT/doxygen.out" >&2
  fi
  echo "[docs] full log: $LOG" >&2
  exit 1
fi
ms=$(( (t1 - t0) / 1000000 ))
printf '[docs] OK: no warnings, %d.%01d s. HTML: %s/html/index.html\n' $((ms / 1000)) $((ms % 1000 / 100)) "$OUT"
