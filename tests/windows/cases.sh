# SPDX-License-Identifier: Apache-2.0
# The cases of tests/windows/run.sh (sourced by it: $lin, $exe, $W, $in, $data, $root, both,
# check, compare_case, normalize are its). Inputs are made by the Linux build and by outside
# programs (ImageMagick's convert for the edits a modder makes in an image editor).

# --- Inputs --------------------------------------------------------------------------------------
(
  set -e
  cd "$in"
  "$lin" neutral neutral.png >/dev/null
  # The modder's edit of the strip, by another program (ImageMagick): saturation, levels.
  convert neutral.png -modulate 100,125,97 -level 4%,96% -depth 8 PNG24:graded.png
  cp "$root/samples/sample_grade.cube" look.cube
  cp "$data/cube/resolve_shaper_3d.cube" shaper.cube
  cp "$data/cube/adobe_1d.cube" curve1d.cube
  cp "$data/nutexb/graded4_tiled.nutexb" stage.nutexb
  cp "$data/hald/graded_level3.png" hald3.png
  cp "$data/strip/graded5_smush_rgba8.png" smush.png
  # A 1080p screenshot: the sample scene at 1920x1080 with a fine grain, as PNG and as the JPEG the
  # Switch saves; and a reference look for match (the same picture, warmed and darkened).
  convert "$root/samples/sample_scene.png" -resize '1920x1080!' -attenuate 0.4 +noise Gaussian \
    -depth 8 PNG24:shot.png
  convert shot.png -quality 92 shot.jpg
  convert shot.png -modulate 90,115,96 -depth 8 PNG24:reference.png
  for i in 1 2; do # the colourist's plates (OpenEXR, half float), by OpenImageIO's oiiotool
    oiiotool --pattern "fill:topleft=0.1,0.2,0.3:bottomright=0.9,0.7,0.$i" 64x36 3 -d half \
      -o "plate.000$i.exr"
  done
  mkdir -p frames
  for i in 1 2 3; do convert shot.png -resize 480x270 -modulate "$((90 + 5 * i)),100,100" \
    -depth 8 "PNG24:frames/f000$i.png"; done
)

# --- One self-contained file: it imports Windows' own DLLs only --------------------------------
system_dlls="kernel32.dll msvcrt.dll shell32.dll user32.dll advapi32.dll ws2_32.dll bcrypt.dll"
self_contained() {
  local d
  for d in $(x86_64-w64-mingw32-objdump -p "$exe" | sed -n 's/^[[:space:]]*DLL Name: //p' | tr 'A-Z' 'a-z'); do
    case " $system_dlls " in *" $d "*) ;; *) echo "         imports $d"; return 1 ;; esac
  done
}
check self-contained self_contained

# --- The README's quick starts -------------------------------------------------------------------
both qs-modder-1 --dir qs -- neutral neutral2.png
both qs-modder-2 --dir qs -- convert graded.png color_grading_lut.nutexb
both qs-modder-3 --dir qs -- preview shot.png -o in_game.png --lut color_grading_lut.nutexb
# The colourist's: .3dl and OpenEXR are OpenColorIO's and OpenEXR's, which this edition leaves out:
# one line naming the edition, exit code 1, nothing written.
winonly qs-colourist-3dl -- convert look.cube look.3dl
check qs-colourist-3dl-refused expect_win qs-colourist-3dl 1 "look.3dl: .* lutkit for Windows does not include"
winonly qs-colourist-exr -- apply --lut look.cube plate.%04d.exr -o graded.%04d.exr
check qs-colourist-exr-refused expect_win qs-colourist-exr 1 "lutkit for Windows"

# --- A convert into every native format ----------------------------------------------------------
both cube-adobe -- convert graded.png out.cube
both cube-adobe-33 -- convert look.cube out.cube --size 33
both cube-resolve -- convert shaper.cube out.cube
both cube-1d -- convert curve1d.cube out.cube
for layout in unreal unity smush reshade unity-32 pilot godot lattice unreal-32; do
  both "strip-$layout" -- convert look.cube "out_$layout.png" --layout "$layout"
done
both strip-16bit -- convert graded.png out16.png --layout unity --bit-depth 16
# PNG has no float samples: refused on both, the same line (exit 1).
both strip-float --rc 1 -- convert graded.png out32.png --bit-depth 32
both hald -- convert look.cube out_hald.png --layout hald --level 6
both hald-in -- convert hald3.png out.cube
both smush-in -- convert smush.png out.cube
both nutexb-game -- convert graded.png color_grading_lut.nutexb
both nutexb-raw -- convert graded.png raw.nutexb --target raw
both nutexb-in -- convert stage.nutexb out.png
both nutexb-look -- convert look.cube look.nutexb
both spi3d -- convert graded.png out.spi3d
both atlas-build -- atlas build graded.png look.cube smush.png -o atlas.png --neutral-first
both atlas-split --dir atlas-build -- atlas split atlas.png -o .
both atlas-info --dir atlas-build -- atlas info atlas.png
for f in cube nutexb spi3d; do both "neutral-$f" -- neutral "n.$f"; done
both neutral-hald -- neutral --level 8 hald8.png
both neutral-reshade -- neutral --layout reshade --bit-depth 16 reshade.png
both info -- info look.cube
both validate -- validate shaper.cube

