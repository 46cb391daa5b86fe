#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Byte-for-byte comparison of lutkit's outputs before and after a change (a refactor must not
# move a single byte). Two steps:
#
#   scripts/compare-outputs.sh BIN OUTDIR          run every command over the test corpus
#   scripts/compare-outputs.sh --compare DIR1 DIR2 compare two such folders
#
# BIN is a lutkit binary (build/bin/lutkit). The first form runs each command of lutkit over
# the made-up inputs of tests/data and samples/ with the options that change the bytes written
# (sizes, formats, layouts, bit depths, interpolations, methods, targets, strengths), one folder
# per case in OUTDIR: the files the command wrote, its stdout, stderr and exit code. Inputs some
# commands need (a graded picture for fit and match, a patched screenshot for extract) are made
# by earlier cases with the same BIN, so they are compared too.
#
# The second form compares every file of the two folders byte for byte, except that in the
# printed text (stdout, stderr) durations and throughputs ("0.31 s", "12 ms", "85 Mpx/s", JSON's
# "seconds") are replaced by a token first, and in files the time of writing some formats store
# (TIFF's DateTime). It prints the cases that differ and exits 1 if any does, 0 if all
# are identical. bench (only timings) is not run.
#
# Typical use (docs/architecture.md, "Refactoring without changing a byte"):
#   git stash; cmake --build build --target lutkit; cp build/bin/lutkit /tmp/lutkit-before
#   git stash pop; cmake --build build --target lutkit
#   scripts/compare-outputs.sh /tmp/lutkit-before /tmp/out-before
#   scripts/compare-outputs.sh build/bin/lutkit /tmp/out-after
#   scripts/compare-outputs.sh --compare /tmp/out-before /tmp/out-after
#
# The same comparison against a committed record instead of a second binary (ctest's
# compare_outputs runs the check on every Release build):
#
#   scripts/compare-outputs.sh --manifest DIR          the record of a folder of the first form:
#                                                     one line per file, "SHA256  CASE/FILE", of
#                                                     the text as --compare sees it (timings
#                                                     blanked) and the files undated
#   scripts/compare-outputs.sh --check BIN [MANIFEST]  runs BIN into a temporary folder and
#                                                     compares its record with MANIFEST; prints
#                                                     the files that differ, exits 1 if any does
#   scripts/compare-outputs.sh --update [BIN]          writes MANIFEST anew from BIN (default
#                                                     build/bin/lutkit)
#
# MANIFEST defaults to tests/data/compare-outputs.sha256. A change that moves bytes on purpose
# runs --update and commits the manifest with it: the commit's diff of the manifest lists the
# cases whose outputs changed (docs/architecture.md, "Refactoring without changing a byte").
set -u

usage() {
    echo "usage: $0 BIN OUTDIR | $0 --compare DIR1 DIR2 | $0 --manifest DIR |" \
        "$0 --check BIN [MANIFEST] | $0 --update [BIN]" >&2
    exit 2
}

# What the comparison sees of an output file (one perl sub, used by --compare and the record):
# in printed text (stdout, stderr) durations and throughputs become <t> (also JSON's "seconds"
# fields) and a batch's lines are sorted (each file's line comes when its thread is done); in
# files the time of writing some formats store (TIFF's DateTime, "2026:12:07 15:41:54") is
# blanked and the clone's own path is ROOT (a .cube header names its input).
NORMALISED_PL='
sub normalised {
    my ($rel, $data) = @_;
    if ($rel =~ m{/(stdout|stderr)\.txt$}) {
        my @lines = split /(?<=\n)/, $data;
        for (@lines) {
            s/[0-9]+([.,][0-9]+)?([eE][-+]?[0-9]+)? ?(ns|us|µs|ms|s|sec|seconds|min|[KMG]?i?B\/s|[KMG]?px\/s|frames\/s|fps)\b/<t>/g;
            s/"([a-z_]*seconds|[a-z_]*_ms)": \{[^}]*\}/"$1": {<t>}/g;
            s/"([a-z_]*seconds|[a-z_]*_ms)": [-+0-9.eE]+/"$1": <t>/g;
            s/[0-9.]+ [A-Za-z]+\/s\b/<t>/g;
            s/ in [0-9]+:[0-9]{2}(:[0-9]{2})?\b/ in <t>/g;
            s/^(time +).*/$1<t>/;
        }
        if ($rel =~ m{(^|/)convert-batch/}) {
            $_ .= "\n" for grep { !/\n$/ } @lines; # as sort(1) ends every line
            @lines = sort @lines;
        }
        $data = join "", @lines;
    } else {
        $data =~ s/\d{4}:\d\d:\d\d \d\d:\d\d:\d\d/0000:00:00 00:00:00/g;
        # where the clone sits is not part of the output (a .cube header names its input)
        $data =~ s/\Q$ENV{COMPARE_OUTPUTS_ROOT}\E/ROOT/g if $ENV{COMPARE_OUTPUTS_ROOT};
    }
    return $data;
}
'
# normalise REL FILE: FILE (the output REL of some folder) as the comparison sees it.
normalise() {
    COMPARE_OUTPUTS_ROOT=$ROOT_DIR perl -e "$NORMALISED_PL"'
        open(my $fh, "<:raw", $ARGV[1]) or die "$ARGV[1]: $!";
        local $/;
        my $data = <$fh> // "";
        binmode STDOUT;
        print normalised($ARGV[0], $data);' "$1" "$2"
}

