#!/usr/bin/env python3
"""Builds the nutexb golden files and the malformed corpus (one defect per file) straight from
the formulas in docs/specs/nutexb.md, independently of lutkit's writer. Re-run to regenerate.
The expected error for each bad_*.nutexb is asserted in tests/formats/test_nutexb_malformed.cpp."""
import hashlib, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))

def gob(xg, yg):
    return (xg // 32) * 256 + (yg // 2) * 64 + ((xg % 32) // 16) * 32 + (yg % 2) * 16 + (xg % 16)

def bd_for(d):
    d2 = d + d // 2
    for v in (16, 8, 4, 2):
        if d2 >= v:
            return v
    return 1

def cdiv(a, b):
    return (a + b - 1) // b

def tiled(n, texel):
    bpp, bh, bd = 4, 1, bd_for(n)
    W = cdiv(n * bpp, 64)
    block = 512 * bh * bd
    size = W * cdiv(n, 8 * bh) * bh * (cdiv(n, bd) * bd) * 512
    out = bytearray(size)
    slice_ = cdiv(n, 8 * bh) * W * block
    for z in range(n):
        for y in range(n):
            for x in range(n):
                xb = x * bpp
                addr = ((z // bd) * slice_ + (z % bd) * 512 * bh + (y // (8 * bh)) * W * block
                        + ((y % (8 * bh)) // 8) * 512 + (xb // 64) * block + gob(xb % 64, y % 8))
                out[addr:addr + 4] = texel(x, y, z)
    return bytes(out)

def linear(n, texel):
    return b"".join(texel(x, y, z) for z in range(n) for y in range(n) for x in range(n))

def footer(n, data_size, name=b"color_grading_lut", fmt=0x0400, ttype=8, mips=1, tiling=0x1000,
           layers=1, w=None, h=None, d=None, magic1=b" XNT", magic2=b" XET", untiled=None):
    w = n if w is None else w
    h = n if h is None else h
    d = n if d is None else d
    table = struct.pack("<I", n * n * n * 4 if untiled is None else untiled).ljust(0x40, b"\0")
    f = magic1 + name.ljust(64, b"\0")
    f += struct.pack("<IIIIIIIII", w, h, d, fmt, ttype, mips, tiling, layers, data_size)
    f += magic2 + struct.pack("<HH", 1, 2)
    assert len(f) == 0x70
    return table + f

def neutral(n):
    s = 255 / (n - 1)
    return lambda x, y, z: bytes((round(x * s), round(y * s), round(z * s), 255))

def graded(n):
    # Arbitrary but deterministic 8-bit values, alpha 255.
    return lambda x, y, z: bytes(((x * 37 + y * 11 + z * 5) % 256, (x * 3 + y * 71 + z * 13) % 256,
                                  (x * 7 + y * 17 + z * 101) % 256, 255))

def write(name, data):
    with open(os.path.join(HERE, name), "wb") as fh:
        fh.write(data)

def main():
    ref = tiled(16, neutral(16))
    good16 = ref + footer(16, len(ref))
    assert len(good16) == 16560
    assert hashlib.sha256(good16).hexdigest() == \
        "0320481c091b10c63b605ce1045e66d15fcc0b568ca99d91400bb566f816f272"
    write("neutral16.nutexb", good16)
    g4 = tiled(4, graded(4))
    write("graded4_tiled.nutexb", g4 + footer(4, len(g4)))
    l4 = linear(4, graded(4))
    write("graded4_linear.nutexb", l4 + footer(4, len(l4), tiling=0))
    s4 = g4
    write("graded4_srgb.nutexb", s4 + footer(4, len(s4), fmt=0x0405))

    good = g4 + footer(4, len(g4))
    write("bad_truncated_tiny.nutexb", good[-0x50:])
    write("bad_truncated_data.nutexb", good[:len(good) - 0xB0 - 100] + good[-0xB0:])
    write("bad_magic_xnt.nutexb", g4 + footer(4, len(g4), magic1=b"XXXX"))
    write("bad_magic_xet.nutexb", g4 + footer(4, len(g4), magic2=b"\0XET"))
    write("bad_format_bc7.nutexb", g4 + footer(4, len(g4), fmt=0x04e0))
    write("bad_format_bgra.nutexb", g4 + footer(4, len(g4), fmt=0x0450))
    write("bad_width_huge.nutexb", g4 + footer(4, len(g4), w=1 << 31, h=1 << 31, d=1 << 31))
    write("bad_height.nutexb", g4 + footer(4, len(g4), h=8))
    write("bad_depth1.nutexb", g4 + footer(4, len(g4), d=1))
    write("bad_width_zero.nutexb", g4 + footer(4, len(g4), w=0))
    write("bad_layers.nutexb", g4 + footer(4, len(g4), layers=2))
    write("bad_mips_zero.nutexb", g4 + footer(4, len(g4), mips=0))
    write("bad_tiling.nutexb", g4 + footer(4, len(g4), tiling=0x20))
    write("bad_type_2d.nutexb", g4 + footer(4, len(g4), ttype=4))
    # Declares the linear size (256) while saying tiled (2048 expected).
    write("bad_tiled_size.nutexb", l4 + footer(4, len(l4), tiling=0x1000))
    # Data size right, but extra bytes before it: the length does not add up.
    write("bad_file_size.nutexb", b"\0" * 16 + g4 + footer(4, len(g4)))
    # Data size larger than the bytes before the mip table.
    write("bad_data_past_table.nutexb", g4[:1024] + footer(4, len(g4)))

if __name__ == "__main__":
    main()