# --- The modder's round trip on a screenshot, and the commands of the acceptance -----------------
both rt-embed --dir rt -- embed shot.png patched.png
# The grade, made in "an image editor": ImageMagick, on Linux's patched.png, given to both.
if [ -f "$W/lin/rt/patched.png" ]; then
  convert "$W/lin/rt/patched.png" -modulate 100,130,95 -gamma 1.1 -depth 8 PNG24:"$W/rt-edited.png"
  cp "$W/rt-edited.png" "$W/lin/rt/edited.png"
  cp "$W/rt-edited.png" "$W/win/rt/edited.png"
fi
both rt-extract --dir rt -- extract edited.png grade.cube
both rt-extract-nutexb --dir rt -- extract edited.png color_grading_lut.nutexb
both rt-convert --dir rt -- convert grade.cube game.nutexb
both rt-preview --dir rt -- preview shot.png -o in_game.png --lut color_grading_lut.nutexb
both preview-jpeg -- preview shot.jpg -o seen.png --lut look.cube
both preview-strength -- preview shot.png -o seen.png --lut graded.png --strength 0.6
both preview-frames --unordered -- preview frames -o seen/ --lut look.cube
both apply -- apply --lut look.cube shot.png -o applied.png
both extract-strip -- extract graded.png from_strip.cube
both match -- match shot.png reference.png look_match.cube
both match-nutexb -- match shot.png reference.png color_grading_lut.nutexb --strength 0.7
both check -- check look.cube --report check.png
# The test's 4^3 stage LUT folds and shifts hues: check fails it (exit 1) on both.
both check-game --rc 1 -- check stage.nutexb --image shot.png --json
both chart -- chart all charts.png
both diff -- diff look.cube graded.png --image shot.png --heatmap where.png
both compose -- compose look.cube graded.png composed.cube
both invert -- invert curve1d.cube inverse.cube
both resize -- resize look.cube small.cube --size 17
both smooth -- smooth graded.png smooth.cube
both mix -- mix look.cube graded.png mixed.cube --strength 0.3
both plot -- plot look.cube plot.png

# --- Standard output: bytes as they are (binary mode: no CRLF) -----------------------------------
both stdout-cube --stdout-bytes -- convert look.cube - --format cube --size 9
both stdout-png --stdout-bytes -- neutral - --format strip
both stdout-nutexb --stdout-bytes -- convert graded.png - --format nutexb --target raw

# --- Exit codes and messages: usage, bad input ---------------------------------------------------
both usage-none --rc 2 --
both usage-unknown --rc 2 -- nuetral n.cube
both usage-missing --rc 2 -- convert
both usage-option --rc 2 -- convert look.cube out.cube --no-such-option
both usage-value --rc 2 -- neutral n.cube --size 1
both exists --rc 1 -- convert graded.png neutral.png
both missing --rc 1 -- convert missing.cube out.cube
both folder-in --rc 1 -- convert frames out.cube
both folder-out --rc 1 -- convert look.cube frames

