#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the hostile image files of issue 29 into tests/data/fuzz-regress/image_oiio/ as
reject-* inputs: regress_tests replays each through fuzz_image_oiio's target and requires it to
be refused. Each is built here byte by byte from its format's specification (the JPEG and the cut
TIFF start from files oiiotool writes). Run once; the files are checked in."""
import os
import shutil
import struct
import subprocess
import tempfile
import zlib

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "..", "data", "fuzz-regress", "image_oiio")
os.makedirs(out, exist_ok=True)


def put(name, data):
    with open(os.path.join(out, "reject-" + name), "wb") as f:
        f.write(data)


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


PNG = b"\x89PNG\r\n\x1a\n"
IDAT1 = zlib.compress(b"\0")

# TGA, RLE, 65535x65535 in 82 bytes (preview allocated 4.3 GB).
put("tga-rle-65535-square", (bytes([0, 0, 10]) + bytes(9) + struct.pack("<HH", 65535, 65535)
                             + bytes([32, 8])).ljust(82, b"\x7f"))
# PNG, 16384x16384 RGBA (the pixel limit) in a 10-byte IDAT.
put("png-16384-square-in-10-bytes", PNG + chunk(b"IHDR", struct.pack(">IIBBBBB", 16384, 16384, 8,
                                                                     6, 0, 0, 0))
    + chunk(b"IDAT", IDAT1) + chunk(b"IEND", b""))
# PNG, interlaced 16-bit 2000x2000 (32 MB stored), padded with a private chunk to 40 KB (the
# file's size passed the old check: 40 KB x 1032; its IDAT does not).
put("png-interlaced-padded-private-chunk", PNG + chunk(b"IHDR", struct.pack(
    ">IIBBBBB", 2000, 2000, 16, 6, 0, 0, 1)) + chunk(b"prIv", bytes(40000))
    + chunk(b"IDAT", IDAT1) + chunk(b"IEND", b""))
# Radiance HDR 1x100000000: flat scanlines, 4 bytes a pixel, in 64 bytes.
put("hdr-1x100000000", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000000 +X 1\n".ljust(64, b"\0"))


def tiff(w, h):
    tags = [(256, 4, 1, w), (257, 4, 1, h), (258, 3, 1, 8), (259, 3, 1, 1), (262, 3, 1, 1),
            (273, 4, 1, 152), (277, 3, 1, 1), (278, 4, 1, h), (279, 4, 1, 16), (284, 3, 1, 1),
            (296, 3, 1, 1)]
    s = b"II*\0" + struct.pack("<IH", 8, len(tags))
    s += b"".join(struct.pack("<HHII", *t) for t in tags) + struct.pack("<I", 0)
    return s.ljust(168, b"\x7f")


put("tiff-2pow31-by-2", tiff(2 ** 31, 2))
put("tiff-65535-square", tiff(65535, 65535))
put("tiff-16000-square-in-16-bytes", tiff(16000, 16000))
# PSD: a 2 GB colour mode block in 62 bytes (2.1 GB allocated).
put("psd-colour-mode-2gb", (b"8BPS" + struct.pack(">H6xHIIHH", 1, 3, 2, 2, 8, 3)
                            + struct.pack(">I", 0x7FFFFFFF)).ljust(62, b"\0"))
# GIF: a 60000x60000 screen; a 4000x4000 frame in 3 bytes of LZW.
put("gif-screen-60000-square", b"GIF89a" + struct.pack("<HH", 60000, 60000) + b"\0\0\0;")
put("gif-frame-4000-square-in-3-bytes", b"GIF89a" + struct.pack("<HH", 4000, 4000) + b"\0\0\0,"
    + struct.pack("<HHHH", 0, 0, 4000, 4000) + b"\0\x08\x03\x01\x02\x03\0;")
# BMP 2000x2000 24-bit uncompressed with 10 bytes of pixels.
put("bmp-2000-square-in-10-bytes", (b"BM" + struct.pack("<IIIIiiHHIIIIII", 64, 0, 54, 40, 2000,
                                                         2000, 1, 24, 0, 0, 0, 0, 0, 0)).ljust(64, b"\0"))
# Maya IFF 4000x4000 RGBA RLE in 52 bytes.
put("iff-4000-square-in-52-bytes", b"FOR4" + struct.pack(">I", 48) + b"CIMGTBHD" + struct.pack(
    ">IIIHHIHHIII", 32, 4000, 4000, 1, 1, 3, 0, 1, 1, 0, 0))
# DPX 3000x3000 10-bit RGB in 2 KiB.
dpx = bytearray(2048)
dpx[0:4] = b"SDPX"
dpx[4:8] = struct.pack(">I", 2048)
dpx[772:780] = struct.pack(">II", 3000, 3000)
dpx[800], dpx[803], dpx[805] = 50, 10, 1
dpx[808:812] = struct.pack(">I", 2048)
put("dpx-3000-square-in-2k", bytes(dpx))


def dpx_le(user, w, h, encoding):
    """A little-endian DPX, one 16-bit RGB element at byte 2048 (OpenImageIO reads it when its
    fields are honest)."""
    s = bytearray(2048 + 1152)
    s[0:4] = b"XPDS"
    struct.pack_into("<I", s, 4, 2048)
    s[8:12] = b"V2.0"
    struct.pack_into("<IIIII", s, 16, len(s), 0, 1664, 384, user)
    struct.pack_into("<HHII", s, 768, 0, 1, w, h)
    s[800], s[803] = 50, 16
    struct.pack_into("<HHI", s, 804, 0, encoding, 2048)
    return bytes(s)


# DPX whose user data size says 2 GB (OpenImageIO allocated it at open: 14 GB peak; found by
# fuzz_image_apply); a run-length encoded element 2^28 pixels wide (a 384 GB row buffer asked).
put("dpx-user-data-2gb", dpx_le(0x7FFFFFF0, 16, 12, 0))
put("dpx-run-length-wide", dpx_le(0, 1 << 28, 1, 1))
# OpenEXR: one 10000x10000 half RGB ZIP part in a 100-byte chunk area.


def attr(name, kind, value):
    return name + b"\0" + kind + b"\0" + struct.pack("<I", len(value)) + value


chans = b"".join(c + b"\0" + struct.pack("<i4xii", 1, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
put("exr-10000-square-zip-in-100-bytes", b"\x76\x2f\x31\x01\x02\0\0\0" + attr(b"channels", b"chlist", chans)
    + attr(b"compression", b"compression", b"\x03")
    + attr(b"dataWindow", b"box2i", struct.pack("<iiii", 0, 0, 9999, 9999)) + b"\0" + bytes(100))

oiiotool = shutil.which("oiiotool")
if oiiotool:
    with tempfile.TemporaryDirectory() as tmp:
        # A JPEG whose frame header claims 4000x4000 (refused by its bytes) and 128x128 (libjpeg's
        # "premature end of data segment": the rest was grey).
        jpg = os.path.join(tmp, "s.jpg")
        subprocess.run([oiiotool, "--pattern", "fill:top=0.2,0.4,0.6:bottom=0.9,0.1,0.3", "64x64",
                        "3", "-d", "uint8", "-o", jpg], check=True)
        b = bytearray(open(jpg, "rb").read())
        i = 2
        while b[i + 1] != 0xC0:
            i += 2 + (b[i + 2] << 8 | b[i + 3])
        for w, name in ((4000, "jpeg-claims-4000-square"), (128, "jpeg-claims-128-square")):
            c = bytearray(b)
            c[i + 5:i + 9] = struct.pack(">HH", w, w)
            put(name, bytes(c))
        # A zip TIFF cut at 60% (its directory first, its last strips gone: black rows, exit 0).
        tif = os.path.join(tmp, "s.tif")
        subprocess.run([oiiotool, "--pattern", "fill:top=0.2,0.4,0.6:bottom=0.9,0.1,0.3",
                        "256x256", "3", "-d", "uint8", "--compression", "zip", "-o", tif], check=True)
        t = open(tif, "rb").read()
        put("tiff-zip-cut-short", t[:len(t) * 6 // 10])
print("image_oiio rejects:", len([f for f in os.listdir(out) if f.startswith("reject-")]))
