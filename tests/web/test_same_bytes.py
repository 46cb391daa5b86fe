# SPDX-License-Identifier: Apache-2.0
"""The browser edition against the native CLI (issue: "same bytes as native").

Every case runs one command line twice on the same input bytes: build/bin/lutkit in a folder, and
lutkit.mjs's run() in headless Chromium. The exit code, every file written (byte for byte) and
what was printed (timings taken out) must be the same. The inputs are made at test time by other
programs (ImageMagick, oiiotool) and by the native CLI; the oracle is the native CLI itself.
What the browser edition cannot do (OpenColorIO's formats, OpenImageIO's images, colour
management) must be refused with the one line that names the edition, exit 1.

Run: python3 tests/web/test_same_bytes.py  (after scripts/build-web.sh and the native build;
LUTKIT_WEB_RUNNER=node uses Node instead of Chromium, for quick checks).
"""
import os
import re
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(__file__))
from lutkit_runner import ROOT, BrowserRunner, NativeRunner  # noqa: E402

DATA = os.path.join(ROOT, "tests", "data")
SAMPLES = os.path.join(ROOT, "samples")


def read(path):
    with open(path, "rb") as f:
        return f.read()


def tool(*args, cwd):
    subprocess.run(list(args), cwd=cwd, check=True, capture_output=True)


def timing_rules():
    """tests/common/timing-rules.sed, the list tests/windows/run.sh reads too: (regex, replacement)."""
    rules = []
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common",
                           "timing-rules.sed"), encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            command, regex, replacement, flags = line.split("#")
            assert command == "s" and flags == "g", line
            rules.append((re.compile(regex, re.MULTILINE), replacement))
    return rules


TIMING_RULES = timing_rules()


def normalise(text):
    """What may differ between two runs of the same command: times."""
    for regex, replacement in TIMING_RULES:
        text = regex.sub(replacement, text)
    return text


class Inputs:
    """The test's input files, made once by outside programs."""

    def __init__(self, native):
        self.dir = tempfile.mkdtemp(prefix="lutkit-web-inputs-")
        d = self.dir
        b = {}
        b["look.cube"] = read(os.path.join(SAMPLES, "sample_grade.cube"))
        b["shaper.cube"] = read(os.path.join(DATA, "cube", "resolve_shaper_3d.cube"))
        # A screenshot-like picture, 1280x720, 8-bit sRGB: the sample scene resized by ImageMagick.
        tool("convert", os.path.join(SAMPLES, "sample_scene.png"), "-resize", "1280x720!", "-depth", "8",
             "-strip", "PNG24:shot.png", cwd=d)
        tool("convert", "shot.png", "-quality", "92", "shot.jpg", cwd=d)
        tool("convert", "shot.png", "-interlace", "JPEG", "-quality", "85", "shot_progressive.jpg", cwd=d)
        # The modder's strip, edited by another program (ImageMagick: curves and saturation).
        r = native.run(["neutral", "neutral.png"])
        b["neutral.png"] = r.files["neutral.png"]
        with open(os.path.join(d, "neutral.png"), "wb") as f:
            f.write(b["neutral.png"])
        tool("convert", "neutral.png", "-modulate", "100,125,100", "-level", "4%,96%,0.9", "-strip",
             "PNG24:graded.png", cwd=d)
        for n in ("shot.png", "shot.jpg", "shot_progressive.jpg", "graded.png"):
            b[n] = read(os.path.join(d, n))
        self.bytes = b

    def pick(self, *names):
        return {n: self.bytes[n] for n in names}