# --- Hostile inputs: the test data's malformed files and the fuzzers' findings ---------------------
hostile() { # NAME FILE AS ARGS...: FILE copied in as AS, then lutkit ARGS
  local name="$1" file="$2" as="$3"
  shift 3
  mkdir -p "$W/hostile-in"
  rm -rf "$W/hostile-in"/*
  cp "$file" "$W/hostile-in/$as"
  in="$W/hostile-in" both "$name" --rc any -- "$@" # the same as Linux's, whatever it is
}
for f in "$data"/cube/malformed/*.cube "$data"/fuzz-regress/cube/*; do
  hostile "hostile-cube-$(basename "$f")" "$f" "$(basename "$f")" convert "$(basename "$f")" out.nutexb
done
for f in "$data"/nutexb/bad_*.nutexb "$data"/fuzz-regress/nutexb/*; do
  hostile "hostile-nutexb-$(basename "$f")" "$f" "$(basename "$f")" convert "$(basename "$f")" out.cube
done
for f in "$data"/fuzz-regress/strip/*; do
  hostile "hostile-strip-$(basename "$f")" "$f" strip.png convert strip.png out.cube
done
for f in "$data"/fuzz-regress/hald/*; do
  hostile "hostile-hald-$(basename "$f")" "$f" hald.png convert hald.png out.cube --in-layout hald
done
hostile hostile-image-small-png "$data/fuzz-regress/image_apply/small-png" small.png preview small.png -o seen.png
hostile hostile-image-small-jpg "$data/fuzz-regress/image_apply/small-jpg" small.jpg preview small.jpg -o seen.png
for f in "$data"/fuzz-regress/patch/*; do
  hostile "hostile-patch-$(basename "$f")" "$f" edited.png extract edited.png out.cube
done
# Made here: empty, cut short, lying about its size, not what its name says.
mkdir -p "$W/made"
: >"$W/made/empty.png"
head -c 3000 "$in/shot.png" >"$W/made/cut.png"
head -c 20000 "$in/shot.jpg" >"$W/made/cut.jpg"
printf 'not an image\n' >"$W/made/text.png"
printf 'not an image\n' >"$W/made/text.jpg"
$py - "$in/neutral.png" "$W/made/huge.png" <<'EOF'
import struct, sys, zlib
data = bytearray(open(sys.argv[1], "rb").read())
# IHDR claims 60000x60000 (the CRC made right): refused before anything is allocated.
data[16:24] = struct.pack(">II", 60000, 60000)
data[29:33] = struct.pack(">I", zlib.crc32(bytes(data[12:29])))
open(sys.argv[2], "wb").write(data)
EOF
for f in empty.png cut.png cut.jpg text.png text.jpg huge.png; do
  hostile "hostile-made-$f" "$W/made/$f" "$f" preview "$f" -o seen.png --lut builtin:neutral
  hostile "hostile-made-strip-$f" "$W/made/$f" "$f" convert "$f" out.cube
done

# --- The drop: files and no command (what Windows does for files dropped on lutkit.exe) ----------
both drop -- graded.png
check drop-is-convert cmp -s "$W/win/drop/color_grading_lut.nutexb" "$W/lin/qs/color_grading_lut.nutexb"
# Dropped again: the .nutexb there is kept, a new name is taken and said.
both drop-again --dir drop -- graded.png
check drop-again-kept cmp -s "$W/win/drop/color_grading_lut.nutexb" "$W/win/drop/color_grading_lut (2).nutexb"
check drop-again-said grep -q 'color_grading_lut (2).nutexb (color_grading_lut.nutexb is there already' "$W/win/drop-again.out"
# Two files in other folders, given as Explorer gives them: absolute, with a drive letter and
# backslashes; each output beside its own file.
mkdir -p "$W/win/drop-abs/mod one" "$W/win/drop-abs/Stage Two" "$W/lin/drop-abs/mod one" "$W/lin/drop-abs/Stage Two"
for s in lin win; do
  cp "$in/graded.png" "$W/$s/drop-abs/mod one/neutral edited.png"
  cp "$in/look.cube" "$W/$s/drop-abs/Stage Two/look.cube"
done
winpath() { echo "Z:$1" | sed 's#/#\\#g'; }
(cd "$W/lin/drop-abs" && "$lin" "$W/lin/drop-abs/mod one/neutral edited.png" "$W/lin/drop-abs/Stage Two/look.cube" \
  >"$W/lin/drop-abs.out" 2>"$W/lin/drop-abs.err" </dev/null)
lrc=$?
(cd "$in" && wine "$exe" "$(winpath "$W/win/drop-abs/mod one/neutral edited.png")" \
  "$(winpath "$W/win/drop-abs/Stage Two/look.cube")" >"$W/win/drop-abs.out" 2>"$W/win/drop-abs.err" </dev/null)
wrc=$?
sed -i "s#$W/lin/#$W/win/#g" "$W/lin/drop-abs.out" "$W/lin/drop-abs.err"
compare_case drop-abs drop-abs "$lrc" "$wrc" 0 0
check drop-abs-beside test -f "$W/win/drop-abs/Stage Two/color_grading_lut.nutexb"
both drop-nutexb --rc 1 -- stage.nutexb
check drop-nutexb-said grep -q 'is a game LUT (.nutexb) already' "$W/win/drop-nutexb.err"
both drop-screenshot --rc 1 -- shot.png
# No arguments (a double click): the short how to use, exit code 2; no wait with stdin no console.
check noargs-howto grep -q 'drop it on lutkit (lutkit.exe on Windows)' "$W/win/usage-none.err"

# --- Paths: spaces, non-ASCII names, backslashes, a drive letter ---------------------------------
for s in lin win; do
  mkdir -p "$W/$s/names/dossier été/ünï cödé 😀"
  cp "$in/graded.png" "$W/$s/names/dossier été/ünï cödé 😀/neutre édité.png"
done
both names-utf8 --dir names -- convert "dossier été/ünï cödé 😀/neutre édité.png" "dossier été/sortie ç.nutexb"
both names-utf8-report --dir names -- info "dossier été/ünï cödé 😀/neutre édité.png"
winonly names-backslash --dir names -- convert 'dossier été\ünï cödé 😀\neutre édité.png' 'dossier été\ünï cödé 😀\sortie β.nutexb'
check names-backslash-bytes cmp -s "$W/win/names/dossier été/ünï cödé 😀/sortie β.nutexb" "$W/lin/names/dossier été/sortie ç.nutexb"
winonly names-drive --dir names -- convert "$(winpath "$W/win/names/dossier été/ünï cödé 😀/neutre édité.png")" \
  "$(winpath "$W/win/names/dossier été/ünï cödé 😀/Ω.cube")"
check names-drive-written test -s "$W/win/names/dossier été/ünï cödé 😀/Ω.cube"
check names-drive-said grep -q "Z:.*Ω.cube" "$W/win/names-drive.out"
check names-no-temp test -z "$(find "$W/win/names" -name '.*tmp*')"

# --- A read-only folder: nothing written, nothing lost, the old file as it was --------------------
# Root writes into a chmod-ed folder; an immutable one (chattr +i) refuses root too.
readonly_folder() {
  chmod a-w "$1"
  [ "$(id -u)" = 0 ] && chattr +i "$1" 2>/dev/null
  return 0
}
for s in lin win; do
  mkdir -p "$W/$s/ro/ro"
  cp "$in/look.cube" "$W/$s/ro/ro/old.cube"
  cp "$in/graded.png" "$W/$s/ro/graded.png"
  readonly_folder "$W/$s/ro/ro"
done
# As root, the immutable folder's refusal is "Operation not permitted" on Linux (EPERM) and
# "Permission denied" under Wine (ERROR_ACCESS_DENIED); for a user it is EACCES on both.
ro_words() { [ -f "$1" ] && sed -i 's/Operation not permitted/Permission denied/' "$1"; }
FIXUP=ro_words both ro-replace --dir ro --rc 1 -- convert graded.png ro/old.cube -y
FIXUP=ro_words both ro-new --dir ro --rc 1 -- convert graded.png ro/new.nutexb
check ro-old-kept cmp -s "$W/win/ro/ro/old.cube" "$in/look.cube"
check ro-nothing-left test "$(ls -A "$W/win/ro/ro")" = "old.cube"
for s in lin win; do chattr -i "$W/$s/ro/ro" 2>/dev/null; chmod u+w "$W/$s/ro/ro"; done

# --- A failed write in a writable folder keeps the old file (an input that cannot be read) --------
for s in lin win; do
  mkdir -p "$W/$s/keep"
  cp "$in/look.cube" "$W/$s/keep/old.cube"
  cp "$W/made/cut.png" "$W/$s/keep/cut.png"
done
both keep-old --dir keep --rc 1 -- convert cut.png old.cube -y
check keep-old-kept cmp -s "$W/win/keep/old.cube" "$in/look.cube"

# --- Colours: none where the console takes none (a pipe here) -------------------------------------
both batch --unordered -- apply --lut look.cube frames -o applied/
check no-escapes-in-pipes bash -c "! grep -q $'\033' '$W/win/batch.err' '$W/win/batch.out'"

# --- Ctrl-C: exit code 130, the temporary file removed, the old output as it was ------------------
# SIGINT to Wine's process is the console's Ctrl-C event for the program (lut/os/Signals.h), sent
# once the temporary output exists (the write has begun). A batch (preview) stops cooperatively
# and reports; a single command (embed) exits from the handler at once.
mkdir -p "$W/win/int"
cp "$in/look.cube" "$W/win/int/look.cube"
convert "$in/shot.png" -resize '7680x4320!' -depth 8 PNG24:"$W/win/int/big.png"
interrupt() { # NAME OUTPUT ARGS...
  local name="$1" out="$2"
  shift 2
  cp "$in/reference.png" "$W/win/int/$out"
  (
    cd "$W/win/int" || exit 1
    wine "$exe" "$@" >"$W/win/$name.out" 2>"$W/win/$name.err" </dev/null &
    local pid=$! stem="${out%.*}"
    for _ in $(seq 1 400); do
      [ -n "$(find . -name ".$stem.tmp*")" ] && break
      sleep 0.05
    done
    sleep 0.2
    kill -INT "$pid"
    wait "$pid"
    echo $? >"$W/win/$name.rc"
  )
  check "$name-exit-130" test "$(cat "$W/win/$name.rc")" = 130
  check "$name-said" grep -q 'interrupted (SIGINT)' "$W/win/$name.err"
  check "$name-no-temp" test -z "$(find "$W/win/int" -name '.*tmp*')"
  check "$name-old-kept" cmp -s "$W/win/int/$out" "$in/reference.png"
}
interrupt interrupt-batch seen.png preview big.png -o seen.png -y --lut look.cube
interrupt interrupt-now patched.png embed big.png patched.png -y
