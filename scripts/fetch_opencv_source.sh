#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: scripts/fetch_opencv_source.sh [--suite SUITE] [DEST]
#
# Without --suite: fetches Debian's OpenCV source package of exactly the version of the installed
# libopencv-dev and extracts it (with Debian's patches, contrib under DEST/contrib/modules) into
# DEST. Default DEST: ${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance/opencv-<upstream version>, the
# location CMake looks at when -DOPENCV_SOURCE_DIR is not given.
# Enables deb-src (deb822 *.sources or classic sources.list) when needed. Uses sudo only when
# not root.
#
# With --suite SUITE (scripts/check_intree.sh: trixie, OpenCV 4.10): fetches the `opencv` source
# package of that Debian release. apt runs on a private state of its own (a deb-src entry for
# SUITE only, its own package lists and cache, under ${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance/
# apt-SUITE): the system's sources, preferences and package lists are never touched, so nothing
# from SUITE can be installed or upgraded, and no root is needed. The two upstream tarballs
# (opencv_<v>.orig.tar.xz and opencv_<v>.orig-contrib.tar.xz) are downloaded with
# `apt-get source --download-only`, checked against the SHA-256 sums of SUITE's signed source
# index, and unpacked as dpkg-source does: the main one into DEST, contrib into DEST/contrib.
# Debian's patches are not applied (the mirrors do not always serve SUITE's .dsc, without which
# dpkg-source cannot run). Default DEST: ${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance/opencv-<upstream
# version>. The last line printed is DEST.
#
# Idempotent: does nothing when DEST already holds the matching version.
set -euo pipefail

log() { echo "[fetch_opencv_source] $*" >&2; }
die() { log "ERROR: $*"; exit 1; }

SUITE=""
if [ "${1:-}" = "--suite" ]; then
  [ -n "${2:-}" ] || die "--suite needs a Debian release name (e.g. trixie)"
  SUITE="$2"
  shift 2
fi
CACHE_ROOT="${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance"

# Unpacks the downloaded upstream tarballs main ($1) and contrib ($2) into DEST ($3) with the
# stamp $4, through a temporary sibling so that an interrupted run leaves no half tree.
unpack_upstream() {
  local tmp="$3.tmp.$$"
  rm -rf "$tmp"
  mkdir -p "$tmp/contrib"
  log "unpacking $(basename "$1") and $(basename "$2") (into contrib/) into $3"
  tar -xJf "$1" -C "$tmp" --strip-components=1
  tar -xJf "$2" -C "$tmp/contrib" --strip-components=1
  echo "$4" >"$tmp/.lsd_advance_debian_source_version"
  rm -rf "$3"
  mv "$tmp" "$3"
}

