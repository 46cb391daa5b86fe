#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
# tests/windows/diffstat.py A B: how two files lutkit wrote differ, in one line. Pictures (PNG,
# JPEG, TIFF) are decoded by ImageMagick (an outside program) and compared sample by sample, in the
# file's own bit depth; other files byte by byte. Exit 0 when identical, 1 when they differ.
import subprocess
import sys

import numpy as np


def depth_of(data):
    if data[:8] == b"\x89PNG\r\n\x1a\n":
        return data[24]
    return 8


def samples(path):
    raw = subprocess.run(["convert", path, "-depth", "16", "-endian", "MSB", "RGBA:-"],
                         check=True, capture_output=True).stdout
    size = subprocess.run(["identify", "-format", "%w %h", path + "[0]"], check=True,
                          capture_output=True, text=True).stdout.split()
    w, h = int(size[0]), int(size[1])
    return np.frombuffer(raw, dtype=">u2").astype(np.int64).reshape(h, w, 4)


def main():
    a, b = sys.argv[1], sys.argv[2]
    da, db = open(a, "rb").read(), open(b, "rb").read()
    if da == db:
        print("identical")
        return 0
    if a.lower().endswith((".png", ".jpg", ".jpeg", ".tif", ".tiff")):
        try:
            sa, sb = samples(a), samples(b)
        except (subprocess.CalledProcessError, ValueError) as e:
            sa = sb = None
            print(f"(not decoded: {e})", end=" ")
        if sa is not None and sa.shape == sb.shape:
            depth = depth_of(da)
            scale = 257 if depth == 8 else 1
            d = np.abs(sa - sb) // scale
            pixels = int(np.count_nonzero(d.max(axis=2)))
            total = d.shape[0] * d.shape[1]
            print(f"picture {d.shape[1]}x{d.shape[0]}, {depth}-bit: {pixels} of {total} pixels "
                  f"differ ({100.0 * pixels / total:.4f}%), {int(np.count_nonzero(d))} samples, "
                  f"max difference {int(d.max())} of {(1 << depth) - 1}; the files: "
                  f"{len(da)} vs {len(db)} bytes")
            return 1
    n = min(len(da), len(db))
    x = np.frombuffer(da[:n], np.uint8).astype(int)
    y = np.frombuffer(db[:n], np.uint8).astype(int)
    diff = np.abs(x - y)
    print(f"{len(da)} vs {len(db)} bytes: {int(np.count_nonzero(diff)) + abs(len(da) - len(db))} "
          f"bytes differ, max byte difference {int(diff.max()) if n else 0}")
    return 1


if __name__ == "__main__":
    sys.exit(main())
