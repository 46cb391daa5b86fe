#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the libFuzzer harnesses (tests/fuzz) with clang and runs each for a bounded time.
# Usage: scripts/fuzz.sh [BUILD_DIR] [SECONDS] [FUZZER...]
#   BUILD_DIR defaults to build-fuzz, SECONDS (per fuzzer) to 60 (0: build only), FUZZER to all
#   that were built. Longer per-format runs of image_oiio: scripts/fuzz-nightly.sh.
# Each fuzzer starts from a COPY of its seed corpus (tests/fuzz/corpus/<name> plus matching files
# in tests/data), so the checked-in seeds never change. Crashes, leaks, timeouts and OOMs land in
# BUILD_DIR/findings/<name>/ and make this script exit non-zero; add each one (after fixing it) to
# tests/data/fuzz-regress/<name>/ so the normal test suite replays it.
# FUZZ_SEED (default 1) fixes libFuzzer's random seed, so a run explores the same mutations on
# every machine: CI's verdict on a commit is the one its author saw, not a lottery over inputs
# nobody changed. FUZZ_SEED=0 draws a new seed (exploration: run it longer, locally or nightly).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-fuzz}"
seconds="${2:-60}"
shift $(( $# > 2 ? 2 : $# )) || true
case "$build" in /*) ;; *) build="$root/$build" ;; esac
jobs="$(nproc)"
seed="${FUZZ_SEED:-1}"

start=$(date +%s)
echo "fuzz: configuring $build (clang, -fsanitize=fuzzer-no-link,address,undefined)"
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
# Flags go on the command line (not the environment) so a re-run updates an existing tree.
# LUTKIT_OIIO_PKGCONFIG: OpenImageIO found as ./run.sh finds it on a machine without its tools.
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags -Wno-unknown-warning-option" \
  -DLUTKIT_FUZZ=ON -DLUTKIT_OIIO_PKGCONFIG=ON -DLUTKIT_BUILD_TESTS=OFF -DLUTKIT_BUILD_GUI=OFF -DLUTKIT_BUILD_BENCH=OFF >/dev/null

# The harnesses that run when none is named (CI): all ten. image_oiio joined on 27 Nov 2026, once
# the heap corruption it kept finding (OpenImageIO's IFF decoder writing past a tile) was found and
# refused before decoding (docs/robustness.md); fuzz-nightly.sh runs it longer, format by format.
all=(cube strip hald nutexb cli_numbers ocio image_apply patch check image_oiio)
targets=()
for f in "${all[@]}" "$@"; do
  [ -f "$root/tests/fuzz/fuzz_$f.cpp" ] && [[ " ${targets[*]} " != *" fuzz_$f "* ]] && targets+=("fuzz_$f")
done
cmake --build "$build" -j"$jobs" --target "${targets[@]}"
echo "fuzz: build took $(( $(date +%s) - start )) s"
[ "$seconds" = 0 ] && exit 0

# Seed files from tests/data for each fuzzer, by extension (the image fuzzers take encoded
# descriptions, not raw images, so their seeds are only the checked-in ones).
seed_globs() {
  case "$1" in
    cube | check) echo "*.cube" ;;
    nutexb) echo "*.nutexb" ;;
    *) echo "" ;;
  esac
}

names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for t in "${targets[@]}"; do names+=("${t#fuzz_}"); done
fi

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:allocator_may_return_null=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:${LSAN_OPTIONS:-}"
# One fuzzer: its seeds, its run, one line (the log's tail when it found something). Exit status:
# 0 clean, 1 a finding or no executable.
fuzz_one() {
  local name="$1" bin="$build/bin/fuzz_$1" work="$build/corpus/$1" findings="$build/findings/$1"
  [ -x "$bin" ] || { echo "fuzz: no $bin"; return 1; }
  rm -rf "$work"
  mkdir -p "$work" "$findings"
  [ -d "$root/tests/fuzz/corpus/$name" ] && cp -r "$root/tests/fuzz/corpus/$name/." "$work/"
  [ -d "$root/tests/data/fuzz-regress/$name" ] && cp -r "$root/tests/data/fuzz-regress/$name/." "$work/"
  local glob
  glob="$(seed_globs "$name")"
  if [ -n "$glob" ]; then
    # Small files only: a huge seed slows every mutation.
    find "$root/tests/data" -type f -name "$glob" -size -64k -not -path "*/fuzz-regress/*" \
      -exec sh -c 'for f; do cp "$f" "$0/$(echo "$f" | md5sum | cut -c1-16)"; done' "$work" {} +
  fi
  local seeds log="$build/findings/$name.log" rc=0
  seeds=$(ls "$work" | wc -l)
  "$bin" "$work" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
    -seed="$seed" -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1 || rc=$?
  # Leftovers of findings-free runs are empty folders; keep only real findings.
  rmdir "$findings" 2>/dev/null || true
  if [ $rc -eq 0 ]; then
    echo "fuzz: $name ok, ${seconds} s from $seeds seeds, seed $seed ($(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}') runs)"
    return 0
  fi
  # One write, so a finding's lines are not interleaved with the other fuzzer's line.
  printf '%s\n' "fuzz: $name FOUND A PROBLEM; last lines of $log:" "$(tail -n 40 "$log")"
  return 1
}

# Each fuzzer is one thread: $jobs of them run at once.
failed=()
pids=()
for name in "${names[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  fuzz_one "$name" &
  pids+=($!)
done
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || failed+=("${names[$i]}")
done
rm -rf /dev/shm/lutkit-fuzz-* 2>/dev/null || true

if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (inputs in $build/findings/)"
  exit 1
fi
echo "fuzz: all ${#names[@]} fuzzers clean, $(( $(date +%s) - start )) s in total"
