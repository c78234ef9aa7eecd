#!/usr/bin/env bash
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Usage: bash scripts/fuzz.sh [seconds]
#
# Builds the libFuzzer target fuzz/fuzz_lsd_advance.cpp with Debian's clang (the module's
# sources compiled into it, with -fsanitize=fuzzer,address,undefined) and runs it for a bounded
# time (default 60 s) from the seed corpus fuzz/corpus. Any finding (crash, sanitizer report,
# broken invariant, timeout, memory blow-up) fails the script; the input that caused it is left
# in <build>/artifacts/ (replay: <build>/lsd_advance_fuzz <file>). Prints the number of
# executions.
#
# Environment:
#   LSD_ADVANCE_FUZZ_BUILD_DIR  build directory (default: <repo>/build-fuzz)
#   LSD_ADVANCE_JOBS            parallel build jobs (default 2)
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${LSD_ADVANCE_FUZZ_BUILD_DIR:-$REPO/build-fuzz}"
JOBS="${LSD_ADVANCE_JOBS:-2}"
SECONDS_TO_RUN="${1:-60}"
T0=$SECONDS
section() { echo; echo "==== [fuzz] $* ($((SECONDS - T0)) s)"; }

section "dependencies"
bash "$REPO/scripts/install_deps.sh" --fuzz  # the standalone packages plus clang

section "configure ($BUILD, clang)"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DBUILD_TESTS=OFF -DBUILD_EXAMPLES=OFF -DLSD_ADVANCE_FUZZ=ON

section "build lsd_advance_fuzz"
cmake --build "$BUILD" -j"$JOBS" --target lsd_advance_fuzz

section "fuzz for $SECONDS_TO_RUN s"
# libFuzzer adds the inputs it finds to the first corpus folder: a scratch copy, never the repo.
WORK="$BUILD/corpus"
ARTIFACTS="$BUILD/artifacts"
rm -rf "$WORK" "$ARTIFACTS"
mkdir -p "$WORK" "$ARTIFACTS"
cp "$REPO"/fuzz/corpus/* "$WORK"/
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
# Leaks inside OpenCV itself, each explained in the file; what was suppressed is printed.
export LSAN_OPTIONS="suppressions=$REPO/scripts/lsan_suppressions.txt:print_suppressions=1"
LOG="$BUILD/fuzz.log"
rc=0
"$BUILD/lsd_advance_fuzz" -max_total_time="$SECONDS_TO_RUN" -timeout=20 -rss_limit_mb=3072 \
  -max_len=16384 -print_final_stats=1 -artifact_prefix="$ARTIFACTS/" "$WORK" >"$LOG" 2>&1 || rc=$?
tail -n 25 "$LOG"

executions="$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+).*/\1/p' "$LOG" | tail -n1)"
findings="$(find "$ARTIFACTS" -type f | wc -l)"
section "done"
echo "fuzz: ${executions:-0} executions in $SECONDS_TO_RUN s, $findings finding(s), corpus $(ls "$WORK" | wc -l) inputs"
if [ "$rc" -ne 0 ] || [ "$findings" -ne 0 ] || [ -z "$executions" ]; then
  echo "ERROR: the fuzzer found a problem (exit $rc); log: $LOG, inputs: $ARTIFACTS" >&2
  exit 1
fi
