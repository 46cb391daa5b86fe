# SPDX-License-Identifier: Apache-2.0
"""Runs the same lutkit command line with the native CLI and with the browser edition.

NativeRunner runs build/bin/lutkit in a fresh folder holding the input files; BrowserRunner runs
lutkit.mjs's run() in a real headless Chromium (Debian's chromium and chromedriver through
python3-selenium), served from 127.0.0.1 by a thread of this process. Both return a Result with
the exit code, standard output (bytes), standard error (text), every file the command wrote or
changed (name -> bytes) and the wall time. Nothing is downloaded.
"""
import base64
import functools
import http.server
import os
import shutil
import subprocess
import tempfile
import threading
import time
from dataclasses import dataclass, field

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


@dataclass
class Result:
    exit_code: int
    stdout: bytes
    stderr: str
    files: dict = field(default_factory=dict)
    seconds: float = 0.0


def _snapshot(folder):
    out = {}
    for base, _, names in os.walk(folder):
        for n in names:
            p = os.path.join(base, n)
            with open(p, "rb") as f:
                out[os.path.relpath(p, folder)] = f.read()
    return out


class NativeRunner:
    def __init__(self, exe=None):
        self.exe = exe or os.environ.get("LUTKIT_NATIVE", os.path.join(ROOT, "build", "bin", "lutkit"))

    def run(self, args, files=None, stdin=b""):
        files = files or {}
        with tempfile.TemporaryDirectory(prefix="lutkit-native-") as d:
            for name, data in files.items():
                p = os.path.join(d, name)
                os.makedirs(os.path.dirname(p), exist_ok=True)
                with open(p, "wb") as f:
                    f.write(data)
            t0 = time.monotonic()
            p = subprocess.run([self.exe] + list(args), cwd=d, input=stdin, capture_output=True,
                               env=dict(os.environ, LC_ALL="C", NO_COLOR="1"))
            seconds = time.monotonic() - t0
            after = _snapshot(d)
        written = {k: v for k, v in after.items() if files.get(k) != v}
        return Result(p.returncode, p.stdout, p.stderr.decode("utf-8", "replace"), written, seconds)


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = dict(http.server.SimpleHTTPRequestHandler.extensions_map,
                          **{".mjs": "text/javascript", ".wasm": "application/wasm", ".js": "text/javascript"})

    def log_message(self, *args):
        pass


class BrowserRunner:
    """lutkit.mjs + lutkit.wasm from `site` (default build/web), in headless Chromium."""

    def __init__(self, site=None):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        site = site or os.environ.get("LUTKIT_WEB_DIR", os.path.join(ROOT, "build", "web"))
        self._dir = tempfile.mkdtemp(prefix="lutkit-web-")
        for name in ("lutkit.mjs", "lutkit.wasm"):
            shutil.copy(os.path.join(site, name), self._dir)
        shutil.copy(os.path.join(os.path.dirname(__file__), "harness.html"), self._dir)
        handler = functools.partial(_QuietHandler, directory=self._dir)
        self._server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        threading.Thread(target=self._server.serve_forever, daemon=True).start()
        opts = webdriver.ChromeOptions()
        self._profile = tempfile.mkdtemp(prefix="lutkit-chromium-")
        for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--disable-dev-shm-usage", "--user-data-dir=" + self._profile):
            opts.add_argument(a)
        opts.binary_location = os.environ.get("CHROMIUM", "/usr/bin/chromium")
        self.driver = webdriver.Chrome(service=Service(os.environ.get("CHROMEDRIVER", "/usr/bin/chromedriver")),
                                       options=opts)
        self.driver.set_script_timeout(600)
        self.driver.get("http://127.0.0.1:%d/harness.html" % self._server.server_address[1])
        for _ in range(200):
            if self.driver.title == "ready":
                break
            time.sleep(0.05)
        self.driver.execute_async_script("window.lutkitReady.then(() => arguments[0]())")

    def run(self, args, files=None, stdin=b""):
        files = {k: base64.b64encode(v).decode() for k, v in (files or {}).items()}
        t0 = time.monotonic()
        r = self.driver.execute_async_script(
            "window.lutkitRun(arguments[0], arguments[1], arguments[2]).then(arguments[3], "
            "e => arguments[3]({error: String(e && e.stack || e)}))",
            list(args), files, base64.b64encode(stdin).decode() if stdin else None)
        seconds = time.monotonic() - t0
        if "error" in r:
            raise RuntimeError("run() threw: " + r["error"])
        out = {k: base64.b64decode(v) for k, v in r["files"].items()}
        res = Result(r["exitCode"], base64.b64decode(r["stdout"]), r["stderr"], out, seconds)
        res.browser_ms = r["ms"]
        return res

    def close(self):
        try:
            self.driver.quit()
        finally:
            self._server.shutdown()
            shutil.rmtree(self._dir, ignore_errors=True)
            shutil.rmtree(self._profile, ignore_errors=True)
