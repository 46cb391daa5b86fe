#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# lutkit match against the plain HM-MKL-HM on outside looks (issue 42's acceptance): for each
# picture and each look, the look is made by an outside program (ffmpeg or ImageMagick), the
# reference is the graded picture with its pixels shuffled (no correspondence left), and the
# distance of each result from the truly graded picture is measured here in numpy, mean and p99 of
# every channel value in 8-bit steps:
#   auto / hm-mkl-hm   `lutkit match` (the default .cube) applied by `lutkit apply`;
#   plain              a plain HM-MKL-HM (bench/match_numpy.py's maths: np.unique and np.interp per
#                      channel, MKL by eigh, float64) tabulated at the same size as a 3D .cube,
#                      applied by ffmpeg's lut3d (tetrahedral): the floor auto must not lose to.
# Looks:
#   mix      ffmpeg: per-channel curves, then a saturation matrix (colorchannelmixer)
#   poster   ImageMagick: grey, posterised to 4 levels, mapped to a 4-tone green palette (-clut)
#   gradmap  ImageMagick: grey through a gradient map, navy (black) -> orange (white) (-clut)
#   sepia    ImageMagick: -sepia-tone 80%
# Prints a Markdown table, and the seconds of each `lutkit match` (auto, whole command).
#   /usr/bin/python3 bench/match_looks.py [--build DIR] [--size N] [--looks a,b] [--check]
#                                         [--require MEAN:P99] PICTURE...
# --check: exit 1 when auto is further than the plain HM-MKL-HM on mean or p99 in any case;
# --require: exit 1 when auto is further than MEAN / P99 steps from the truth in any case
# (tests/cli/test_match_looks.cpp runs both).
import os
import subprocess
import sys
import tempfile
import time
import json

import numpy as np



