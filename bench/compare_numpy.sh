#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lutkit match against a plain HM-MKL-HM in numpy (bench/match_numpy.py), issue 23's speed
# yardstick, on a 1080p source and a 1080p reference, paired runs, medians. SOURCE is the picture
# given (default samples/sample_scene.png), scaled to 1920x1080 with a fine grain by oiiotool; the
# reference is SOURCE graded by the match tests' formula (bench/grade_cube.py, applied by
# ffmpeg's lut3d) and flipped upside down. Times: `lutkit match` whole (reading both PNGs, fitting
# every method for auto, writing the 33^3 .cube) on both cores, wall; numpy's match alone (its
# reading excluded). Accuracy: each result against the true grade, mean / p99 8-bit steps
# (lutkit's .cube applied by `lutkit apply`, measured by oiiotool's idiff and numpy).
#
#   bench/compare_numpy.sh [--build DIR] [RUNS] [PICTURE]      (defaults: build, 5)
#
# Needs python3 with numpy (Debian's python3-numpy for /usr/bin/python3), oiiotool, idiff,
# ffmpeg and GNU time.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="$ROOT/build"
if [ "${1:-}" = "--build" ]; then BUILD="$2"; shift 2; fi
RUNS="${1:-5}"
PICTURE="${2:-$ROOT/samples/sample_scene.png}"
LUTKIT="$BUILD/bin/lutkit"
[ -x "$LUTKIT" ] || { echo "no $LUTKIT: build lutkit first" >&2; exit 1; }
PY=python3
$PY -c "import numpy" 2>/dev/null || PY=/usr/bin/python3
$PY -c "import numpy" 2>/dev/null ||
  { echo "numpy missing: apt-get install python3-numpy (for /usr/bin/python3)" >&2; exit 1; }
for t in oiiotool idiff ffmpeg; do
  command -v "$t" >/dev/null || { echo "$t missing (scripts/install-deps.sh)" >&2; exit 1; }
done
[ -x /usr/bin/time ] || { echo "/usr/bin/time (GNU time) missing" >&2; exit 1; }

W="$(mktemp -d /tmp/lutkit-numpy.XXXXXX)"
trap 'rm -rf "$W"' EXIT
# graded, steps: the grade by ffmpeg, the distance by idiff
. "$ROOT/bench/match_oracles.sh"
write_grade_cube
oiiotool "$PICTURE" --ch R,G,B --resize 1920x1080 \
  --pattern noise:type=uniform:min=-0.006:max=0.006:seed=3 1920x1080 3 --add -d uint8 -o "$W/source.png"
graded "$W/source.png" "$W/truth.png"
oiiotool "$W/truth.png" --flip -o "$W/reference.png"
for f in source truth reference; do oiiotool "$W/$f.png" -o "$W/$f.ppm"; done

median() { sort -n | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
: > "$W/lutkit.txt"
: > "$W/numpy.txt"
for _ in $(seq "$RUNS"); do
  /usr/bin/time -f "%e" -o "$W/t" "$LUTKIT" match -q -y "$W/source.png" "$W/reference.png" \
    "$W/look.cube" >/dev/null 2>&1
  cat "$W/t" >> "$W/lutkit.txt"
  $PY "$ROOT/bench/match_numpy.py" "$W/source.ppm" "$W/reference.ppm" "$W/truth.ppm" > "$W/np"
  awk '{print $2}' "$W/np" >> "$W/numpy.txt"
done
"$LUTKIT" apply -q -y --lut "$W/look.cube" "$W/source.png" -o "$W/got.png" >/dev/null 2>&1
lutkit_steps="$(steps "$W/got.png" "$W/truth.png")"
lk="$(median < "$W/lutkit.txt")"
np="$(median < "$W/numpy.txt")"
echo "| 1080p source + reference -> LUT | wall s (median of $RUNS) | mean steps from the true grade |"
echo "|---|---|---|"
echo "| \`lutkit match\` (auto, whole command: read, fit all four, write the .cube) | $lk | $lutkit_steps |"
echo "| numpy HM-MKL-HM (the match alone, no LUT) | $np | $(awk '{print $4 " (p99 " $6 ")"}' "$W/np") |"
awk -v a="$lk" -v b="$np" 'BEGIN {printf "\nlutkit takes %.2fx the wall time of the numpy script\n", a / b}'
