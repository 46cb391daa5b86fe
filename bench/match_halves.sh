#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lutkit match on real pictures (issue 23's acceptance cases), with outside tools for everything
# but the match: for each picture given, in every method,
#   same scene:  SOURCE = the picture, REFERENCE = the picture graded and flipped upside down;
#   halves:      SOURCE = one half (left, then right), REFERENCE = the other half graded;
# and the mean distance, in 8-bit steps, of `lutkit match`'s LUT applied to SOURCE from SOURCE
# truly graded. Two columns frame it: "no LUT" (SOURCE itself against the truth: how far the grade
# moves the picture) and "content alone" (the auto match with no grade on either side, against
# SOURCE itself: how far the two pictures' different content moves a match that should change
# nothing; a match of distributions cannot tell that from a look). The grade is the float64 formula of tests/match/MatchTestUtil.h (channel mix,
# per-channel curves, saturation 1.25), written by bench/grade_cube.py as a 65^3 .cube and applied by
# ffmpeg's lut3d filter (tetrahedral); the halves are cut and flipped by oiiotool, the distance
# measured by idiff. Prints a Markdown table.
#
#   bench/match_halves.sh [--build DIR] PICTURE...     (any picture oiiotool reads; 8-bit RGB used)
#
# Needs oiiotool and idiff (openimageio-tools), ffmpeg and python3 (scripts/install-deps.sh).
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="$ROOT/build"
if [ "${1:-}" = "--build" ]; then BUILD="$2"; shift 2; fi
LUTKIT="$BUILD/bin/lutkit"
[ -x "$LUTKIT" ] || { echo "no $LUTKIT: build lutkit first" >&2; exit 1; }
[ $# -gt 0 ] || { echo "usage: bench/match_halves.sh [--build DIR] PICTURE..." >&2; exit 2; }
for t in oiiotool idiff ffmpeg python3; do
  command -v "$t" >/dev/null || { echo "$t missing (scripts/install-deps.sh)" >&2; exit 1; }
done

W="$(mktemp -d /tmp/lutkit-match.XXXXXX)"
trap 'rm -rf "$W"' EXIT

# graded, steps: the grade by ffmpeg, the distance by idiff
. "$ROOT/bench/match_oracles.sh"
write_grade_cube
METHODS=(auto hm mkl hm-mkl-hm regularised)

printf '| picture | case | no LUT | content alone |'
printf ' %s |' "${METHODS[@]}"
printf '\n|---|---|---|---|'
printf -- '---|%.0s' "${METHODS[@]}"
printf '\n'
for pic in "$@"; do
  name="$(basename "$pic")"
  oiiotool "$pic" --ch R,G,B -d uint8 -o "$W/full.png"
  read -r w h < <(oiiotool --info "$W/full.png" | sed -E 's/.*: *([0-9]+) x +([0-9]+).*/\1 \2/')
  half=$((w / 2))
  oiiotool "$W/full.png" --cut "${half}x${h}+0+0" -o "$W/left.png"
  oiiotool "$W/full.png" --cut "$((w - half))x${h}+${half}+0" -o "$W/right.png"
  for f in full left right; do graded "$W/$f.png" "$W/$f-graded.png"; done
  oiiotool "$W/full-graded.png" --flip -o "$W/full-reference.png"
  oiiotool "$W/full.png" --flip -o "$W/full-flipped.png"
  for c in "same scene:full:full-reference:full-flipped" "left half:left:right-graded:right" \
    "right half:right:left-graded:left"; do
    IFS=: read -r label src ref plain <<<"$c"
    # content alone: the same match with no grade on either side, against SOURCE itself
    "$LUTKIT" match -q -y "$W/$src.png" "$W/$plain.png" "$W/plain.cube" >/dev/null 2>>"$W/warnings.log"
    "$LUTKIT" apply -q -y --lut "$W/plain.cube" "$W/$src.png" -o "$W/plain.png" >/dev/null 2>>"$W/warnings.log"
    printf '| %s | %s | %s | %s |' "$name" "$label" "$(steps "$W/$src.png" "$W/$src-graded.png")" \
      "$(steps "$W/plain.png" "$W/$src.png")"
    for m in "${METHODS[@]}"; do
      "$LUTKIT" match -q -y --method "$m" "$W/$src.png" "$W/$ref.png" "$W/look.cube" >/dev/null 2>>"$W/warnings.log"
      "$LUTKIT" apply -q -y --lut "$W/look.cube" "$W/$src.png" -o "$W/got.png" >/dev/null 2>>"$W/warnings.log"
      printf ' %s |' "$(steps "$W/got.png" "$W/$src-graded.png")"
    done
    printf '\n'
  done
done
