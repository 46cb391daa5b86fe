#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The browser edition's speed against the native CLI, measured in the same run.

For each case (preview of a 1080p screenshot, convert of an edited strip to .nutexb, match of a
1080p picture to a 1080p reference), runs the native CLI (build/bin/lutkit) and lutkit.mjs's
run() in headless Chromium (build/web) alternately, N times each (paired runs: the machine is
shared and noisy), and prints the median wall times and their ratio. The browser's time is the
whole run() as a page calls it, timed in the page: a fresh instance of the compiled module, the
files copied in and out, the command. The "round trip" column adds what only this harness pays
(WebDriver's transport of the files as base64 both ways); the machine's load average is printed,
as the ratios move with it (the native CLI's two threads gain less on a busy machine). Inputs are
made by ImageMagick.

  python3 bench/web/speed.py [RUNS]     (default 5)
"""
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "web"))
from lutkit_runner import ROOT, BrowserRunner, NativeRunner  # noqa: E402


def make_inputs(native):
    d = tempfile.mkdtemp(prefix="lutkit-webbench-")
    run = lambda *a: subprocess.run(list(a), cwd=d, check=True, capture_output=True)  # noqa: E731
    run("convert", os.path.join(ROOT, "samples", "sample_scene.png"), "-resize", "1920x1080!", "-depth", "8",
        "-strip", "PNG24:shot.png")
    run("convert", "shot.png", "-modulate", "100,70,110", "-level", "5%,90%", "-strip", "PNG24:ref.png")
    neutral = native.run(["neutral", "neutral.png"]).files["neutral.png"]
    with open(os.path.join(d, "neutral.png"), "wb") as f:
        f.write(neutral)
    run("convert", "neutral.png", "-modulate", "100,125,100", "-level", "4%,96%,0.9", "-strip", "PNG24:graded.png")
    files = {}
    for n in ("shot.png", "ref.png", "graded.png"):
        with open(os.path.join(d, n), "rb") as f:
            files[n] = f.read()
    lut = native.run(["convert", "graded.png", "lut.nutexb"], {"graded.png": files["graded.png"]})
    files["lut.nutexb"] = lut.files["lut.nutexb"]
    return files


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    native = NativeRunner()
    web = BrowserRunner()
    try:
        files = make_inputs(native)
        cases = [
            ("preview 1080p screenshot", ["preview", "shot.png", "-o", "seen.png", "--lut", "lut.nutexb"],
             ["shot.png", "lut.nutexb"], 3.0),
            ("convert strip -> .nutexb", ["convert", "graded.png", "out.nutexb"], ["graded.png"], 3.0),
            ("match 1080p + 1080p", ["match", "shot.png", "ref.png", "look.cube"], ["shot.png", "ref.png"], 4.0),
        ]
        print("load average %.1f" % os.getloadavg()[0])
        print("%-28s %10s %10s %7s %7s %12s" % ("case", "native s", "browser s", "ratio", "target", "round trip"))
        for label, args, names, target in cases:
            given = {n: files[n] for n in names}
            web.run(args, given)  # warm: the page has compiled the module once
            nt, wt, rt = [], [], []
            for _ in range(runs):
                n = native.run(args, given)
                w = web.run(args, given)
                assert n.exit_code == 0 and w.exit_code == 0, (n.stderr, w.stderr)
                nt.append(n.seconds)
                wt.append(w.browser_ms / 1000)
                rt.append(w.seconds)
            ratios = [w / n for n, w in zip(nt, wt)]
            print("%-28s %10.3f %10.3f %7.2f %7.1f %12.3f" % (label, statistics.median(nt), statistics.median(wt),
                                                              statistics.median(ratios), target,
                                                              statistics.median(rt)))
    finally:
        web.close()


if __name__ == "__main__":
    main()
