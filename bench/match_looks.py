#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# lutkit match against the plain HM-MKL-HM on outside looks (issue 42's acceptance): for each
# picture and each look, the look is made by an outside program (ffmpeg or ImageMagick), the
# reference is the graded picture with its pixels shuffled (no correspondence left), and the
# distance of each result from the truly graded picture is measured here in numpy, mean and p99 of
# every channel value in 8-bit steps:
#   auto / hm-mkl-hm   `lutkit match`'s default .cube;
#   plain              a plain HM-MKL-HM (bench/plain_transfer.py: np.unique and np.interp per
#                      channel, MKL by eigh, float64) tabulated at the same size as a 3D .cube:
#                      the floor auto must not lose to.
# Every LUT is applied by the same outside program, ffmpeg's lut3d (tetrahedral), in float, and
# rounded to 8 bits here (ffmpeg's 8-bit output truncates, half a step down on average); a .cube
# with a 1D shaper, which ffmpeg does not read, by `lutkit apply` (16 bits, rounded here).
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
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plain_transfer import (ffmpeg_apply, lutkit_apply, plain_transfer, read_ppm,  # noqa: E402
                            write_cube)

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


def steps(got, truth):
    d = np.abs(got * 255.0 - truth * 255.0)
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
            write_cube(plain_transfer(src, shuffled), size, p("plain.cube"))
            plain = steps(ffmpeg_apply(p("plain.cube"), src, w, h), truth)
            res = {}
            for m in ["hm-mkl-hm", "auto"]:
                t0 = time.perf_counter()
                out = subprocess.run([lutkit, "match", "-y", "--json", "--size", str(size),
                                      "--method", m, p("src.png"), p("ref.png"), p("look.cube")],
                                     check=True, capture_output=True, text=True).stdout
                secs = time.perf_counter() - t0
                j = json.loads(out)
                with open(p("look.cube")) as f:
                    shaper = "LUT_1D_SIZE" in f.read(4096)
                got = (lutkit_apply(lutkit, p("look.cube"), p("src.png")) if shaper
                       else ffmpeg_apply(p("look.cube"), src, w, h))
                res[m] = (steps(got, truth), j["method"], j.get("look", {}).get("kind", ""),
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


if __name__ == "__main__":
    main()
