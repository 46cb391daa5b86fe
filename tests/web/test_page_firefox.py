# SPDX-License-Identifier: Apache-2.0
"""The modder's route in headless Firefox (issue 38: the page works in Chromium and Firefox), and
the page opened from its folder (file://), which Firefox allows and Chromium does not.

Debian has no geckodriver, so this test speaks WebDriver BiDi, which Firefox serves itself
(--remote-debugging-port), through python3-trio-websocket (selenium's own dependency). It drops
the files on the page's drop places (drop events carrying them), answers the question, waits for
the preview (and the live view's picture, made with the browser's OffscreenCanvas in the worker)
and the game's file, and compares the file the download link holds with the native CLI's on the
command line the page showed. Skipped when firefox-esr is not installed (it is not one of
scripts/install-deps.sh's packages: apt install firefox-esr).

Run: /usr/bin/python3 tests/web/test_page_firefox.py
"""
import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import unittest

sys.path.insert(0, os.path.dirname(__file__))
from page_browser import SITE, serve_web  # noqa: E402
from page_support import outside_edit, read, run_native, screenshot_png  # noqa: E402

FIREFOX = shutil.which("firefox-esr") or shutil.which("firefox")

DROP = """(name, b64, css) => {
  const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
  const dt = new DataTransfer();
  dt.items.add(new File([bytes], name));
  const target = document.querySelector(css);
  for (const type of ['dragenter', 'dragover', 'drop'])
    target.dispatchEvent(new DragEvent(type, {bubbles: true, cancelable: true, dataTransfer: dt}));
  return true;
}"""

RESULT = """(css) => {
  const n = document.querySelector(css);
  const s = n && n.querySelector('.status');
  if (!s || n.classList.contains('is-running')) return '';
  return JSON.stringify({cls: n.className, status: s.textContent,
                         command: (n.querySelector('details.command code') || {}).textContent || ''});
}"""

LINK_BYTES = """async (css) => {
  const a = document.querySelector(css);
  const bytes = new Uint8Array(await (await fetch(a.href)).arrayBuffer());
  let s = '';
  for (const b of bytes) s += String.fromCharCode(b);
  return JSON.stringify({name: a.getAttribute('download'), b64: btoa(s)});
}"""


