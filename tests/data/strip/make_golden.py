#!/usr/bin/env python3
"""Golden LUT images for tests/formats/test_strip_golden.cpp, written with a minimal PNG encoder
(zlib + struct) straight from the layout formulas of docs/specs/strip-layouts.md, independently
of lutkit and OpenImageIO. Re-run to regenerate (also writes ../hald/)."""
import os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))

def png(path, w, h, rows, bits, channels):
    ctype = {1: 0, 3: 2, 4: 6}[channels]
    raw = b""
    for row in rows:
        raw += b"\0"
        for px in row:
            for v in px:
                raw += struct.pack(">H", v) if bits == 16 else bytes([v])
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, bits, ctype, 0, 0, 0))
    data += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(data)

def graded(r, g, b, mx):
    # The same pattern the tests compute: distinct per entry and channel.
    return ((r * 37 + g * 11 + b * 5) % (mx + 1), (r * 3 + g * 71 + b * 13) % (mx + 1),
            (r * 7 + g * 17 + b * 101) % (mx + 1))

def pixel_of(layout, n, r, g, b):
    if layout == "pilot":
        return r + n * b, g
    if layout == "unity":
        return r + n * b, n - 1 - g
    if layout == "smush":
        return r + n * g, b
    level = round(n ** 0.5)
    side = level ** 3
    i = r + n * g + n * n * b
    return i % side, i // side

def image(layout, n, value, channels):
    if layout == "hald":
        w = h = round(n ** 0.5) ** 3
    else:
        w, h = n * n, n
    rows = [[None] * w for _ in range(h)]
    for b in range(n):
        for g in range(n):
            for r in range(n):
                x, y = pixel_of(layout, n, r, g, b)
                v = value(r, g, b)
                rows[y][x] = v + ((255,) if channels == 4 else ())
    return w, h, rows

def main():
    n4 = lambda r, g, b: (r * 85, g * 85, b * 85)  # neutral 4^3: 255*i/3
    for layout in ("pilot", "unity", "smush"):
        w, h, rows = image(layout, 4, n4, 3)
        png(os.path.join(HERE, "neutral4_%s.png" % layout), w, h, rows, 8, 3)
    w, h, rows = image("smush", 5, lambda r, g, b: graded(r, g, b, 255), 4)
    png(os.path.join(HERE, "graded5_smush_rgba8.png"), w, h, rows, 8, 4)
    w, h, rows = image("unity", 3, lambda r, g, b: graded(r, g, b, 65535), 3)
    png(os.path.join(HERE, "graded3_unity16.png"), w, h, rows, 16, 3)
    # Alpha 128 everywhere: the colour must still read as stored (no premultiplication).
    w, h, rows = image("pilot", 4, n4, 4)
    rows = [[px[:3] + (128,) for px in row] for row in rows]
    png(os.path.join(HERE, "neutral4_pilot_alpha128.png"), w, h, rows, 8, 4)
    hald = os.path.join(HERE, "..", "hald")
    os.makedirs(hald, exist_ok=True)
    w, h, rows = image("hald", 4, n4, 3)
    png(os.path.join(hald, "neutral_level2.png"), w, h, rows, 8, 3)
    w, h, rows = image("hald", 9, lambda r, g, b: graded(r, g, b, 255), 3)
    png(os.path.join(hald, "graded_level3.png"), w, h, rows, 8, 3)

if __name__ == "__main__":
    main()
