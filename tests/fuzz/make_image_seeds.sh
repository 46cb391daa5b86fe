#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Writes the seed corpus of fuzz_image_oiio (tests/fuzz/corpus/image_oiio/): small real files of
# every format OpenImageIO reads for lutkit, in the variants whose code paths differ (strips and
# tiles, compressions, bit depths, several pages, parts or frames, MIP levels). Made with
# oiiotool (OpenImageIO's own writer); PSD, which OpenImageIO does not write, by hand from the
# Adobe specification (raw and PackBits merged image, one layer). Run once; the files are
# checked in. Usage: tests/fuzz/make_image_seeds.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="$here/corpus/image_oiio"
mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# A 16x12 gradient with some structure (corners of different colours), RGB and RGBA.
oiiotool --pattern fill:topleft=0,0,0,1:topright=1,0,0,1:bottomleft=0,1,0,0.5:bottomright=0,0,1,1 \
  16x12 4 -d float -o "$tmp/rgba.exr"
oiiotool "$tmp/rgba.exr" --ch R,G,B -o "$tmp/rgb.exr"
oiiotool --pattern checker:width=4:height=4 16x12 3 -d float -o "$tmp/checker.exr"

seed() { # NAME oiiotool-args... (the last is the output file's extension)
  local name="$1"; shift
  local ext="${@: -1}"; set -- "${@:1:$(($#-1))}"
  oiiotool "$@" -o "$tmp/s.$ext"
  cp "$tmp/s.$ext" "$out/$name"
}

# TIFF
seed tiff-strip-8 "$tmp/rgb.exr" -d uint8 tif
seed tiff-strip-16-lzw "$tmp/rgba.exr" -d uint16 --compression lzw tif
seed tiff-strip-zip-float "$tmp/rgb.exr" -d float --compression zip tif
seed tiff-packbits "$tmp/rgb.exr" -d uint8 --compression packbits tif
seed tiff-tiled "$tmp/rgba.exr" -d uint8 --tile 16 16 tif
oiiotool "$tmp/rgb.exr" --resize 20x12 -o "$tmp/wide.exr"
seed tiff-tiled-partial "$tmp/wide.exr" -d uint16 --tile 16 16 --compression zip tif
seed tiff-jpeg "$tmp/rgb.exr" -d uint8 --compression jpeg tif
seed tiff-two-pages "$tmp/rgb.exr" "$tmp/checker.exr" --siappend -d uint8 tif
seed tiff-grey "$tmp/rgb.exr" --ch R -d uint8 tif
# JPEG
seed jpeg-baseline "$tmp/rgb.exr" -d uint8 jpg
seed jpeg-420 "$tmp/checker.exr" -d uint8 --attrib jpeg:subsampling 4:2:0 jpg
seed jpeg-progressive "$tmp/rgb.exr" -d uint8 --attrib jpeg:progressive 1 jpg
seed jpeg-grey "$tmp/rgb.exr" --ch R -d uint8 jpg
# TGA
seed tga-raw "$tmp/rgba.exr" -d uint8 tga
seed tga-rle "$tmp/checker.exr" -d uint8 --compression rle tga
# BMP
seed bmp-24 "$tmp/rgb.exr" -d uint8 bmp
seed bmp-32 "$tmp/rgba.exr" -d uint8 bmp
# Radiance HDR (16 pixels wide: run-length coded scanlines)
seed hdr-rle "$tmp/rgb.exr" hdr
oiiotool "$tmp/rgb.exr" --resize 4x3 -o "$tmp/small.exr"
seed hdr-flat "$tmp/small.exr" hdr
# DPX
seed dpx-10 "$tmp/rgb.exr" -d uint16 --attrib oiio:BitsPerSample 10 dpx
seed dpx-8 "$tmp/rgb.exr" -d uint8 dpx
seed dpx-16-rgba "$tmp/rgba.exr" -d uint16 dpx
# GIF
seed gif-one "$tmp/rgb.exr" -d uint8 gif
seed gif-two-frames "$tmp/rgb.exr" "$tmp/checker.exr" --siappend -d uint8 gif
# OpenEXR through OpenImageIO: tiled, MIP-mapped, several parts
seed exr-tiled-half "$tmp/rgba.exr" -d half --tile 16 16 exr
seed exr-tiled-partial-piz "$tmp/rgb.exr" -d float --tile 8 8 --compression piz exr
seed exr-two-parts "$tmp/rgb.exr" "$tmp/checker.exr" --siappend -d half exr
oiiotool "$tmp/rgb.exr" -d half --tile 8 8 -otex "$tmp/mip.exr" && cp "$tmp/mip.exr" "$out/exr-mipmapped"
# Maya IFF (always tiled)
seed iff-rgb "$tmp/rgb.exr" -d uint8 iff
seed iff-rgba-16 "$tmp/rgba.exr" -d uint16 iff
# WebP
seed webp-lossy "$tmp/rgb.exr" -d uint8 webp
seed webp-lossless "$tmp/rgba.exr" -d uint8 --compression lossless webp

# PSD, by hand (Adobe Photoshop File Formats Specification): 4x2 RGB, 8 bits.
python3 - "$out" <<'PY'
import struct, sys
out = sys.argv[1]
w, h, ch = 4, 2, 3
planes = [bytes((x * 60 + c * 20) % 256 for y in range(h) for x in range(w)) for c in range(ch)]

def header():
    return b"8BPS" + struct.pack(">H6xHIIHH", 1, ch, h, w, 8, 3)

def packbits_row(row):
    return bytes([len(row) - 1]) + row  # one literal run

raw = header() + struct.pack(">III", 0, 0, 0) + struct.pack(">H", 0) + b"".join(planes)
open(f"{out}/psd-raw", "wb").write(raw)
rows = [packbits_row(p[y * w:(y + 1) * w]) for p in planes for y in range(h)]
rle = (header() + struct.pack(">III", 0, 0, 0) + struct.pack(">H", 1)
       + b"".join(struct.pack(">H", len(r)) for r in rows) + b"".join(rows))
open(f"{out}/psd-rle", "wb").write(rle)
# One layer covering the image, its channels raw, then the merged image.
chans = b"".join(struct.pack(">hI", i, 2 + w * h) for i in range(ch))
# Extra data: no mask, no blending ranges, an empty name padded to 4 bytes.
extra = struct.pack(">II", 0, 0) + b"\0\0\0\0"
record = (struct.pack(">iiiiH", 0, 0, h, w, ch) + chans + b"8BIMnorm" + bytes([255, 0, 0, 0])
          + struct.pack(">I", len(extra)) + extra)
layer_data = b"".join(struct.pack(">H", 0) + p for p in planes)
info = struct.pack(">h", 1) + record + layer_data
if len(info) % 2:
    info += b"\0"
layers = struct.pack(">I", len(info)) + info + struct.pack(">I", 0)
layered = (header() + struct.pack(">II", 0, 0) + struct.pack(">I", len(layers)) + layers
           + struct.pack(">H", 0) + b"".join(planes))
open(f"{out}/psd-one-layer", "wb").write(layered)
PY
ls -l "$out" | awk '{s += $5} END {print "image_oiio seeds: " NR - 1 " files, " s " bytes"}'
