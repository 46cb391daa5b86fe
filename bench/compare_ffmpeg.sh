#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lutkit apply/preview against ffmpeg's lut3d filter, whole process, side by side in one run
# (issue 13's targets), and against the physical floor (issue 27): copying the same file with
# `cat IN > OUT && sync OUT`. Generates its inputs, then for every job alternates lutkit and its
# yardstick (paired, so a busy machine slows both alike) and prints the median wall time, CPU
# time (user + sys) and peak memory (/usr/bin/time -v) of each, and their ratio, as Markdown
# tables. The modder's default `convert EDIT.png color_grading_lut.nutexb` has no peer: its
# figure is the absolute target (0.3 s on an idle machine).
#
#   bench/compare_ffmpeg.sh [BUILD_DIR] [RUNS]      (defaults: build, 5)
#
# Needs ffmpeg (installed with apt-get when missing), oiiotool (openimageio-tools, in
# scripts/install-deps.sh) and GNU time. The LUT is samples/sample_grade.cube (33^3), applied
# with tetrahedral interpolation by both tools.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
RUNS="${2:-5}"
LUTKIT="$BUILD/bin/lutkit"
[ -x "$LUTKIT" ] || { echo "no $LUTKIT: build lutkit first" >&2; exit 1; }
if ! command -v ffmpeg >/dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq ffmpeg >/dev/null
fi
command -v oiiotool >/dev/null || { echo "oiiotool missing (scripts/install-deps.sh)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "/usr/bin/time (GNU time) missing" >&2; exit 1; }

W="$(mktemp -d /tmp/lutkit-bench.XXXXXX)"
trap 'rm -rf "$W"' EXIT
LUT="$ROOT/samples/sample_grade.cube"

# ---- inputs: a smooth ramp with fine noise (like a rendered or photographed frame) ----
ramp() { # W H CHANNELS NOISE
  echo --pattern "fill:topleft=0.1,0.2,0.3:topright=0.9,0.4,0.1:bottomleft=0,0.8,0.6:bottomright=0.8,0.7,0.6" \
    "$1x$2" "$3" --pattern "noise:type=uniform:min=0:max=$4" "$1x$2" "$3" --add
}
oiiotool $(ramp 3840 2160 3 0.05) -d half --compression none -o "$W/in4k.exr"
oiiotool $(ramp 3840 2160 3 0.03) -d uint8 -o "$W/in4k.ppm"
oiiotool $(ramp 3840 2160 3 0.03) -d uint8 -o "$W/in4k.png"
oiiotool $(ramp 1920 1080 3 0.03) -d uint8 -o "$W/shot1080.png"
# the modder's edit: a neutral 256x16 strip graded by oiiotool (gamma + tint), as an image editor would
"$LUTKIT" neutral -q "$W/strip.png" -y
oiiotool "$W/strip.png" --powc 0.8,0.9,1.1 --mulc 1.0,0.97,0.92 -d uint8 -o "$W/edit.png"
mkdir -p "$W/frames"
for i in $(seq 1 24); do
  oiiotool $(ramp 1920 1080 3 0.03) --addc "0.00$((i % 10))" -d uint8 -o "$W/frames/f$(printf %04d "$i").png"
done

# ---- measuring ----
# run NAME CMD...: one run; appends "wall cpu peakKB" to $W/NAME.txt
run() {
  local name="$1"; shift
  /usr/bin/time -f "%e %U %S %M" -o "$W/time.txt" "$@" >/dev/null 2>"$W/err.txt" || {
    echo "FAILED: $*" >&2; cat "$W/err.txt" >&2; exit 1; }
  awk '{printf "%s %.3f %s\n", $1, $2 + $3, $4}' "$W/time.txt" >>"$W/$name.txt"
}
median() { # FILE COLUMN
  sort -g -k"$2","$2" "$1" | awk -v c="$2" '{v[NR]=$c} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'
}
ffloop() { # the folder frame by frame, one ffmpeg process per frame
  mkdir -p "$W/out_loop"
  for f in "$W"/frames/*.png; do
    ffmpeg -v error -y -i "$f" -vf "lut3d=file=$LUT:interp=tetrahedral" "$W/out_loop/$(basename "$f")"
  done
}
FF="ffmpeg -v error -y"
copy() { cat "$1" >"$2" && sync "$2"; } # the floor: the same bytes read and written, synced
TETRA="lut3d=file=$LUT:interp=tetrahedral"

jobs=(exr ppm png folder_loop folder_seq preview)
for i in $(seq 1 "$RUNS"); do
  run exr_l "$LUTKIT" apply --lut "$LUT" "$W/in4k.exr" -o "$W/o.exr" -y
  run exr_f $FF -i "$W/in4k.exr" -vf "$TETRA" -c:v exr -format half -compression none "$W/f.exr"
  run exr_c bash -c "$(declare -f copy); copy '$W/in4k.exr' '$W/c.exr'"
  run ppm_l "$LUTKIT" apply --lut "$LUT" "$W/in4k.ppm" -o "$W/o.ppm" -y
  run ppm_f $FF -i "$W/in4k.ppm" -vf "$TETRA" "$W/f.ppm"
  run ppm_c bash -c "$(declare -f copy); copy '$W/in4k.ppm' '$W/c.ppm'"
  run png_l "$LUTKIT" apply --lut "$LUT" "$W/in4k.png" -o "$W/o.png" -y
  run png_f $FF -i "$W/in4k.png" -vf "$TETRA" "$W/f.png"
  run folder_loop_l "$LUTKIT" apply -q --lut "$LUT" "$W/frames" -o "$W/out_l/" -y
  run folder_loop_f bash -c "$(declare -f ffloop); W='$W' LUT='$LUT' ffloop"
  mkdir -p "$W/out_s"
  run folder_seq_l "$LUTKIT" apply -q --lut "$LUT" "$W/frames/f%04d.png" -o "$W/out_s/o%04d.png" -y
  mkdir -p "$W/out_fs"
  run folder_seq_f $FF -i "$W/frames/f%04d.png" -vf "$TETRA" "$W/out_fs/o%04d.png"
  run preview_l "$LUTKIT" preview "$W/shot1080.png" -o "$W/pv.png" -y
  run preview_f $FF -i "$W/shot1080.png" -vf "lut3d=file=$LUT" "$W/fpv.png"
  run convert_l "$LUTKIT" convert -q "$W/edit.png" "$W/color_grading_lut.nutexb" -y
done

# The outputs keep the input's type: half EXR stays half.
oiiotool --info "$W/o.exr" | grep -q "half openexr" || echo "WARNING: lutkit's EXR output is not half" >&2

printf "machine: %s, %s cores, load average at the end: %s\n\n" "$(uname -m)" "$(nproc)" \
  "$(cut -d' ' -f1-3 /proc/loadavg)"
echo "| job | lutkit wall | ffmpeg wall | wall ratio | lutkit CPU | ffmpeg CPU | lutkit peak | ffmpeg peak |"
echo "|---|---|---|---|---|---|---|---|"
label() {
  case "$1" in
    exr) echo "apply 4K half EXR (uncompressed in/out), 33^3 tetrahedral" ;;
    ppm) echo "apply 4K 8-bit PPM" ;;
    png) echo "apply 4K 8-bit PNG" ;;
    folder_loop) echo "24 x 1080p PNG folder vs a loop of ffmpeg runs" ;;
    folder_seq) echo "24 x 1080p PNG sequence vs one ffmpeg run" ;;
    preview) echo "preview 1080p PNG screenshot vs ffmpeg's plain lut3d (targets: 0.08 s idle, 0.35x)" ;;
    exr_floor) echo "apply 4K half EXR vs cat + sync (target <= 2x)" ;;
    ppm_floor) echo "apply 4K 8-bit PPM vs cat + sync (target <= 2x)" ;;
    convert) echo "convert edit.png color_grading_lut.nutexb (target <= 0.3 s idle)" ;;
  esac
}
row() { # JOB LABEL-KEY PEER-SUFFIX
  local j="$1" peer="$W/${1}_$3.txt"
  lw=$(median "$W/${j}_l.txt" 1); lc=$(median "$W/${j}_l.txt" 2); lm=$(median "$W/${j}_l.txt" 3)
  if [ -f "$peer" ]; then
    fw=$(median "$peer" 1); fc=$(median "$peer" 2); fm=$(median "$peer" 3)
    ratio=$(awk -v a="$lw" -v b="$fw" 'BEGIN {printf "%.2fx", a / b}')
    printf "| %s | %.3f s | %.3f s | **%s** | %.3f s | %.3f s | %d MB | %d MB |\n" "$(label "$2")" \
      "$lw" "$fw" "$ratio" "$lc" "$fc" $((lm / 1024)) $((fm / 1024))
  else
    printf "| %s | %.3f s | - | - | %.3f s | - | %d MB | - |\n" "$(label "$2")" "$lw" "$lc" $((lm / 1024))
  fi
}
for j in "${jobs[@]}"; do row "$j" "$j" f; done
echo
echo "| job | lutkit wall | floor (cat + sync) wall | wall ratio | lutkit CPU | floor CPU | lutkit peak | floor peak |"
echo "|---|---|---|---|---|---|---|---|"
row exr exr_floor c
row ppm ppm_floor c
row convert convert none
