#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The long fuzzing runs CI has no time for (issue 29): fuzz_image_oiio once per image format
# OpenImageIO reads for lutkit, each from that format's seeds (tests/fuzz/corpus/image_oiio/
# <format>-*, made by tests/fuzz/make_image_seeds.sh) and its regression inputs, for a number of
# mutation runs (default 10000) or a time, whichever comes first. Any single allocation over
# 256 MiB is a finding (libFuzzer's -malloc_limit_mb: no file under 1 MiB may make lutkit ask for
# more), as are crashes, timeouts, leaks and a process past --rss MiB (ASan's own shadow and
# quarantine included). Prints one line per format and writes the table docs/robustness.md
# records to BUILD_DIR/findings/image_oiio-nightly.md.
# Usage: scripts/fuzz-nightly.sh [BUILD_DIR] [RUNS] [SECONDS] [FORMAT...]
#   BUILD_DIR build-fuzz, RUNS 10000 per format, SECONDS 1800 per format at most,
#   FORMAT tiff jpeg tga bmp hdr dpx psd gif exr iff webp (the seed name prefixes).
# Findings land in BUILD_DIR/findings/image_oiio-<format>/; fix each and copy it into
# tests/data/fuzz-regress/image_oiio/ (CONTRIBUTING.md, Fuzzing).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-fuzz}"
runs="${2:-10000}"
seconds="${3:-1800}"
shift $(( $# > 3 ? 3 : $# )) || true
case "$build" in /*) ;; *) build="$root/$build" ;; esac
formats=("$@")
[ ${#formats[@]} -eq 0 ] && formats=(tiff jpeg tga bmp hdr dpx psd gif exr iff webp)
rss="${LUTKIT_FUZZ_RSS_MB:-2048}"

# The build: the same tree and flags as scripts/fuzz.sh (0 seconds: build only).
"$root/scripts/fuzz.sh" "$build" 0 image_oiio >/dev/null
bin="$build/bin/fuzz_image_oiio"
[ -x "$bin" ] || { echo "fuzz-nightly: no $bin"; exit 1; }

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:allocator_may_return_null=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:${LSAN_OPTIONS:-}"
summary="$build/findings/image_oiio-nightly.md"
mkdir -p "$build/findings"
{
  echo "| format | seeds | mutation runs | crashes, OOMs, timeouts | peak RSS (MiB, with ASan) | seconds |"
  echo "|---|---|---|---|---|---|"
} >"$summary"
failed=()
for fmt in "${formats[@]}"; do
  work="$build/corpus/image_oiio-$fmt"
  findings="$build/findings/image_oiio-$fmt"
  rm -rf "$work"
  mkdir -p "$work" "$findings"
  cp "$root/tests/fuzz/corpus/image_oiio/$fmt"-* "$work/" 2>/dev/null || true
  cp "$root/tests/data/fuzz-regress/image_oiio/$fmt"-* "$root/tests/data/fuzz-regress/image_oiio/"*-"$fmt"-* "$work/" 2>/dev/null || true
  seeds=$(ls "$work" | wc -l)
  [ "$seeds" -gt 0 ] || { echo "fuzz-nightly: no seeds for $fmt"; failed+=("$fmt(no seeds)"); continue; }
  log="$build/findings/image_oiio-$fmt.log"
  start=$(date +%s)
  status=ok
  if ! "$bin" "$work" -runs="$runs" -max_total_time="$seconds" -rss_limit_mb="$rss" \
       -malloc_limit_mb=256 -timeout=20 -max_len=65536 -artifact_prefix="$findings/" \
       -print_final_stats=1 >"$log" 2>&1; then
    status=FOUND
    failed+=("$fmt")
  fi
  took=$(( $(date +%s) - start ))
  done_runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' || true)
  peak=$(grep -E '^stat::peak_rss_mb' "$log" | awk '{print $2}' || true)
  found=$(ls "$findings" | wc -l)
  echo "fuzz-nightly: $fmt: ${done_runs:-?} runs on $seeds seeds, $found findings, peak ${peak:-?} MiB, ${took}s ($status)"
  echo "| $fmt | $seeds | ${done_runs:-?} | $found | ${peak:-?} | $took |" >>"$summary"
  [ "$status" = ok ] || tail -n 30 "$log"
  rmdir "$findings" 2>/dev/null || true
done
rm -rf /dev/shm/lutkit-fuzz-* 2>/dev/null || true
echo "fuzz-nightly: table in $summary"
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz-nightly: FAILED: ${failed[*]} (inputs in $build/findings/)"
  exit 1
fi
echo "fuzz-nightly: all ${#formats[@]} formats clean"
