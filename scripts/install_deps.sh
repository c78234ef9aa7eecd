#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: scripts/install_deps.sh [--intree | --fuzz]
#
# Installs the Debian packages needed to build lsd_advance standalone against Debian's OpenCV,
# its Python module and tests and its API docs
# (and, with --intree, what scripts/check_intree.sh needs to build OpenCV from source; with
# --fuzz, clang and its libFuzzer/sanitizer runtimes for scripts/fuzz.sh).
# Does nothing (no apt at all) when every package is already installed. Uses sudo only when
# not root.
set -euo pipefail

# The Python module (OpenCV's binding generator: Python headers, numpy) and its tests; doxygen +
# bibtex (texlive-binaries) for scripts/docs.sh; valgrind for the instruction counts of
# scripts/benchmark.sh (scripts/tile_work.py).
PACKAGES=(build-essential cmake pkg-config dpkg-dev
          libopencv-dev libopencv-contrib-dev opencv-doc
          python3-dev python3-numpy python3-opencv python3-pytest
          doxygen texlive-binaries valgrind)
if [ "${1:-}" = "--intree" ]; then
  # OpenCV's own build (Debian's source package has no 3rdparty/: use system codecs)
  PACKAGES+=(zlib1g-dev libjpeg-dev libpng-dev libtiff-dev libwebp-dev ninja-build python3)
elif [ "${1:-}" = "--fuzz" ]; then
  PACKAGES+=(clang libclang-rt-14-dev)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "[install_deps] all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "[install_deps] ERROR: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi

echo "[install_deps] installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
