#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The editor's responsiveness while its long tasks run, measured by its repaint probe
# (gui/app/RepaintProbe.h: a widget in the status bar repainted every 5 ms; the longest gap
# between two repaints, and the window's own part of it, less the time its thread waited for a
# CPU other programs took). The editor's target is under 100 ms of its own; the unit tests only
# check that the probe saw repaints during each task (no time is asserted in a test).
# Runs lutkit-editor's scripted mode in a real X server (xvfb-run) over:
#   compare       Tools > Compare of a 1920x1080 picture's grade, to the end
#   save-preview  File > Save Preview Image of that picture, to the end
#   huge-open     an 8192x8192 picture opening, cancelled after 150 ms
#   match         Tools > Match to Reference of a 1920x1080 photo-like picture to a graded
#                 1920x1080 reference, the fit to the end (the dialog opens)
#   drag-strength the dialog's Strength dragged by hand from 100 % to 20 % over 1.5 s (a move
#                 every 16 ms, each re-baking the 33^3 LUT), then 300 ms to settle
#   drag-luma     Lightness share dragged from 20 % to 150 % the same way
#   match-cancel  the same fit again, cancelled after 300 ms
# and prints one line per task: the longest gap, its own part, the paints. RUNS repeats it.
#
#   bench/editor_probe.sh [--build DIR] [RUNS]        (default 3 runs)
#
# Needs xvfb-run (xvfb), ImageMagick's convert and python3 (scripts/install-deps.sh). Run it alone on the
# machine: another heavy program on the same cores takes the window's thread's CPU.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="$ROOT/build"
if [ "${1:-}" = "--build" ]; then BUILD="$2"; shift 2; fi
RUNS="${1:-3}"
EDITOR="$BUILD/bin/lutkit-editor"
[ -x "$EDITOR" ] || { echo "no $EDITOR: build lutkit-editor first" >&2; exit 1; }
for t in xvfb-run convert python3; do
  command -v "$t" >/dev/null || { echo "$t missing (scripts/install-deps.sh)" >&2; exit 1; }
done

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cp "$ROOT/samples/sample_grade.cube" "$TMP/grade.cube"
convert -size 1920x1080 gradient:red-blue -depth 8 "$TMP/shot.png"
# a photo-like 1080p picture and a reference with another look (levels, saturation, a hue turn)
convert -seed 7 -size 1920x1080 plasma:fractal -blur 0x2 -depth 8 "$TMP/photo.png"
convert "$TMP/photo.png" -level 4%,92%,0.85 -modulate 100,135,96 -depth 8 "$TMP/look.png"
# 8192x8192 black RGB pixels in a ~200 KB PNG (as tests/gui/GuiTestSupport.h's writeBlackPng).
python3 - "$TMP/huge.png" <<'PY'
import struct, sys, zlib
w = h = 8192
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
z = zlib.compressobj(9)
row = bytes(3 * w + 1)
idat = b"".join(z.compress(row) for _ in range(h)) + z.flush()
with open(sys.argv[1], "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", idat) + chunk(b"IEND", b""))
PY
cat >"$TMP/probe.txt" <<SCRIPT
open-image $TMP/shot.png
open-lut $TMP/grade.cube
wait
probe on
start-compare $TMP/grade.cube
wait-task compare
probe off
probe on
start-save-preview $TMP/preview.png
wait-task save-preview
probe off
probe on
start-open-image $TMP/huge.png
sleep 150
cancel load
sleep 100
probe off
open-image $TMP/photo.png
wait
dialogs hold
probe on
start-match $TMP/look.png
wait-task match
probe off
probe on
match-drag strength 20 1500
sleep 300
probe off
probe on
match-drag luma 150 1500
sleep 300
probe off
dialogs reject
sleep 200
probe on
start-match $TMP/look.png
sleep 300
cancel match
sleep 100
probe off
close
SCRIPT

echo "| run | task | longest gap (ms) | own (ms) | paints |"
echo "|---|---|---|---|---|"
for run in $(seq 1 "$RUNS"); do
  out="$(QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1600x1000x24" "$EDITOR" --lut-target raw --script "$TMP/probe.txt" 2>/dev/null)"
  i=0
  for task in compare save-preview huge-open match drag-strength drag-luma match-cancel; do
    i=$((i + 1))
    line="$(grep '^probe longest-gap' <<<"$out" | sed -n "${i}p")"
    # probe longest-gap G ms own O ms over P paints
    read -r _ _ gap _ _ own _ _ paints _ <<<"$line"
    echo "| $run | $task | $gap | $own | $paints |"
  done
done