# The record of a folder of outputs: "SHA256  CASE/FILE", sorted bytewise, each file as
# normalise() sees it (in one perl run: a process per file took a minute).
manifest() {
    (cd "$1" && export COMPARE_OUTPUTS_ROOT=$ROOT_DIR && find . -type f -print0 | LC_ALL=C perl -0 -MDigest::SHA=sha256_hex -e "$NORMALISED_PL"'
        my @files = sort map { s|^\./||r } map { chomp; $_ } <STDIN>;
        for my $rel (@files) {
            open(my $fh, "<:raw", $rel) or die "$rel: $!";
            local $/;
            my $data = <$fh> // "";
            close $fh;
            print sha256_hex(normalised($rel, $data)), "  $rel\n";
        }')
}

ROOT_DIR=$(cd "$(dirname "$0")/.." && pwd)
DEFAULT_MANIFEST=$ROOT_DIR/tests/data/compare-outputs.sha256

if [ "${1:-}" = "--manifest" ]; then
    [ $# -eq 2 ] && [ -d "$2" ] || usage
    manifest "$2"
    exit 0
fi

if [ "${1:-}" = "--check" ] || [ "${1:-}" = "--update" ]; then
    mode=$1
    if [ "$mode" = "--check" ]; then
        [ $# -eq 2 ] || [ $# -eq 3 ] || usage
        bin=$2
        target=${3:-$DEFAULT_MANIFEST}
        [ -f "$target" ] || { echo "$0: no manifest $target" >&2; exit 2; }
    else
        [ $# -le 2 ] || usage
        bin=${2:-$ROOT_DIR/build/bin/lutkit}
        target=$DEFAULT_MANIFEST
    fi
    work=$(mktemp -d "${TMPDIR:-/tmp}/compare-outputs.XXXXXX")
    trap 'rm -rf "$work"' EXIT
    "$0" "$bin" "$work/out" >"$work/run.log" 2>&1 || { cat "$work/run.log" >&2; exit 2; }
    manifest "$work/out" >"$work/manifest"
    if [ "$mode" = "--update" ]; then
        cp "$work/manifest" "$target"
        echo "$target: $(wc -l <"$target") files of $(ls "$work/out" | wc -l) cases"
        exit 0
    fi
    if cmp -s "$target" "$work/manifest"; then
        echo "$(wc -l <"$target") files identical to $target"
        exit 0
    fi
    # the files whose hash changed, and those only one side has
    diff <(sort -k2 "$target") <(sort -k2 "$work/manifest") | sed -n 's/^\([<>]\) [0-9a-f]*  //p' |
        sort -u | sed 's/^/differs: /'
    echo "$(diff "$target" "$work/manifest" | grep -c '^>') of $(wc -l <"$work/manifest") files" \
        "differ from $target; if the change is meant, refresh it:" \
        "scripts/compare-outputs.sh --update $bin (and commit the manifest)"
    exit 1
fi

if [ "${1:-}" = "--compare" ]; then
    [ $# -eq 3 ] || usage
    a=$2
    b=$3
    [ -d "$a" ] && [ -d "$b" ] || { echo "$0: $a or $b is not a folder" >&2; exit 2; }
    status=0
    same=0
    differ=0
    # every file of either side
    while IFS= read -r rel; do
        fa="$a/$rel"
        fb="$b/$rel"
        if [ ! -e "$fa" ] || [ ! -e "$fb" ]; then
            echo "only in $([ -e "$fa" ] && echo "$a" || echo "$b"): $rel"
            status=1
            differ=$((differ + 1))
            continue
        fi
        case "$rel" in
        */stdout.txt | */stderr.txt)
            if cmp -s <(normalise "$rel" "$fa") <(normalise "$rel" "$fb"); then
                same=$((same + 1))
            else
                echo "differs (text, timings aside): $rel"
                diff <(normalise "$rel" "$fa") <(normalise "$rel" "$fb") | head -10
                status=1
                differ=$((differ + 1))
            fi
            ;;
        *)
            if cmp -s "$fa" "$fb" || cmp -s <(normalise "$rel" "$fa") <(normalise "$rel" "$fb"); then
                same=$((same + 1))
            else
                echo "differs: $rel ($(cmp "$fa" "$fb" 2>&1 | head -1))"
                status=1
                differ=$((differ + 1))
            fi
            ;;
        esac
    done < <( (cd "$a" && find . -type f; cd "$b" && find . -type f) | sed 's|^\./||' | sort -u)
    echo "$same files identical, $differ differ ($(ls "$a" | wc -l) cases)"
    exit $status
fi

[ $# -eq 2 ] || usage
BIN=$(realpath "$1")
OUT=$2
[ -x "$BIN" ] || { echo "$0: $1 is not an executable" >&2; exit 2; }
if [ -e "$OUT" ] && [ -n "$(ls -A "$OUT" 2>/dev/null)" ]; then
    echo "$0: $OUT exists and is not empty (choose a new folder)" >&2
    exit 2
fi
mkdir -p "$OUT"
OUT=$(realpath "$OUT")
ROOT=$(cd "$(dirname "$0")/.." && pwd)
D=$ROOT/tests/data
S=$ROOT/samples
# The same answers everywhere: lutkit's own OpenColorIO config, no user settings.
unset OCIO
export LC_ALL=C
export HOME="$OUT/.home"
mkdir -p "$HOME"

cases=0
failed_to_start=0
# run NAME ARGS...: runs lutkit ARGS in $OUT/NAME (outputs named relative to it).
run() {
    local name=$1
    shift
    local dir="$OUT/$name"
    mkdir -p "$dir"
    (cd "$dir" && "$BIN" "$@" >stdout.txt 2>stderr.txt </dev/null)
    echo $? >"$dir/exit-code.txt"
    # the folders' own paths are not part of the output
    sed -i "s|$OUT|OUT|g; s|$ROOT|ROOT|g" "$dir/stdout.txt" "$dir/stderr.txt"
    cases=$((cases + 1))
}

# ---- neutral: every writer, layouts, bit depths
for f in cube nutexb spi3d flame lustre csp clf ctf cub itx houdini; do
    run "neutral-$f" neutral "out.$f" --format "$f" --size 17
done
run neutral-strip neutral out.png --format strip --size 17
run neutral-hald neutral out.png --format hald --size 16
for l in unreal unity smush hald reshade unity-32; do
    run "neutral-layout-$l" neutral out.png --layout "$l"
done
for b in 8 16 32; do
    run "neutral-strip-$b" neutral out.tif --bit-depth "$b"
done
run neutral-level neutral out.png --level 4
run neutral-title neutral out.cube --size 5 --title "made-up title"
run neutral-nutexb-name neutral out.nutexb --name other_name

# ---- info and validate over the corpus (text only)
i=0
for f in "$D"/cube/*.cube "$D"/cube/malformed/*.cube "$D"/nutexb/*.nutexb "$D"/strip/*.png \
    "$D"/hald/*.png "$D"/ocio/*.* "$D"/ocio/corpus/*.cube "$D"/ocio/corpus/*.spi3d \
    "$D"/ocio/corpus/*.3dl "$D"/ocio/corpus/*.csp "$D"/ocio/corpus/*.spi1d "$D"/ocio/corpus/clf/*.clf; do
    i=$((i + 1))
    run "info-$i-$(basename "$f")" info "$f" --json
    run "validate-$i-$(basename "$f")" validate --strict "$f"
done

# ---- convert: formats, sizes, layouts, interpolations, strengths, targets, the corpus
G=$S/sample_grade.cube
for f in cube nutexb spi3d flame lustre csp clf ctf cub itx houdini; do
    run "convert-$f" convert "$G" "out.$f" --format "$f" --json
done
run convert-strip convert "$G" out.png --format strip --json
run convert-hald convert "$G" out.png --format hald --json
for interp in nearest trilinear tetrahedral; do
    run "convert-size9-$interp" convert "$G" out.cube --size 9 --interp "$interp"
done
for l in unreal unity smush hald reshade unity-32; do
    run "convert-layout-$l" convert "$G" out.png --layout "$l"
done
run convert-level convert "$G" out.png --level 5
run convert-dither convert "$G" out.png --dither --bit-depth 8
run convert-16bit convert "$G" out.tif --bit-depth 16
run convert-strength convert "$G" out.cube --strength 0.6
run convert-luma-chroma convert "$G" out.cube --luma-strength 0.5 --chroma-strength 1.4
run convert-reshade-blend convert "$G" out.cube --strength 0.7 --strength-blend reshade
run convert-smash-target convert "$G" out.nutexb --target smash
run convert-smash-refine convert "$G" out.nutexb --target smash --refine --screenshot "$S/sample_scene.png"
run convert-raw-nutexb convert "$G" out.nutexb --target raw
run convert-from-nutexb convert "$D/nutexb/graded4_srgb.nutexb" out.cube --json
run convert-from-nutexb-raw convert "$D/nutexb/graded4_tiled.nutexb" out.cube --in-target raw
run convert-from-strip convert "$D/strip/graded5_smush_rgba8.png" out.cube
run convert-from-hald convert "$D/hald/graded_level3.png" out.cube
run convert-1d convert "$D/cube/adobe_1d.cube" out.cube
run convert-shaper convert "$D/cube/resolve_shaper_3d.cube" out.spi3d
run convert-domain convert "$D/cube/adobe_3d_domain.cube" out.cube
run convert-ocio-clf convert "$D/ocio/corpus/clf/lut3d_17x17x17_10i_12i.clf" out.cube --size 17
run convert-ocio-csp convert "$D/ocio/affine.csp" out.cube --size 9
run convert-ocio-cdl convert "$D/ocio/corpus/cdl_test1.ccc" out.cube --cccid 1 --size 9
run convert-ocio-3dl convert "$D/ocio/corpus/lustre_33x33x33.3dl" out.cube
run convert-colour convert "$G" out.cube --from sRGB --to 'Linear Rec.709 (sRGB)' --size 9
mkdir -p "$OUT/_batch-in"
cp "$G" "$D/cube/size2.cube" "$D/cube/resolve_3d_video.cube" "$OUT/_batch-in/"
run convert-batch convert "$OUT/_batch-in" -o outdir/ --format spi3d --size 9

# ---- apply and preview over the sample scene
P=$S/sample_scene.png
run apply-png apply "$P" --lut "$G" -o graded.png
run apply-16 apply "$P" --lut "$G" -o graded.tif --bit-depth 16 --compression zip
run apply-exr apply "$S/sample_scene.exr" --lut "$G" -o graded.exr --compression piz
for interp in nearest tetrahedral; do
    run "apply-$interp" apply "$P" --lut "$G" -o graded.png --interp "$interp"
done
run apply-strength apply "$P" --lut "$G" -o graded.png --strength 0.5 --strength-blend reshade
run apply-nutexb apply "$P" --lut "$D/nutexb/graded4_srgb.nutexb" -o graded.png
run apply-smash-default apply "$P" --lut builtin:smash-default -o graded.png
run apply-colour apply "$P" --lut "$G" -o graded.exr --from sRGB --lut-space sRGB --to 'Linear Rec.709 (sRGB)'
for preset in smash filmic cinematic none; do
    run "preview-$preset" preview "$P" --preset "$preset" --lut "$G" -o shown.png
done
run preview-scene preview "$P" --scene --lut "$D/nutexb/graded4_srgb.nutexb" -o shown.png --frame 3
run preview-no-bloom preview "$P" --no-bloom --lut "$G" -o shown.png --bit-depth 16
run preview-list preview --list-stages

# ---- embed and extract, fit and match (the lattice solvers)
run embed-smash embed "$P" patched.png --target smash
run embed-raw embed "$P" patched.png --target raw --size 12 --scale 2 --corner bottom-right
run embed-layout embed "$P" patched.tif --layout unity --lattice uniform --size 8
run apply-patched apply "$OUT/embed-smash/patched.png" --lut "$G" -o graded.png
run apply-patched-raw apply "$OUT/embed-raw/patched.png" --lut "$G" -o graded.png
run extract-smash extract "$OUT/apply-patched/graded.png" out.nutexb -v
run extract-smash-refine extract "$OUT/apply-patched/graded.png" out.cube --target smash --refine
run extract-raw extract "$OUT/apply-patched-raw/graded.png" out.cube --size 17 -v
run extract-raw-strength extract "$OUT/apply-patched-raw/graded.png" out.cube --strength 0.5
for f in "$D"/roundtrip/*.png; do
    run "extract-corpus-$(basename "$f" .png)" extract "$f" out.cube -v
done
run extract-lut-image extract "$D/strip/graded5_smush_rgba8.png" out.cube
GR=$OUT/apply-png/graded.png
run fit-default fit "$P" "$GR" out.cube
run fit-size17 fit "$P" "$GR" out.cube --size 17 --smoothness 0.3
run fit-size8-plain fit "$P" "$GR" out.cube --size 8 --no-robust
run fit-smooth0 fit "$P" "$GR" out.cube --size 9 --smoothness 0
run fit-nutexb fit "$P" "$GR" out.nutexb
for m in auto hm mkl hm-mkl-hm regularised gradient-map; do
    run "match-$m" match "$P" "$GR" out.cube --method "$m" --json
done
for form in shaper table; do
    run "match-form-$form" match "$P" "$GR" out.cube --lut-form "$form" --size 17
done
run match-preserve match "$P" "$GR" out.cube --preserve luma skin --size 17
run match-regularised-17 match "$P" "$GR" out.cube --method regularised --size 17
run match-smash match "$P" "$GR" out.nutexb --target smash --report-image report.png
run match-two-refs match "$P" "$GR" "$OUT/preview-filmic/shown.png" out.cube --size 17
run match-strength match "$P" "$GR" out.cube --strength 0.7 --size 17

# ---- LUT maths
A=$G
B=$D/cube/resolve_3d_video.cube
run diff diff "$A" "$B" --json --heatmap heat.png
run diff-image diff "$A" "$B" --image "$P" --heatmap heat.png --interp tetrahedral
run diff-slices diff "$A" "$B" --size 9 --slices 3 --heatmap heat.png
run compose compose "$A" "$B" out.cube
run compose-size compose "$A" "$B" out.cube --size 9 --interp tetrahedral
run compose-smash compose "$A" "$B" out.nutexb --target smash
run invert invert "$A" out.cube --json
run invert-range invert "$A" out.cube --output-range --size 17 -v
run invert-1d invert "$D/cube/adobe_1d.cube" out.cube
run resize resize "$A" out.cube --size 9
run resize-tetra resize "$A" out.cube --size 65 --interp tetrahedral
run resize-nearest resize "$A" out.cube --size 5 --interp nearest
run smooth smooth "$A" out.cube
run smooth-sigma smooth "$A" out.cube --sigma 2.5
run mix mix "$A" "$B" out.cube --strength 0.3
run mix-extrapolate mix "$A" "$B" out.cube --strength 1.5 --interp tetrahedral
run mix-smash mix "$A" "$B" out.nutexb --target smash
run plot plot "$A" out.png
run plot-points plot "$A" out.png --lattice-points 5
printf 'exposure 0.3\nsaturation 1.2\ncontrast 1.1\n' >"$OUT/_adjust.txt"
run adjust adjust "$A" out.cube --adjustments "$OUT/_adjust.txt" -v
run check check "$A" "$B" --json --report reports/
run check-image check "$A" --image "$P" -v
run check-smash check "$D/nutexb/graded4_srgb.nutexb" --target smash
for c in grey hue-saturation hue-lightness skin slices all; do
    run "chart-$c" chart "$c" out.png --width 256
done
run chart-exr chart all out.exr --bit-depth 32
run atlas-build atlas build "$A" "$B" -o atlas.png --neutral-first --layout unreal --size 16
run atlas-info atlas info "$OUT/atlas-build/atlas.png"
run atlas-split atlas split "$OUT/atlas-build/atlas.png" -o parts/

# ---- bake (OpenColorIO)
run bake-lut bake out.cube --lut "$A" --size 17
run bake-invlut bake out.spi3d --invlut "$D/cube/adobe_1d.cube" --size 9
run bake-spaces bake out.cube --config "$D/ocio/test_config.ocio" --inputspace lin --outputspace log --size 9
run bake-shaper bake out.csp --lut "$A" --shaper log2 --size 17

echo "$cases cases run into $OUT"