def read_ppm(path):
    """An 8-bit P6 PPM as ImageMagick and ffmpeg write it, values in [0, 1]."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
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
    w, h = int(fields[1]), int(fields[2])
    px = np.frombuffer(data, dtype=np.uint8, count=w * h * 3, offset=pos + 1)
    return px.reshape(-1, 3).astype(np.float64) / 255.0

PALETTE = ["#0f380f", "#306230", "#8bac0f", "#9bbc0f"]


def run(*args):
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def look(name, src, out):
    if name == "mix":
        run("ffmpeg", "-v", "error", "-y", "-i", src, "-vf",
            "curves=r='0/0.04 0.5/0.56 1/0.97':g='0/0 0.5/0.5 1/1':b='0/0.08 0.5/0.46 1/0.9',"
            "colorchannelmixer=rr=1.3:rg=-0.15:rb=-0.15:gr=-0.15:gg=1.3:gb=-0.15:br=-0.15:"
            "bg=-0.15:bb=1.3", "-pix_fmt", "rgb24", "-frames:v", "1", "-update", "1", out)
    elif name == "poster":
        run("convert", src, "-colorspace", "gray", "-posterize", "4", "(", "-size", "1x1",
            *[f"xc:{c}" for c in PALETTE], "+append", ")", "-clut", "-type", "TrueColor",
            "PNG24:" + out)
    elif name == "gradmap":
        run("convert", src, "-colorspace", "gray", "(", "-size", "1x256",
            "gradient:#1a1446-#ffb347", "-rotate", "-90", ")", "-clut", "-type", "TrueColor",
            "PNG24:" + out)
    elif name == "sepia":
        run("convert", src, "-sepia-tone", "80%", "-type", "TrueColor", "PNG24:" + out)
    else:
        raise ValueError(name)


def write_ppm(path, rgb01, w, h):
    data = np.clip(np.round(rgb01 * 255.0), 0, 255).astype(np.uint8).reshape(h, w, 3)
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (w, h))
        f.write(data.tobytes())


def ppm_size(path):
    out = subprocess.run(["identify", "-format", "%w %h", path], check=True, capture_output=True,
                         text=True).stdout.split()
    return int(out[0]), int(out[1])


def curve(src, ref):
    """The plain histogram match of one channel as a function (np.interp of the CDFs)."""
    s_values, s_counts = np.unique(src, return_counts=True)
    r_values, r_counts = np.unique(ref, return_counts=True)
    s_cdf = np.cumsum(s_counts) / s_counts.sum()
    r_cdf = np.cumsum(r_counts) / r_counts.sum()
    return lambda x: np.interp(np.interp(x, s_values, s_cdf), r_cdf, r_values)


def plain_cube(src, ref, size, path):
    """Plain HM-MKL-HM fitted on the pictures and tabulated on a size^3 lattice as a .cube."""
    h1 = [curve(src[:, c], ref[:, c]) for c in range(3)]
    u = np.stack([h1[c](src[:, c]) for c in range(3)], axis=1)
    a, b = np.cov(u.T), np.cov(ref.T)
    da2, ua = np.linalg.eigh(a)
    da = np.sqrt(np.maximum(da2, 1e-10))
    c_ = np.diag(da) @ ua.T @ b @ ua @ np.diag(da)
    dc2, uc = np.linalg.eigh(c_)
    dc = np.sqrt(np.maximum(dc2, 1e-10))
    t = ua @ np.diag(1.0 / da) @ uc @ np.diag(dc) @ uc.T @ np.diag(1.0 / da) @ ua.T
    mu, mr = u.mean(axis=0), ref.mean(axis=0)
    mixed = (u - mu) @ t + mr
    h2 = [curve(mixed[:, c], ref[:, c]) for c in range(3)]
    g = np.linspace(0.0, 1.0, size)
    bb, gg, rr = np.meshgrid(g, g, g, indexing="ij")  # red fastest in the file
    x = np.stack([rr.ravel(), gg.ravel(), bb.ravel()], axis=1)
    y = np.stack([h1[c](x[:, c]) for c in range(3)], axis=1)
    y = (y - mu) @ t + mr
    y = np.stack([h2[c](y[:, c]) for c in range(3)], axis=1)
    with open(path, "w") as f:
        f.write("LUT_3D_SIZE %d\n" % size)
        for v in y:
            f.write("%.6f %.6f %.6f\n" % tuple(v))


def steps(got_ppm, truth):
    d = np.abs(read_ppm(got_ppm) * 255.0 - truth * 255.0)
    return d.mean(), np.percentile(d, 99)


def main():
    args = sys.argv[1:]
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    build = os.path.join(root, "build")
    size = 33
    looks = ["mix", "poster", "gradmap", "sepia"]
    check = False
    require = None
    while args and args[0].startswith("--"):
        if args[0] == "--check":
            check = True
            args = args[1:]
            continue
        if args[0] == "--require":
            require = tuple(float(v) for v in args[1].split(":"))
        if args[0] == "--build":
            build = args[1]
        elif args[0] == "--size":
            size = int(args[1])
        elif args[0] == "--looks":
            looks = args[1].split(",")
        args = args[2:]
    lutkit = os.path.join(build, "bin", "lutkit")
    w_ = tempfile.mkdtemp(prefix="lutkit-looks.")
    p = lambda name: os.path.join(w_, name)  # noqa: E731
    print("| picture | look | no LUT | plain HM-MKL-HM %d³ | hm-mkl-hm | auto | auto method, "
          "kind | auto s |" % size)
    print("|---|---|---|---|---|---|---|---|")
    worst, missed = [], []
    for pic in args:
        name = os.path.basename(pic)
        run("convert", pic, "-alpha", "off", "-type", "TrueColor", "PNG24:" + p("src.png"))
        run("convert", p("src.png"), p("src.ppm"))
        src = read_ppm(p("src.ppm"))
        w, h = ppm_size(p("src.ppm"))
        for lk in looks:
            look(lk, p("src.png"), p("truth.png"))
            run("convert", p("truth.png"), p("truth.ppm"))
            truth = read_ppm(p("truth.ppm"))
            rng = np.random.default_rng(42)
            shuffled = truth[rng.permutation(truth.shape[0])]
            write_ppm(p("ref.ppm"), shuffled, w, h)
            run("convert", p("ref.ppm"), p("ref.png"))
            no = np.abs(src - truth).mean() * 255.0
            plain_cube(src, shuffled, size, p("plain.cube"))
            run("ffmpeg", "-v", "error", "-y", "-i", p("src.png"), "-vf",
                "lut3d=file=%s:interp=tetrahedral" % p("plain.cube"), "-pix_fmt", "rgb24",
                "-frames:v", "1", "-update", "1", p("plain.ppm"))
            plain = steps(p("plain.ppm"), truth)
            res = {}
            for m in ["hm-mkl-hm", "auto"]:
                t0 = time.perf_counter()
                out = subprocess.run([lutkit, "match", "-y", "--json", "--size", str(size),
                                      "--method", m, p("src.png"), p("ref.png"), p("look.cube")],
                                     check=True, capture_output=True, text=True).stdout
                secs = time.perf_counter() - t0
                run(lutkit, "apply", "-q", "-y", "--lut", p("look.cube"), p("src.png"), "-o",
                    p("got.ppm"))
                j = json.loads(out)
                res[m] = (steps(p("got.ppm"), truth), j["method"], j.get("look", {}).get("kind", ""),
                          secs)
            (am, ap), method, kind, secs = res["auto"]
            hm_, hp = res["hm-mkl-hm"][0]
            flag = "" if am <= plain[0] + 1e-9 and ap <= plain[1] + 1e-9 else " **LOSES**"
            print("| %s | %s | %.2f | %.2f / %.0f | %.2f / %.0f | %.2f / %.0f%s | %s %s | %.2f |" %
                  (name, lk, no, plain[0], plain[1], hm_, hp, am, ap, flag, method, kind, secs))
            sys.stdout.flush()
            if flag:
                worst.append((name, lk))
            if require and (am > require[0] or ap > require[1]):
                missed.append((name, lk, round(am, 2), round(ap)))
    print("\nauto further than the plain HM-MKL-HM (mean or p99): %d case(s) %s" %
          (len(worst), worst))
    if require:
        print("auto beyond %g / %g steps: %d case(s) %s" % (require + (len(missed), missed)))
    if (check and worst) or missed:
        sys.exit(1)


main()
