# SPDX-License-Identifier: Apache-2.0
"""The colourist's tools through the page, in headless Chromium at 1280x720, and what goes wrong
shown, never silent (issue 38): convert with the error report, check with its report picture,
apply to a picture, match a look; a format only OpenColorIO reads, a tiny PNG that claims a huge
picture, a worker that dies (the page's self-test of a failed allocation), and every control
reached from the keyboard.

The oracle of every file is the native CLI (build/bin/lutkit) on the command line the page showed.
Run: /usr/bin/python3 tests/web/test_page_colourist.py
"""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(__file__))
from page_browser import ROOT, Page  # noqa: E402
from page_support import (magick, pixels, png_claiming, read, run_native, screenshot_png, shot,  # noqa: E402
                          work_periods_long_tasks)

SAMPLE_GRADE = os.path.join(ROOT, "samples", "sample_grade.cube")


class Colourist(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="lutkit-page-colourist-")
        cls.picture = os.path.join(cls.dir, "plate.png")
        screenshot_png(cls.picture, 960, 540)
        cls.reference = os.path.join(cls.dir, "reference.png")
        magick(os.path.join(ROOT, "samples", "sample_scene.png"), "-modulate", "100,60,80", "-gamma", "1.2",
               cls.reference)
        cls.page = Page()
        cls.page.open("#colourist")
        cls.page.wait(lambda: cls.page.js("return document.documentElement.dataset.engine"), 30, "lutkit ready")
        cls.working_since = cls.page.js("return performance.now()")

    @classmethod
    def tearDownClass(cls):
        cls.page.close()

    def native(self, command, inputs, name, downloaded, picture=False):
        code, printed, written = run_native(command, inputs, {"LUTKIT_SIMD": "scalar"} if picture else None)
        self.assertIn(name, written, f"{command}\n{printed}")
        if picture:
            self.assertEqual(pixels(written[name]), pixels(downloaded), f"{name} vs LUTKIT_SIMD=scalar {command}")
        else:
            self.assertEqual(written[name], downloaded, f"{name} vs {command}")
        return code

    def drop_lut(self, path, answer="raw", asked=True):
        """Drops a LUT in step 1; answers what it is for if the page asks (asked: it must)."""
        p = self.page
        p.mark("#clut .result")
        p.give_file("clut-file", path)
        name = os.path.basename(path)
        p.wait(lambda: p.qs('#clut [data-question="purpose"]') or (
            p.q("#clut").get_attribute("data-ready") == "1" and name in p.q("#clut .facts-line").text), 60, "the LUT read")
        if p.qs('#clut [data-question="purpose"]'):
            p.click(f'#clut input[value="{answer}"]')
        else:
            self.assertFalse(asked, "the page did not ask what the LUT is for")
        p.wait(lambda: p.q("#clut").get_attribute("data-ready") == "1", 10, "the LUT ready")

    def test_1_convert_check_apply_match(self):
        p = self.page
        grade = read(SAMPLE_GRADE)
        self.drop_lut(SAMPLE_GRADE)
        shot(p, "colourist-1-lut", "#c-lut")
        # Asked once: the same file again is not asked about, the answer is said to be the earlier one.
        p.mark("#clut .result")
        p.give_file("clut-file", SAMPLE_GRADE)
        p.wait(lambda: "your earlier answer" in p.q("#clut .purpose-line").text, 60, "the answer recalled")
        self.assertFalse(p.qs('#clut [data-question="purpose"]'))

        # Convert into the game's file: the error report, the same bytes as the native CLI.
        p.js("const s = document.querySelector('#convert-format'); s.value = 'nutexb'; s.dispatchEvent(new Event('change'))")
        p.mark("#convert-result")
        p.click("#convert-run")
        r = p.result_done("#convert-result")
        self.assertIn("is-ok", r["cls"], r["text"])
        self.assertEqual(r["command"], "lutkit convert sample_grade.cube sample_grade.nutexb --in-target raw")
        self.assertRegex(r["text"], r"In the game, against your grade \(exact composition\): max [\d.]+")
        self.assertRegex(r["text"], r"Storage: max [\d.e-]+ \([\d.e-]+ 8-bit steps\)")
        name, data = p.download("#convert-result a.download")
        self.native(r["command"], {"sample_grade.cube": grade}, name, data)

        # Into a ReShade strip, 16-bit, 33 points: the resampling error reported.
        p.js("""const s = document.querySelector('#convert-format'); s.value = 'strip'; s.dispatchEvent(new Event('change'));
                document.querySelector('#convert-layout').value = 'reshade';
                document.querySelector('#convert-depth').value = '16';""")
        p.mark("#convert-result")
        p.click("#convert-run")
        r = p.result_done("#convert-result")
        self.assertEqual(r["command"], "lutkit convert sample_grade.cube sample_grade.png --in-target raw --layout reshade --bit-depth 16")
        self.assertRegex(r["text"], r"Resampling: ")
        name, data = p.download("#convert-result a.download")
        self.native(r["command"], {"sample_grade.cube": grade}, name, data, picture=True)
        shot(p, "colourist-2-convert", "#c-convert")

        # Check, with its report picture shown.
        p.mark("#check-result")
        p.click("#check-run")
        r = p.result_done("#check-result")
        self.assertEqual(r["command"], "lutkit check sample_grade.cube --report sample_grade_check.png --target raw")
        self.assertIn("it passes, with warnings", r["status"])
        p.wait(lambda: p.js("const i = document.querySelector('#check-result img.report'); return i && i.complete && i.naturalWidth > 0"),
               20, "the report picture drawn")
        name, data = p.download("#check-result a.download")
        self.native(r["command"], {"sample_grade.cube": grade}, name, data, picture=True)
        shot(p, "colourist-3-check", "#c-check")

        # Apply to a picture: before | after, the exact picture.
        p.give_file("apply-file", self.picture)
        r = p.result_done("#c-apply .live > .result")
        self.assertIn("is-ok", r["cls"], r["text"])
        self.assertEqual(r["command"], "lutkit apply --lut sample_grade.cube --lut-target raw plate.png -o plate_graded.png")
        name, data = p.download("#c-apply a.download")
        self.native(r["command"], {"sample_grade.cube": grade, "plate.png": read(self.picture)}, name, data, picture=True)
        shot(p, "colourist-4-apply", "#c-apply")

        # Match a look to a reference picture, at a strength.
        p.give_file("match-source", os.path.join(ROOT, "samples", "sample_scene.png"))
        p.give_file("match-refs", self.reference)
        strength = p.q("#match-strength")
        from selenium.webdriver.common.keys import Keys
        for _ in range(4):
            strength.send_keys(Keys.ARROW_LEFT)
        p.mark("#match-result")
        p.click("#match-run")
        r = p.result_done("#match-result", timeout=240)
        self.assertNotIn("is-error", r["cls"], r["text"])
        self.assertEqual(r["command"], "lutkit match sample_scene.png reference.png sample_scene_look.cube "
                                       "--report-image sample_scene_match.png --strength 0.8")
        self.assertRegex(r["text"], r"Distance to the reference before: sliced Wasserstein [\d.]+")
        self.assertRegex(r["text"], r"Distance to the reference after: sliced Wasserstein [\d.]+")
        name, data = p.download("#match-result a.download[data-file='sample_scene_look.cube']")
        self.native(r["command"], {"sample_scene.png": read(os.path.join(ROOT, "samples", "sample_scene.png")),
                                   "reference.png": read(self.reference)}, name, data)
        shot(p, "colourist-5-match", "#c-match")

        slow = work_periods_long_tasks(p, self.working_since)
        self.assertEqual(slow, [], f"main-thread tasks over 100 ms while working: {slow}")

    def test_2_what_goes_wrong_is_shown(self):
        p = self.page
        self.drop_lut(SAMPLE_GRADE, asked=False)  # answered once, in test_1 (or now, alone)
        # A format only OpenColorIO reads: lutkit's one line naming the edition.
        p.mark("#clut .result")
        p.give_file("clut-file", os.path.join(ROOT, "tests", "data", "ocio", "affine.3dl"))
        r = p.result_done("#clut .result")
        self.assertIn("is-error", r["cls"])
        self.assertIn("exit 1", r["status"])
        self.assertRegex(r["text"], r"affine\.3dl: .*OpenColorIO.*lutkit for the browser")
        # The LUT the slot had stays (test_1's sample grade), as the editor keeps its document.
        self.assertEqual(p.q("#clut").get_attribute("data-ready"), "1")
        self.assertIn("sample_grade.cube", p.q("#clut .facts-line").text)
        self.assertIsNone(p.q("#convert-run").get_attribute("disabled"))

        # A 300-byte PNG claiming 100000 x 100000 pixels: refused before anything is allocated,
        # the page lives on.
        huge = os.path.join(self.dir, "huge.png")
        png_claiming(huge, 100000, 100000)
        p.mark("#c-apply .live > .result")
        p.give_file("apply-file", huge)
        r = p.result_done("#c-apply .live > .result")
        self.assertIn("is-error", r["cls"], r["text"])
        code, printed, _ = run_native(r["command"], {"sample_grade.cube": read(SAMPLE_GRADE), "huge.png": read(huge)})
        self.assertEqual(code, 1)
        native_line = [l for l in printed.splitlines() if "huge.png" in l][0]
        self.assertIn(native_line, r["text"])
        self.assertFalse(p.js("return document.querySelector('#apply-compare img.before').dataset.ready === '1'"),
                         "the picture before is still shown")
        shot(p, "colourist-6-hostile", "#c-apply .strength")

        # A worker that dies (the page's self-test: an allocation failing outside lutkit's own
        # checks): the card says so, lutkit is restarted, the next command runs.
        p.js("window.lutkitPage.runner.failNextRun = 'uncaught'")
        p.mark("#check-result")
        p.click("#check-run")
        r = p.result_done("#check-result")
        self.assertIn("is-error", r["cls"])
        self.assertIn("lutkit stopped unexpectedly", r["status"])
        self.assertIn("could not allocate memory", r["status"])
        self.assertIn("restarted", r["status"])
        shot(p, "colourist-7-crash", "#c-check")
        p.js("window.lutkitPage.runner.failNextRun = 'run'")
        p.mark("#check-result")
        p.click("#check-run")
        r = p.result_done("#check-result")
        self.assertIn("lutkit stopped unexpectedly", r["status"])
        p.mark("#check-result")
        p.click("#check-run")
        r = p.result_done("#check-result")
        self.assertNotIn("is-error", r["cls"], r["text"])
        self.assertEqual(p.js("return document.getElementById('engine').dataset.state"), "ready")
        self.assertEqual(p.console_errors(), [])

    def test_2b_names_a_shell_reads_back(self):
        """A file name with spaces, quotes or a leading '-' is quoted in the command line shown,
        and that line, run by a shell's rules, is the same command (the native CLI's bytes)."""
        import shutil
        p = self.page
        for name in ("my grade (v2) 'final'.cube", "-look.cube"):
            path = os.path.join(self.dir, name)
            shutil.copyfile(SAMPLE_GRADE, path)
            self.drop_lut(path, asked=False)
            p.js("const s = document.querySelector('#convert-format'); s.value = 'nutexb'; s.dispatchEvent(new Event('change'))")
            p.mark("#convert-result")
            p.click("#convert-run")
            r = p.result_done("#convert-result")
            self.assertIn("is-ok", r["cls"], r["text"])
            out, data = p.download("#convert-result a.download")
            self.native(r["command"], {name: read(SAMPLE_GRADE)}, out, data)
            if name.startswith("-"):
                self.assertIn(" ./-look.cube ", r["command"])
            else:
                self.assertIn("'my grade (v2) '\\''final'\\''.cube'", r["command"])

    def test_3_every_control_from_the_keyboard(self):
        """Tab visits every control of both tabs (the tab bar's arrow keys switch tabs)."""
        p = self.page
        from selenium.webdriver.common.keys import Keys
        from selenium.webdriver.common.action_chains import ActionChains
        seen = set()
        for tab in ("modder", "colourist"):
            p.js(f"document.getElementById('tab-{tab}').click(); document.getElementById('tab-{tab}').focus()")
            # One stop per radio group and per tab list: arrow keys move inside them (ARIA's
            # pattern, and what browsers do with radio buttons).
            visible = set(p.js("""
              const out = [];
              const groups = new Map();
              for (const e of document.querySelectorAll('button, input, select, a[href], summary, textarea')) {
                // A file input is drawn as its label (the drop place).
                const shown = e.matches('input[type=file]') ? document.querySelector(`label[for="${e.id}"]`) : e;
                if (!shown || !shown.checkVisibility({ checkVisibilityCSS: true }) || e.disabled)
                  continue;
                const group = e.type === 'radio' ? `radio:${e.name}` : e.getAttribute('role') === 'tab' ? 'tabs' : null;
                if (group && !groups.has(group))
                  groups.set(group, String(Math.random()));
                e.dataset.kb = group ? groups.get(group) : (e.dataset.kb || String(Math.random()));
                if (!out.includes(e.dataset.kb))
                  out.push(e.dataset.kb);
              }
              return out;"""))
            visited = set()
            trail = []
            for _ in range(600):
                ActionChains(p.driver).send_keys(Keys.TAB).perform()
                kb, what = p.js("const e = document.activeElement; return [e && e.dataset.kb, e && e.outerHTML.slice(0, 60)]")
                trail.append(what)
                if kb:
                    visited.add(kb)
                if visible <= visited:
                    break
            missing = p.js("""return Array.from(document.querySelectorAll('[data-kb]'))
                .filter(e => arguments[0].includes(e.dataset.kb))
                .map(e => { const c = e.closest('[id]'); return `${e.outerHTML.slice(0, 100)} in #${c && c.id}`; })""",
                           sorted(visible - visited))
            self.assertEqual(missing, [], f"{tab}: controls Tab does not reach; Tab went through {len(trail)}: {trail[-40:]}")
            seen |= visited
        self.assertGreater(len(seen), 30)
        # The tabs from the keyboard: arrow keys move between them.
        p.js("document.getElementById('tab-modder').focus()")
        ActionChains(p.driver).send_keys(Keys.ARROW_RIGHT).perform()
        self.assertEqual(p.js("return document.activeElement.id"), "tab-colourist")
        self.assertFalse(p.js("return document.getElementById('colourist').hidden"))


if __name__ == "__main__":
    unittest.main(verbosity=2)
