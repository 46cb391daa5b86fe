# SPDX-License-Identifier: Apache-2.0
"""The modder's whole route through the page, in headless Chromium at 1280x720 (issue 38).

The page is driven as a user drives it: files given through its file inputs, buttons clicked,
files downloaded. The oracle of every file is the native CLI (build/bin/lutkit) run by this test
on the command line the page showed, on the same input bytes: the downloads must be the same
bytes. The outside edit is ImageMagick's. Screenshots of each step go to build/page-shots/ (the
good ones are in docs/images/web/). No main-thread task over 100 ms while lutkit works (Long
Tasks API), and lutkit is ready within 2 s of opening the page.

Run: /usr/bin/python3 tests/web/test_page_modder.py  (after scripts/build-web.sh and the native build)
"""
import os
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(__file__))
from page_browser import ROOT, Page  # noqa: E402
from page_support import (outside_edit, pixels, read, run_native, screenshot_png, shot,  # noqa: E402
                          work_periods_long_tasks, write)


class ModderRoute(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="lutkit-page-modder-")
        cls.screenshot = os.path.join(cls.dir, "screenshot.png")
        screenshot_png(cls.screenshot)
        cls.page = Page()
        t0 = time.monotonic()
        cls.page.open()
        cls.page.wait(lambda: cls.page.js("return document.documentElement.dataset.engine"), 30, "lutkit ready")
        cls.wall_ready = time.monotonic() - t0
        cls.timing = cls.page.timing()

    @classmethod
    def tearDownClass(cls):
        cls.page.close()

    def path(self, name):
        return os.path.join(self.dir, name)

    def same_as_native(self, command, inputs, name, downloaded, picture=False):
        """The download against the native CLI on the page's command line: the same bytes; for a
        picture the same pixels as the native scalar kernels give (docs/web.md, "Same bytes")."""
        code, printed, written = run_native(command, inputs, {"LUTKIT_SIMD": "scalar"} if picture else None)
        self.assertEqual(code, 0, f"{command}\n{printed}")
        self.assertIn(name, written, command)
        if picture:
            self.assertEqual(pixels(written[name]), pixels(downloaded),
                             f"{name}: the page's picture differs from `LUTKIT_SIMD=scalar {command}`")
        else:
            self.assertEqual(written[name], downloaded, f"{name}: the page's download differs from `{command}`")

    def test_modders_route(self):
        p = self.page
        # lutkit ready within 2 s of opening the page (the page's own clock: navigation -> the
        # first command, lutkit --version, answered).
        self.assertEqual(p.js("return document.documentElement.dataset.engine"), "ready")
        self.assertLess(self.timing["ready"], 2000, self.timing)
        print(f"\npage: interactive at {self.timing['ui']:.0f} ms, lutkit ready at {self.timing['ready']:.0f} ms "
              f"(wall {self.wall_ready:.2f} s, {self.timing['version']})", file=sys.stderr)
        shot(p, "modder-1-start")
        working_since = p.js("return performance.now()")

        # 2. The neutral strip.
        p.click("#neutral-make")
        r = p.result_done("#m-neutral .result")
        self.assertEqual(r["command"], "lutkit neutral neutral.png")
        name, neutral = p.download("#m-neutral a.download")
        self.assertEqual(name, "neutral.png")
        self.same_as_native(r["command"], {}, "neutral.png", neutral)
        write(self.path("neutral.png"), neutral)

        # The outside edit, then the graded strip dropped: the file does not say what it is for,
        # so the page asks, once.
        outside_edit(self.path("neutral.png"), self.path("graded.png"))
        graded = read(self.path("graded.png"))
        p.drop_file('label[for="grade-file"]', self.path("graded.png"))
        p.wait(lambda: p.qs('#grade [data-question="purpose"]'), 60, "the purpose question")
        self.assertEqual(p.q("#grade").get_attribute("data-ready"), "0")
        self.assertTrue(all(b.get_attribute("disabled") is not None for b in p.qs("#m-export button[data-target]")))
        shot(p, "modder-2-purpose", "#m-grade")
        p.click('#grade input[value="raw"]')
        p.wait(lambda: p.q("#grade").get_attribute("data-ready") == "1", 10, "the grade ready")
        self.assertFalse(p.qs('#grade [data-question="purpose"]'))

        # 4. The screenshot as the game shows it.
        p.give_file("preview-file", self.screenshot)
        r = p.result_done("#m-preview .result")
        self.assertIn("is-ok", r["cls"], r["text"])
        self.assertEqual(r["command"], "lutkit preview screenshot.png -o screenshot_in_game.png --lut graded.png --lut-target raw")
        p.wait(lambda: p.js("return document.querySelector('#preview-compare img.after').dataset.ready === '1'"), 20, "after")
        name, seen = p.download("#m-preview a.download")
        self.same_as_native(r["command"], {"screenshot.png": read(self.screenshot), "graded.png": graded}, name, seen,
                            picture=True)
        # The grade changes the picture (the oracle: ImageMagick's reading of both PNGs).
        self.assertNotEqual(pixels(self.screenshot), pixels(os.path.join(p.downloads, name)))
        shot(p, "modder-3-preview", "#m-grade")

        # Strength, from the keyboard: the live proxy while it moves, then the exact picture.
        slider = p.q("#grade-strength")
        p.js("arguments[0].scrollIntoView({block: 'center'})", slider)
        p.mark("#m-preview .result")
        from selenium.webdriver.common.keys import Keys
        for _ in range(6):
            slider.send_keys(Keys.ARROW_LEFT)
        self.assertEqual(p.js("return document.querySelector('#grade-strength').value"), "0.7")
        r = p.wait(lambda: (lambda x: x if "--strength 0.7" in x["command"] else None)(p.result_done("#m-preview .result")),
                   180, "the exact preview at strength 0.7")
        self.assertIn("is-ok", r["cls"], r["text"])
        live = [run for run in p.js("return window.lutkitPage.runs") if run["label"] == "live proxy"]
        self.assertTrue(any(run["status"] == "done" and run["exitCode"] == 0 for run in live), live)
        shot(p, "modder-4-strength", "#m-grade")

        # 5. The game's file, at that strength, with its in-game error shown.
        p.mark("#export-result")
        p.click('#m-export button[data-target="nutexb"]')
        r = p.result_done("#export-result")
        self.assertIn("is-ok", r["cls"], r["text"])
        self.assertEqual(r["command"], "lutkit convert graded.png color_grading_lut.nutexb --in-target raw --strength 0.7")
        self.assertRegex(r["text"], r"In the game, against your grade \(exact composition\): max [\d.]+, mean [\d.]+")
        name, nutexb = p.download("#export-result a.download")
        self.assertEqual(name, "color_grading_lut.nutexb")
        self.same_as_native(r["command"], {"graded.png": graded}, name, nutexb)
        shot(p, "modder-5-export", "#m-export")

        # An engine's strip: the grade itself.
        p.mark("#export-result")
        p.click('#m-export button[data-target="reshade"]')
        r = p.result_done("#export-result")
        self.assertEqual(r["command"], "lutkit convert graded.png graded_strip_reshade.png --layout reshade --target raw --in-target raw --strength 0.7")
        name, strip = p.download("#export-result a.download")
        self.same_as_native(r["command"], {"graded.png": graded}, name, strip)

        # 6. The round trip: the patch into the screenshot, an outside edit, the LUT read back.
        p.give_file("embed-file", self.screenshot)
        r = p.result_done("#embed-result")
        self.assertEqual(r["command"], "lutkit embed screenshot.png screenshot_patched.png")
        name, patched = p.download("#embed-result a.download")
        self.same_as_native(r["command"], {"screenshot.png": read(self.screenshot)}, name, patched, picture=True)
        write(self.path("patched.png"), patched)
        outside_edit(self.path("patched.png"), self.path("patched_graded.png"))
        p.give_file("extract-file", self.path("patched_graded.png"))
        r = p.result_done("#extract-result")
        self.assertNotIn("is-error", r["cls"], r["text"])
        self.assertEqual(r["command"], "lutkit extract patched_graded.png color_grading_lut.nutexb")
        self.assertRegex(r["text"], r"Expected in-game error, over all inputs: max [\d.]+")
        name, extracted = p.download("#extract-result a.download")
        self.same_as_native(r["command"], {"patched_graded.png": read(self.path("patched_graded.png"))}, name, extracted)
        # The extracted LUT is the grade now: the game's LUT, said by its format, nothing asked.
        p.wait(lambda: p.qs('#grade .purpose-line[data-purpose="smash"]'), 60, "the extracted LUT as the grade")
        self.assertFalse(p.qs('#grade [data-question="purpose"]'))
        shot(p, "modder-6-roundtrip", "#m-roundtrip")

        # 1. The stage's starting LUT: the game's default one; the preview runs with it.
        p.mark("#m-preview .result")
        p.click('input[name="stage-lut"][value="builtin"]')
        r = p.wait(lambda: (lambda x: x if "builtin:smash-default" in x["command"] else None)(p.result_done("#m-preview .result")),
                   180, "the preview with the stage's LUT")
        self.assertIn("--original-lut builtin:smash-default", r["command"])
        name, seen = p.download("#m-preview a.download")
        self.same_as_native(r["command"], {"screenshot.png": read(self.screenshot),
                                           "color_grading_lut.nutexb": extracted}, name, seen, picture=True)
        shot(p, "modder-7-stage", "#m-stage")

        # No main-thread task over 100 ms while lutkit worked.
        slow = work_periods_long_tasks(p, working_since)
        self.assertEqual(slow, [], f"main-thread tasks over 100 ms while working: {slow}")
        print(f"long tasks while working (all): {p.long_tasks()}", file=sys.stderr)

        # A broken file: lutkit's own line, shown, and nothing else changes: the grade is the one
        # the slot had (as the editor keeps its document), the preview stays.
        runs_before = len(p.js("return window.lutkitPage.runs"))
        bad = os.path.join(ROOT, "tests", "data", "nutexb", "bad_width_huge.nutexb")
        p.give_file("grade-file", bad)
        r = p.result_done("#grade .result")
        self.assertIn("is-error", r["cls"])
        self.assertIn("bad_width_huge.nutexb: nutexb width: found 2147483648", r["text"])
        self.assertIn("exit 1", r["status"])
        self.assertEqual(p.q("#grade").get_attribute("data-ready"), "1")
        self.assertIn("color_grading_lut.nutexb", p.q("#grade .facts-line").text)
        self.assertIn("still color_grading_lut.nutexb", p.q('label[for="grade-file"]').text)
        self.assertEqual([run["args"] for run in p.js("return window.lutkitPage.runs")[runs_before:]],
                         [["info", "--json", "bad_width_huge.nutexb"]])
        self.assertEqual(p.js("return document.querySelector('#preview-compare img.after').dataset.ready"), "1")
        shot(p, "modder-8-error", "#m-grade")
        self.assertEqual(p.console_errors(), [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
