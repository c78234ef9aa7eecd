#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: scripts/fetch_opencv_source.sh [DEST]
#
# Fetches Debian's OpenCV source package of exactly the version of the installed libopencv-dev
# and extracts it (with Debian's patches, contrib under DEST/contrib/modules) into DEST.
# Default DEST: ${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance/opencv-<upstream version>, the
# location CMake looks at when -DOPENCV_SOURCE_DIR is not given.
# Enables deb-src (deb822 *.sources or classic sources.list) when needed. Idempotent: does
# nothing when DEST already holds the matching version. Uses sudo only when not root.
set -euo pipefail

log() { echo "[fetch_opencv_source] $*" >&2; }
die() { log "ERROR: $*"; exit 1; }

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else SUDO="__no_root__"; fi
fi
as_root() {
  if [ "$SUDO" = "__no_root__" ]; then die "need root (or sudo) to run: $*"; fi
  $SUDO "$@"
}

command -v dpkg-query >/dev/null 2>&1 || die "not a Debian-like system (no dpkg-query)"
PKG_INFO="$(dpkg-query -W -f='${source:Package} ${source:Version} ${source:Upstream-Version}' libopencv-dev 2>/dev/null || true)"
[ -n "$PKG_INFO" ] || die "libopencv-dev is not installed (run scripts/install_deps.sh)"
read -r SRC_PKG SRC_VERSION UPSTREAM_VERSION <<<"$PKG_INFO"
UPSTREAM_VERSION="${UPSTREAM_VERSION%%+*}"   # 4.6.0+dfsg -> 4.6.0

if [ $# -ge 1 ] && [ -n "$1" ]; then
  DEST="$1"
else
  DEST="${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance/opencv-${UPSTREAM_VERSION}"
fi
STAMP="$DEST/.lsd_advance_debian_source_version"

if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$SRC_PKG $SRC_VERSION" ] \
   && [ -f "$DEST/modules/core/include/opencv2/core/version.hpp" ]; then
  log "$DEST already holds $SRC_PKG $SRC_VERSION"
  echo "$DEST"
  exit 0
fi

command -v dpkg-source >/dev/null 2>&1 || die "dpkg-source missing: install dpkg-dev (scripts/install_deps.sh)"

have_deb_src() {
  grep -hsE '^[[:space:]]*Types:.*\bdeb-src\b' /etc/apt/sources.list.d/*.sources >/dev/null 2>&1 && return 0
  grep -hsE '^[[:space:]]*deb-src[[:space:]]' /etc/apt/sources.list /etc/apt/sources.list.d/*.list >/dev/null 2>&1 && return 0
  return 1
}

enable_deb_src() {
  local changed=0 f
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    if grep -qE '^[[:space:]]*Types:' "$f" && ! grep -qE '^[[:space:]]*Types:.*\bdeb-src\b' "$f"; then
      log "enabling deb-src in $f"
      as_root sed -i -E '/^[[:space:]]*Types:/{/deb-src/!s/$/ deb-src/}' "$f"
      changed=1
    fi
  done
  local lists=() l
  for l in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$l" ] && grep -qE '^[[:space:]]*deb[[:space:]]' "$l" && lists+=("$l")
  done
  if [ ${#lists[@]} -gt 0 ]; then
    local out=/etc/apt/sources.list.d/lsd-advance-deb-src.list tmp
    tmp="$(mktemp)"
    grep -hE '^[[:space:]]*deb[[:space:]]' "${lists[@]}" | sed -E 's/^[[:space:]]*deb[[:space:]]/deb-src /' | sort -u >"$tmp"
    log "adding classic deb-src entries in $out"
    as_root install -m 0644 "$tmp" "$out"
    rm -f "$tmp"
    changed=1
  fi
  [ "$changed" = 1 ] || die "found no Debian apt sources to derive deb-src entries from"
}

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

download() {
  (cd "$WORK" && apt-get source --download-only -q "${SRC_PKG}=${SRC_VERSION}") >&2
}

if ! have_deb_src; then
  enable_deb_src
  as_root apt-get update -q >&2
fi
if ! download; then
  log "apt-get source failed; refreshing the package lists and retrying"
  as_root apt-get update -q >&2
  download || die "apt-get source ${SRC_PKG}=${SRC_VERSION} failed"
fi

DSC="$(ls "$WORK"/*.dsc | head -n1)"
[ -f "$DSC" ] || die "no .dsc downloaded"
rm -rf "$DEST.tmp.$$"
mkdir -p "$(dirname "$DEST")"
log "extracting $(basename "$DSC") into $DEST"
dpkg-source -x "$DSC" "$DEST.tmp.$$" >&2
echo "$SRC_PKG $SRC_VERSION" >"$DEST.tmp.$$/.lsd_advance_debian_source_version"
rm -rf "$DEST"
mv "$DEST.tmp.$$" "$DEST"
[ -f "$DEST/modules/ts/src/ts.cpp" ] || die "extracted tree has no modules/ts"
log "done: $DEST"
echo "$DEST"
