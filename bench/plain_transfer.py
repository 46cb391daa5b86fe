# SPDX-License-Identifier: Apache-2.0
# The plain HM-MKL-HM in numpy, the way colour-transfer scripts write it (issue 23's yardstick and
# issue 42's floor), shared by bench/match_numpy.py and bench/match_looks.py: per-channel
# histogram matching by np.unique and np.interp of the cumulative distributions, the
# Monge-Kantorovich linear map (F. Pitie, A. Kokaram, "The linear Monge-Kantorovitch linear colour
# mapping for example-based colour transfer", CVMP 2007) from the two covariances by eigh, then
# histogram matching again. float64. Also the PPM reading and a LUT applied by ffmpeg in float.
import os
import subprocess
import tempfile

import numpy as np


def read_ppm(path):
    """An 8-bit binary PPM (P6), as ImageMagick and ffmpeg write it: rows of RGB in [0, 1]."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; comments skipped
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P6" and fields[3] == b"255", path + ": not an 8-bit P6 PPM"
    w, h = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(data, dtype=np.uint8, count=w * h * 3, offset=pos + 1)
    return pixels.reshape(-1, 3).astype(np.float64) / 255.0


def curve(src, ref):
    """The plain histogram match of one channel as a function: T = Q_ref(F_src), the
    distribution functions by unique values and counts, joined by np.interp."""
    s_values, s_counts = np.unique(src, return_counts=True)
    r_values, r_counts = np.unique(ref, return_counts=True)
    s_cdf = np.cumsum(s_counts) / s_counts.sum()
    r_cdf = np.cumsum(r_counts) / r_counts.sum()
    return lambda x: np.interp(np.interp(x, s_values, s_cdf), r_cdf, r_values)


def mkl_map(src, ref, eps=1e-10):
    """The Monge-Kantorovich linear map from src's colours to ref's, as a function."""
    a = np.cov(src.T)
    b = np.cov(ref.T)
    da2, ua = np.linalg.eigh(a)
    da = np.sqrt(np.maximum(da2, eps))
    c = np.diag(da) @ ua.T @ b @ ua @ np.diag(da)
    dc2, uc = np.linalg.eigh(c)
    dc = np.sqrt(np.maximum(dc2, eps))
    t = ua @ np.diag(1.0 / da) @ uc @ np.diag(dc) @ uc.T @ np.diag(1.0 / da) @ ua.T
    mu, mr = src.mean(axis=0), ref.mean(axis=0)
    return lambda x: (x - mu) @ t + mr


def plain_transfer(src, ref):
    """HM-MKL-HM fitted on the two pictures' pixels (rows of RGB), as a function of colours."""
    h1 = [curve(src[:, c], ref[:, c]) for c in range(3)]
    first = lambda x: np.stack([h1[c](x[:, c]) for c in range(3)], axis=1)  # noqa: E731
    u = first(src)
    m = mkl_map(u, ref)
    mixed = m(u)
    h2 = [curve(mixed[:, c], ref[:, c]) for c in range(3)]
    return lambda x: np.stack([h2[c](y[:, c]) for y in [m(first(x))] for c in range(3)], axis=1)


def write_cube(f, size, path):
    """f tabulated on a size^3 lattice over [0, 1] as a plain 3D .cube (red fastest)."""
    g = np.linspace(0.0, 1.0, size)
    bb, gg, rr = np.meshgrid(g, g, g, indexing="ij")
    y = f(np.stack([rr.ravel(), gg.ravel(), bb.ravel()], axis=1))
    with open(path, "w") as out:
        out.write("LUT_3D_SIZE %d\n" % size)
        for v in y:
            out.write("%.6f %.6f %.6f\n" % tuple(v))


def lutkit_apply(lutkit, cube, picture):
    """A .cube applied by `lutkit apply` to a picture, 16-bit output read back through
    ImageMagick: for the .cube files ffmpeg does not read (a 1D shaper before the table)."""
    d = tempfile.mkdtemp(prefix="lutkit-lkapply.")
    png, raw = os.path.join(d, "out.png"), os.path.join(d, "out.raw")
    subprocess.run([lutkit, "apply", "-q", "-y", "--bit-depth", "16", "--lut", cube, picture,
                    "-o", png], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    subprocess.run(["convert", png, "-depth", "16", "-endian", "MSB", "rgb:" + raw], check=True)
    a = np.fromfile(raw, dtype=">u2").reshape(-1, 3).astype(np.float64) / 65535.0
    for p in (png, raw):
        os.remove(p)
    os.rmdir(d)
    return np.round(a * 255.0) / 255.0


def ffmpeg_apply(cube, rgb01, w, h):
    """A .cube applied by ffmpeg's lut3d (tetrahedral) in float, to rows of RGB; the result
    rounded to 8 bits here (ffmpeg's own 8-bit output truncates: half a step down on average, which
    would bias whichever LUT it alone applies)."""
    d = tempfile.mkdtemp(prefix="lutkit-ffapply.")
    src, out = os.path.join(d, "in.raw"), os.path.join(d, "out.raw")
    np.stack([rgb01[:, 1], rgb01[:, 2], rgb01[:, 0]]).astype("<f4").tofile(src)
    subprocess.run(["ffmpeg", "-v", "error", "-nostdin", "-y", "-f", "rawvideo", "-pix_fmt",
                    "gbrpf32le", "-s", "%dx%d" % (w, h), "-i", src, "-vf",
                    "lut3d=file=%s:interp=tetrahedral" % cube, "-f", "rawvideo", "-pix_fmt",
                    "gbrpf32le", out], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.PIPE)
    a = np.fromfile(out, dtype="<f4").reshape(3, -1).astype(np.float64)
    for p in (src, out):
        os.remove(p)
    os.rmdir(d)
    return np.round(np.clip(np.stack([a[2], a[0], a[1]], axis=1), 0.0, 1.0) * 255.0) / 255.0