class SameBytes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.native = NativeRunner()
        if os.environ.get("LUTKIT_WEB_RUNNER") == "node":
            from node_runner import NodeRunner
            cls.web = NodeRunner()
        else:
            cls.web = BrowserRunner()
        cls.inputs = Inputs(cls.native)

    @classmethod
    def tearDownClass(cls):
        cls.web.close()

    def same(self, args, files=None, stdin=b"", expect_exit=None):
        """Runs both; asserts equal exit codes, outputs and messages; returns (native, web)."""
        files = files or {}
        n = self.native.run(args, files, stdin)
        w = self.web.run(args, files, stdin)
        label = "lutkit " + " ".join(args)
        if expect_exit is not None:
            self.assertEqual(n.exit_code, expect_exit, label + "\n" + n.stderr)
        self.assertEqual(w.exit_code, n.exit_code, label + "\nnative: " + n.stderr + "\nweb: " + w.stderr)
        self.assertEqual(sorted(w.files), sorted(n.files), label)
        for name in n.files:
            self.assertTrue(w.files[name] == n.files[name],
                            "%s: %s differs (%d vs %d bytes)" % (label, name, len(w.files[name]), len(n.files[name])))
        self.assertEqual(normalise(w.stderr), normalise(n.stderr), label)
        wout = normalise(w.stdout.decode("utf-8", "replace"))
        nout = normalise(n.stdout.decode("utf-8", "replace"))
        self.assertEqual(wout, nout, label)
        return n, w

    # The README's modder quick start, as written.
    def test_modder_quick_start(self):
        i = self.inputs
        self.same(["neutral", "neutral.png"], expect_exit=0)
        n, _ = self.same(["convert", "graded.png", "color_grading_lut.nutexb"], i.pick("graded.png"),
                         expect_exit=0)
        lut = n.files["color_grading_lut.nutexb"]
        for shot in ("shot.png", "shot.jpg", "shot_progressive.jpg"):
            self.same(["preview", shot, "-o", "in_game.png", "--lut", "color_grading_lut.nutexb"],
                      dict(i.pick(shot), **{"color_grading_lut.nutexb": lut}), expect_exit=0)

    # The Photoshop round trip on a screenshot: embed, an outside edit, extract, convert, preview.
    def test_round_trip(self):
        i = self.inputs
        n, _ = self.same(["embed", "shot.png", "patched.png"], i.pick("shot.png"), expect_exit=0)
        with open(os.path.join(i.dir, "patched.png"), "wb") as f:
            f.write(n.files["patched.png"])
        tool("convert", "patched.png", "-modulate", "100,80,100", "-gamma", "1.1", "-strip", "PNG24:edited.png",
             cwd=i.dir)
        edited = read(os.path.join(i.dir, "edited.png"))
        n, _ = self.same(["extract", "edited.png", "extracted.nutexb"], {"edited.png": edited}, expect_exit=0)
        lut = n.files["extracted.nutexb"]
        self.same(["extract", "edited.png", "extracted.cube"], {"edited.png": edited}, expect_exit=0)
        self.same(["convert", "extracted.nutexb", "strip.png", "--layout", "reshade"],
                  {"extracted.nutexb": lut}, expect_exit=0)
        self.same(["preview", "shot.png", "-o", "seen.png", "--lut", "extracted.nutexb"],
                  dict(i.pick("shot.png"), **{"extracted.nutexb": lut}), expect_exit=0)

    # A convert into every format the browser edition writes.
    def test_convert_into_every_native_format(self):
        i = self.inputs
        outs = [
            ["out.cube"], ["out.cube", "--format", "resolve_cube"], ["out.cube", "--format", "iridas_cube"],
            ["out.nutexb"], ["out.spi3d"], ["out.png"], ["out16.png", "--bit-depth", "16"],
            ["unity.png", "--layout", "unity"], ["unity32.png", "--layout", "unity-32"],
            ["reshade.png", "--layout", "reshade"], ["smush.png", "--layout", "smush"],
            ["hald.png", "--level", "8"], ["out65.cube", "--size", "65"], ["out.nutexb", "--target", "raw"],
        ]
        for src in ("look.cube", "shaper.cube", "graded.png"):
            for out in outs:
                # (33^3 -> 65^3 printed 3.58e-07 natively, 3.88e-07 here: the error bound's heap
                # took equal bounds in libstdc++'s order or libc++'s; now a total order)
                self.same(["convert", src] + out, i.pick(src))
        # What only OpenColorIO writes: the native CLI writes it, this edition refuses it in one
        # line naming the edition, and writes nothing.
        n = self.native.run(["convert", "look.cube", "out.3dl"], i.pick("look.cube"))
        self.assertEqual(n.exit_code, 0, n.stderr)
        w = self.web.run(["convert", "look.cube", "out.3dl"], i.pick("look.cube"))
        self.assertEqual(w.exit_code, 1, w.stderr)
        self.assertEqual(w.files, {})
        self.assertEqual(len(w.stderr.strip().splitlines()), 1, w.stderr)
        self.assertIn("out.3dl", w.stderr)
        self.assertIn("OpenColorIO", w.stderr)
        self.assertIn("for the browser", w.stderr)

    def test_every_command(self):
        i = self.inputs
        look = i.pick("look.cube")
        self.same(["info", "look.cube", "--json"], look, expect_exit=0)
        self.same(["validate", "--strict", "look.cube"], look)
        self.same(["check", "look.cube", "--report", "report.png"], look)
        self.same(["chart", "all", "chart.png"], expect_exit=0)
        self.same(["plot", "look.cube", "plot.png"], look, expect_exit=0)
        self.same(["invert", "look.cube", "inv.cube"], look)
        self.same(["resize", "look.cube", "r.cube", "--size", "17"], look, expect_exit=0)
        self.same(["smooth", "look.cube", "s.cube"], look, expect_exit=0)
        self.same(["compose", "look.cube", "look.cube", "c.cube"], look, expect_exit=0)
        self.same(["mix", "look.cube", "builtin:neutral", "m.cube", "--strength", "0.5"], look, expect_exit=0)
        self.same(["diff", "look.cube", "builtin:neutral", "--json"], look, expect_exit=0)
        self.same(["apply", "--lut", "look.cube", "shot.png", "-o", "graded_shot.png"],
                  dict(look, **i.pick("shot.png")), expect_exit=0)
        self.same(["apply", "--lut", "look.cube", "shot.jpg", "-o", "graded_shot.png"],
                  dict(look, **i.pick("shot.jpg")), expect_exit=0)
        self.same(["atlas", "build", "look.cube", "builtin:neutral", "-o", "atlas.png"], look, expect_exit=0)
        n, _ = self.same(["apply", "--lut", "look.cube", "shot.png", "-o", "graded_ref.png"],
                         dict(look, **i.pick("shot.png")), expect_exit=0)
        self.same(["match", "shot.jpg", "graded_ref.png", "matched.cube"],
                  dict(i.pick("shot.jpg"), **{"graded_ref.png": n.files["graded_ref.png"]}), expect_exit=0)
        self.same(["fit", "shot.png", "graded_ref.png", "fitted.cube"],
                  dict(i.pick("shot.png"), **{"graded_ref.png": n.files["graded_ref.png"]}))

    def test_standard_streams(self):
        i = self.inputs
        self.same(["convert", "-", "-", "--in-format", "cube", "--format", "nutexb"],
                  stdin=i.bytes["look.cube"], expect_exit=0)
        self.same(["info", "-"], stdin=i.bytes["graded.png"])

    def test_hostile_inputs(self):
        for name in sorted(os.listdir(os.path.join(DATA, "cube", "malformed"))):
            self.same(["info", name], {name: read(os.path.join(DATA, "cube", "malformed", name))})
        for name in sorted(os.listdir(os.path.join(DATA, "nutexb"))):
            if name.endswith(".nutexb"):
                self.same(["convert", name, "out.cube"], {name: read(os.path.join(DATA, "nutexb", name))})
        shot = self.inputs.bytes["shot.jpg"]
        self.same(["info", "shot.jpg"], {"shot.jpg": shot[: len(shot) // 2]})
        self.same(["apply", "--lut", "builtin:neutral", "cut.jpg", "-o", "o.png"],
                  {"cut.jpg": shot[: len(shot) // 2] + b"\xff\xd9"})
        self.same(["preview", "x.png", "-o", "o.png"], {"x.png": b"\x89PNG\r\n\x1a\n" + b"\0" * 40})
        self.same(["convert", "look.cube", "out.nutexb", "--size", "7"], self.inputs.pick("look.cube"))
        self.same(["frobnicate"], expect_exit=2)
        self.same(["convert"], expect_exit=2)


if __name__ == "__main__":
    unittest.main(verbosity=2)