if [ -n "$SUITE" ]; then
  command -v apt-get >/dev/null 2>&1 || die "not a Debian-like system (no apt-get)"
  KEYRING=/usr/share/keyrings/debian-archive-keyring.gpg
  [ -f "$KEYRING" ] || die "$KEYRING missing (package debian-archive-keyring)"
  APT_ROOT="$CACHE_ROOT/apt-$SUITE"
  mkdir -p "$APT_ROOT/sources.list.d" "$APT_ROOT/preferences.d" "$APT_ROOT/lists/partial" \
           "$APT_ROOT/cache/archives/partial"
  : >"$APT_ROOT/sources.list"
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: %s\n' \
    "${LSD_ADVANCE_DEBIAN_MIRROR:-http://deb.debian.org/debian}" "$SUITE" "$KEYRING" \
    >"$APT_ROOT/sources.list.d/$SUITE-src.sources"
  APT_OPTS=(-q -o "Dir::Etc::SourceList=$APT_ROOT/sources.list"
            -o "Dir::Etc::SourceParts=$APT_ROOT/sources.list.d"
            -o "Dir::Etc::Preferences=$APT_ROOT/preferences"
            -o "Dir::Etc::PreferencesParts=$APT_ROOT/preferences.d"
            -o "Dir::State::Lists=$APT_ROOT/lists" -o "Dir::Cache=$APT_ROOT/cache"
            -o "APT::Sandbox::User=$(id -un)")
  if ! apt-get "${APT_OPTS[@]}" update >&2; then
    ls "$APT_ROOT"/lists/*_source_Sources* >/dev/null 2>&1 || die "apt-get update of $SUITE's source index failed"
    log "WARNING: apt-get update of $SUITE's source index failed; using the index fetched before"
  fi
  # The version of `opencv` in SUITE, and the SHA-256 of its upstream tarballs from the index.
  SHOWSRC="$(apt-cache "${APT_OPTS[@]}" showsrc --only-source opencv)" || die "no opencv source package in $SUITE"
  SRC_VERSION="$(sed -n 's/^Version: //p' <<<"$SHOWSRC" | sort -V | tail -n1)"
  [ -n "$SRC_VERSION" ] || die "no opencv source package in $SUITE"
  UPSTREAM_VERSION="${SRC_VERSION%-*}"        # 4.10.0+dfsg-5 -> 4.10.0+dfsg
  ORIG="opencv_${UPSTREAM_VERSION}.orig.tar.xz"
  CONTRIB="opencv_${UPSTREAM_VERSION}.orig-contrib.tar.xz"
  UPSTREAM_VERSION="${UPSTREAM_VERSION%%+*}"  # -> 4.10.0
  DEST="${1:-$CACHE_ROOT/opencv-$UPSTREAM_VERSION}"
  STAMP_TEXT="opencv $SRC_VERSION ($SUITE, upstream tarballs)"
  if [ -f "$DEST/.lsd_advance_debian_source_version" ] \
     && [ "$(cat "$DEST/.lsd_advance_debian_source_version")" = "$STAMP_TEXT" ] \
     && [ -f "$DEST/modules/core/include/opencv2/core/version.hpp" ]; then
    log "$DEST already holds $STAMP_TEXT"
    echo "$DEST"
    exit 0
  fi
  WORK="$(mktemp -d)"
  trap 'rm -rf "$WORK"' EXIT
  log "downloading $ORIG and $CONTRIB of opencv $SRC_VERSION ($SUITE)"
  # Exits non-zero when the .dsc is missing on the mirror: the tarballs are checked below.
  (cd "$WORK" && apt-get "${APT_OPTS[@]}" source --download-only "opencv=$SRC_VERSION") >&2 \
    || log "apt-get source reported errors; checking the upstream tarballs it fetched"
  # Checksums-Sha256 of this version's stanza: " <sha256> <size> <file>" lines.
  SUMS="$(awk -v v="$SRC_VERSION" '
    /^Version: / { inVersion = ($2 == v) }
    /^[^ ]/ && !/^Checksums-Sha256:/ { inSums = 0 }
    /^Checksums-Sha256:/ { inSums = inVersion; next }
    inSums && NF == 3 { print $1 "  " $3 }' <<<"$SHOWSRC")"
  for f in "$ORIG" "$CONTRIB"; do
    [ -f "$WORK/$f" ] || die "$f was not downloaded"
    grep -F "  $f" <<<"$SUMS" | (cd "$WORK" && sha256sum --quiet -c -) \
      || die "$f does not match the SHA-256 of $SUITE's signed source index"
  done
  mkdir -p "$(dirname "$DEST")"
  unpack_upstream "$WORK/$ORIG" "$WORK/$CONTRIB" "$DEST" "$STAMP_TEXT"
  [ -f "$DEST/modules/ts/src/ts.cpp" ] && [ -d "$DEST/contrib/modules/ximgproc" ] \
    || die "unpacked tree has no modules/ts or contrib/modules/ximgproc"
  log "done: $DEST"
  echo "$DEST"
  exit 0
fi

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
  DEST="$CACHE_ROOT/opencv-${UPSTREAM_VERSION}"
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
