#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lutkit.exe (the Windows edition, scripts/build-windows.sh) under Wine against the Linux build,
# in the same run: `preview` of a 1080p screenshot with a LUT, whole process, paired runs (each
# Linux run followed by the Windows one, so a busy machine slows both alike), median wall time
# of each and their ratio (issue 39's target: within 2x). Also Wine's own start (`lutkit.exe
# --version`), which is in the Windows figure, and the same outputs byte for byte.
#
#   bench/windows_preview.sh [LINUX_LUTKIT] [LUTKIT_EXE] [RUNS]
#       (defaults: build/bin/lutkit, build/windows/lutkit.exe, 7)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
LIN="${1:-$ROOT/build/bin/lutkit}"
EXE="${2:-$ROOT/build/windows/lutkit.exe}"
RUNS="${3:-7}"
[ -x "$LIN" ] || { echo "no $LIN: build lutkit first" >&2; exit 1; }
[ -f "$EXE" ] || { echo "no $EXE: scripts/build-windows.sh first" >&2; exit 1; }
export WINEPREFIX="${LUTKIT_WINEPREFIX:-$HOME/.cache/lutkit/wine}" WINEDEBUG=-all
export WINEDLLOVERRIDES="mscoree,mshtml=" LC_ALL=C.UTF-8
W="$(mktemp -d /tmp/lutkit-winbench.XXXXXX)"
trap 'rm -rf "$W"; wineserver -k 2>/dev/null || true' EXIT
cd "$W"
# The screenshot: the sample scene at 1920x1080 with a fine grain (as tests/windows makes it).
convert "$ROOT/samples/sample_scene.png" -resize '1920x1080!' -attenuate 0.4 +noise Gaussian \
  -depth 8 PNG24:shot.png
cp "$ROOT/samples/sample_grade.cube" look.cube
wine "$EXE" --version >/dev/null # Wine's first start (the prefix) is not measured
wineserver -p 60 2>/dev/null || true # one server for the runs (one may be running already)

now() { date +%s.%N; }
secs() { echo "$2 - $1" | bc; }
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
: >lin.t
: >win.t
: >start.t
for _ in $(seq "$RUNS"); do
  t=$(now); "$LIN" preview shot.png -o lin.png -y --lut look.cube >/dev/null; secs "$t" "$(now)" >>lin.t
  t=$(now); wine "$EXE" preview shot.png -o win.png -y --lut look.cube >/dev/null; secs "$t" "$(now)" >>win.t
  t=$(now); wine "$EXE" --version >/dev/null; secs "$t" "$(now)" >>start.t
done
l=$(median <lin.t)
w=$(median <win.t)
s=$(median <start.t)
same=$(cmp -s lin.png win.png && echo "byte-identical" || echo "DIFFERENT")
printf '| preview 1080p PNG, %s runs | Linux %.3f s | lutkit.exe under Wine %.3f s | ratio %.2fx | Wine start alone %.3f s | outputs %s |\n' \
  "$RUNS" "$l" "$w" "$(echo "$w / $l" | bc -l)" "$s" "$same"
