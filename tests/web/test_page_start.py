# SPDX-License-Identifier: Apache-2.0
"""The page's start (issue 38): lutkit usable within 2 s of opening the page from 127.0.0.1, the
server's types for the module, the worker and the WebAssembly, nothing asked of any other host,
and a page opened as a file that says how to open it instead of failing silently.

Run: /usr/bin/python3 tests/web/test_page_start.py
"""
import os
import sys
import time
import unittest
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from page_browser import SITE, Page  # noqa: E402


class Start(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.page = Page()

    @classmethod
    def tearDownClass(cls):
        cls.page.close()

    def test_lutkit_ready_within_2_s(self):
        p = self.page
        p.console_errors()  # what another test left in the log
        for attempt in range(2):
            t0 = time.monotonic()
            p.open()
            p.wait(lambda: p.js("return document.documentElement.dataset.engine"), 30, "lutkit ready")
            wall = time.monotonic() - t0
            timing = p.timing()
            print(f"\nopen {attempt + 1}: controls at {timing['ui']:.0f} ms, lutkit ready at {timing['ready']:.0f} ms "
                  f"(the page's clock from navigation; {wall:.2f} s as the test saw it)", file=sys.stderr)
            self.assertEqual(p.js("return document.documentElement.dataset.engine"), "ready")
            self.assertEqual(p.q("#engine").text, f"{timing['version']} ready")
            self.assertLess(timing["ready"], 2000, timing)
            # Everything the page loaded came from its own server.
            urls = p.js("return performance.getEntriesByType('resource').map(e => e.name)")
            self.assertTrue(urls)
            for url in urls:
                self.assertTrue(url.startswith(p.url) or url.startswith(("blob:", "data:")), url)
        self.assertEqual(p.console_errors(), [])

    def test_types_the_browser_needs(self):
        expect = {"index.html": "text/html", "lutkit.mjs": "text/javascript", "worker.js": "text/javascript",
                  "js/main.js": "text/javascript", "lutkit.wasm": "application/wasm", "style.css": "text/css"}
        for name, kind in expect.items():
            with urllib.request.urlopen(self.page.url + name) as r:
                self.assertEqual(r.headers.get_content_type(), kind, name)
                self.assertEqual(r.headers["Cache-Control"], "no-cache", name)

    def test_a_page_opened_as_a_file_says_how_to_open_it(self):
        p = self.page
        p.driver.get("file://" + os.path.join(os.path.abspath(SITE), "index.html"))
        notice = p.wait(lambda: (lambda n: n if n.is_displayed() else None)(p.q("#needs-server")), 10, "the notice")
        self.assertIn("python3 -m http.server", notice.text)
        self.assertFalse(p.q("#main").is_displayed())


if __name__ == "__main__":
    unittest.main(verbosity=2)
