#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job of ./run.sh: a neutral 16^3 LUT in every native format, and the bundled sample grade
# converted to a Smash nutexb and an Unreal 256x16 strip PNG, with the error each conversion cost.
# Usage: scripts/main-job.sh LUTKIT OUTDIR
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 LUTKIT OUTDIR" >&2
  exit 2
fi
lutkit="$1"
out="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
sample="$root/samples/sample_grade.cube"
mkdir -p "$out"

bytes() { stat -c %s "$1"; }

# name | lutkit neutral options
neutrals=(
  "neutral_16.cube|"
  "neutral_16_unreal.png|--layout unreal"
  "neutral_16_unity.png|--layout unity"
  "neutral_16_smush.png|--layout smush"
  "neutral_16_hald.png|--layout hald"
  "neutral_16.nutexb|"
  "neutral_16_flame.3dl|--format flame"
  "neutral_16_lustre.3dl|--format lustre"
  "neutral_16.csp|"
  "neutral_16.clf|"
  "neutral_16.ctf|"
  "neutral_16.cub|"
  "neutral_16.itx|"
  "neutral_16.spi3d|"
  "neutral_16_houdini.lut|--format houdini"
)
echo "== neutral 16^3 LUTs in $out"
for entry in "${neutrals[@]}"; do
  name="${entry%%|*}"
  opts="${entry#*|}"
  # shellcheck disable=SC2086
  msg="$("$lutkit" neutral -y --size 16 $opts "$out/$name")"
  msg="${msg%%$'\n'*}"
  echo "${msg#wrote }, $(bytes "$out/$name") bytes"
done

# One line per converted file: what it is, the resampling and the storage (quantisation) error.
convert() {
  local dst="$1"
  shift
  local report
  report="$("$lutkit" convert -y "$sample" "$out/$dst" "$@")"
  local wrote resample storage total game
  wrote="$(sed -n 's/^wrote *//p' <<<"$report")"
  resample="$(sed -n 's/^resample *//p' <<<"$report")"
  storage="$(sed -n 's/^storage *(quantisation, written file read back): /storage /p' <<<"$report")"
  total="$(sed -n 's/^total *//p' <<<"$report")"
  game="$(sed -n 's/^ *exact composition: *//p' <<<"$report")"
  if [ -n "$game" ]; then # a .nutexb: made for the game (convert --target smash)
    echo "$wrote, $(bytes "$out/$dst") bytes; in game vs the grade: $game"
  else
    echo "$wrote, $(bytes "$out/$dst") bytes; resample $resample; $storage; total $total"
  fi
}
echo "== $sample converted"
convert sample_grade.nutexb
convert sample_grade_unreal.png --layout unreal --size 16