@unittest.skipUnless(FIREFOX, "firefox-esr is not installed")
class FirefoxRoute(unittest.TestCase):
    def test_modders_route_in_firefox(self):
        import trio
        from trio_websocket import HandshakeError, open_websocket_url
        work = tempfile.mkdtemp(prefix="lutkit-page-firefox-")
        profile = tempfile.mkdtemp(prefix="lutkit-page-firefox-profile-")
        server = serve_web.make_server(SITE, port=0, quiet=True)
        threading.Thread(target=server.serve_forever, daemon=True).start()
        url = f"http://127.0.0.1:{server.server_address[1]}/"
        port = 9300 + os.getpid() % 500
        browser = subprocess.Popen([FIREFOX, "--headless", "--no-remote", "--profile", profile,
                                    "--remote-debugging-port", str(port), "about:blank"],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        shot = os.path.join(work, "screenshot.png")
        screenshot_png(shot, 960, 540)
        neutral_path = os.path.join(work, "neutral.png")
        seen = {}

        async def session():
            end = time.monotonic() + 30
            while True:
                try:
                    async with open_websocket_url(f"ws://127.0.0.1:{port}/session") as ws:
                        await drive(ws)
                        return
                except (OSError, HandshakeError):
                    if time.monotonic() > end:
                        raise
                    await trio.sleep(0.2)

        async def drive(ws):
            counter = [0]

            async def call(method, params):
                counter[0] += 1
                await ws.send_message(json.dumps({"id": counter[0], "method": method, "params": params}))
                while True:
                    m = json.loads(await ws.get_message())
                    if m.get("id") == counter[0]:
                        if "error" in m:
                            raise RuntimeError(m)
                        return m["result"]

            await call("session.new", {"capabilities": {}})
            context = (await call("browsingContext.getTree", {}))["contexts"][0]["context"]

            async def js(function, *args):
                r = await call("script.callFunction", {
                    "functionDeclaration": function, "awaitPromise": True, "target": {"context": context},
                    "arguments": [{"type": "string", "value": str(a)} for a in args]})
                if r.get("type") == "exception":
                    raise RuntimeError(r["exceptionDetails"]["text"])
                return r["result"].get("value")

            async def wait(function, *args, timeout=120):
                end = time.monotonic() + timeout
                while time.monotonic() < end:
                    value = await js(function, *args)
                    if value:
                        return value
                    await trio.sleep(0.2)
                raise TimeoutError(function)

            async def drop(path, css):
                await js(DROP, os.path.basename(path), base64.b64encode(read(path)).decode(), css)

            await call("browsingContext.navigate", {"context": context, "url": url, "wait": "complete"})
            await wait("() => document.documentElement.dataset.engine || ''", timeout=30)
            seen["engine"] = await js("() => document.documentElement.dataset.engine")
            seen["ready_ms"] = await js("() => window.lutkitPage.readyAt")
            await js("() => { document.getElementById('neutral-make').click(); return 1; }")
            await wait(RESULT, "#m-neutral .result")
            seen["neutral"] = json.loads(await js(LINK_BYTES, "#m-neutral a.download"))
            with open(neutral_path, "wb") as f:
                f.write(base64.b64decode(seen["neutral"]["b64"]))
            outside_edit(neutral_path, os.path.join(work, "graded.png"))
            await drop(os.path.join(work, "graded.png"), 'label[for="grade-file"]')
            await wait("() => !!document.querySelector('#grade input[value=raw]')")
            await js("() => { document.querySelector('#grade input[value=raw]').click(); return 1; }")
            await drop(shot, 'label[for="preview-file"]')
            seen["preview"] = json.loads(await wait(RESULT, "#m-preview .live > .result"))
            # The live view: the browser's resize of the picture in the worker.
            seen["live"] = json.loads(await js("""async () => {
              const r = await window.lutkitPage.runner.lane('pictures').proxy(
                new Uint8Array(await (await fetch(document.querySelector('#preview-compare img.before').src)).arrayBuffer()), 640);
              return JSON.stringify({status: r.status, width: r.proxy && r.proxy.width, error: r.error || ''}); }"""))
            await js("() => { document.querySelector('#m-export button[data-target=nutexb]').click(); return 1; }")
            seen["export"] = json.loads(await wait(RESULT, "#export-result"))
            seen["nutexb"] = json.loads(await js(LINK_BYTES, "#export-result a.download"))
            # Opened from the folder (file://): Firefox loads the module, the worker and lutkit.wasm.
            await call("browsingContext.navigate", {"context": context, "wait": "complete",
                                                    "url": "file://" + os.path.join(os.path.abspath(SITE), "index.html")})
            seen["file_engine"] = await wait("() => document.documentElement.dataset.engine || ''", timeout=30)
            seen["file_run"] = await js("""async () => { const r = await window.lutkitPage.runner.lane('main').run(['neutral', 'n.png']);
                                           return `${r.status} ${r.exitCode} ${Object.keys(r.outputs)}`; }""")
        try:
            trio.run(session)
        finally:
            browser.terminate()
            browser.wait(timeout=30)
            server.shutdown()
            server.server_close()
            shutil.rmtree(profile, ignore_errors=True)

        print(f"\nfirefox: lutkit ready at {seen['ready_ms']:.0f} ms", file=sys.stderr)
        self.assertEqual(seen["engine"], "ready")
        # The 2 s of the issue are asserted in Chromium (test_page_start.py); here a sanity bound
        # (0.67-1.84 s seen, the higher with both cores busy building).
        self.assertLess(seen["ready_ms"], 5000)
        self.assertIn("is-ok", seen["preview"]["cls"], seen["preview"])
        self.assertEqual(seen["preview"]["command"],
                         "lutkit preview screenshot.png -o screenshot_in_game.png --lut graded.png --lut-target raw")
        self.assertEqual(seen["live"], {"status": "done", "width": 640, "error": ""})
        self.assertNotIn("is-error", seen["export"]["cls"], seen["export"])
        command = seen["export"]["command"]
        self.assertEqual(command, "lutkit convert graded.png color_grading_lut.nutexb --in-target raw")
        code, printed, written = run_native(command, {"graded.png": read(os.path.join(work, "graded.png"))})
        self.assertEqual(code, 0, printed)
        self.assertEqual(seen["nutexb"]["name"], "color_grading_lut.nutexb")
        self.assertEqual(base64.b64decode(seen["nutexb"]["b64"]), written["color_grading_lut.nutexb"])
        code, printed, written = run_native("lutkit neutral neutral.png", {})
        self.assertEqual(base64.b64decode(seen["neutral"]["b64"]), written["neutral.png"])
        self.assertEqual(seen["file_engine"], "ready")
        self.assertEqual(seen["file_run"], "done 0 n.png")
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    unittest.main(verbosity=2)
