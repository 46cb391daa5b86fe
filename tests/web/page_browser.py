# SPDX-License-Identifier: Apache-2.0
"""lutkit's page (build/web) in a real headless Chromium, driven as a user drives it.

Debian's chromium and chromedriver through python3-selenium; the page is served from 127.0.0.1 by
scripts/serve-web.py's server in a thread of this process. Nothing is downloaded at run time: the
browser runs with a fresh profile and no background networking. Files are given through the
page's own file inputs, buttons are clicked, downloads land in a folder of the test's.

Long tasks (the Long Tasks API, every main-thread task over 50 ms) are recorded from the first
script of the page on, so a test can say that no task took over 100 ms while lutkit worked.
"""
import importlib.util
import json
import os
import shutil
import tempfile
import threading
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SITE = os.environ.get("LUTKIT_WEB_DIR", os.path.join(ROOT, "build", "web"))
NATIVE = os.environ.get("LUTKIT_NATIVE", os.path.join(ROOT, "build", "bin", "lutkit"))

_spec = importlib.util.spec_from_file_location("serve_web", os.path.join(ROOT, "scripts", "serve-web.py"))
serve_web = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(serve_web)

LONG_TASKS = """
window.__longTasks = [];
try {
  new PerformanceObserver((list) => {
    for (const e of list.getEntries())
      window.__longTasks.push({start: e.startTime, duration: e.duration, name: e.name});
  }).observe({type: 'longtask', buffered: true});
} catch (e) { window.__longTasksError = String(e); }
"""


class Page:
    """One Chromium with the page open; close() ends both."""

    def __init__(self, width=1280, height=720, site=SITE):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        for name in ("index.html", "lutkit.mjs", "lutkit.wasm", "worker.js"):
            if not os.path.isfile(os.path.join(site, name)):
                raise FileNotFoundError(f"{site}/{name}: build the page first (scripts/build-web.sh)")
        self.server = serve_web.make_server(site, port=0, quiet=True)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)
        self.thread.start()
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}/"
        self.captures = []
        self.profile = tempfile.mkdtemp(prefix="lutkit-page-profile-")
        self.downloads = tempfile.mkdtemp(prefix="lutkit-page-downloads-")
        options = webdriver.ChromeOptions()
        options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
        for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                     "--disable-background-networking", "--disable-component-update", "--disable-sync",
                     "--disable-dev-shm-usage", f"--user-data-dir={self.profile}",
                     f"--window-size={width},{height}", "--hide-scrollbars"):
            options.add_argument(flag)
        options.add_experimental_option("prefs", {
            "download.default_directory": self.downloads,
            "download.prompt_for_download": False,
            "safebrowsing.enabled": False,
        })
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        service = Service(shutil.which("chromedriver") or "/usr/bin/chromedriver")
        self.driver = webdriver.Chrome(service=service, options=options)
        self.driver.set_script_timeout(300)
        self.driver.execute_cdp_cmd("Browser.setDownloadBehavior",
                                    {"behavior": "allow", "downloadPath": self.downloads})
        self.driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": LONG_TASKS})
        # The browser's viewport, not its window, is 1280x720.
        self.driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                                    {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def open(self, path=""):
        self.driver.get(self.url + path)

    def close(self):
        try:
            self.driver.quit()
        finally:
            self.server.shutdown()
            self.server.server_close()
            shutil.rmtree(self.profile, ignore_errors=True)
            shutil.rmtree(self.downloads, ignore_errors=True)

    # -- finding and acting
    def js(self, script, *args):
        return self.driver.execute_script(script, *args)

    def q(self, css):
        from selenium.webdriver.common.by import By
        return self.driver.find_element(By.CSS_SELECTOR, css)

    def qs(self, css):
        from selenium.webdriver.common.by import By
        return self.driver.find_elements(By.CSS_SELECTOR, css)

    def wait(self, condition, timeout=120, what="a condition", poll=0.1):
        """Polls condition() until it returns a true value; returns it."""
        end = time.monotonic() + timeout
        last_error = None
        while time.monotonic() < end:
            try:
                value = condition()
                if value:
                    return value
            except Exception as e:  # the element may not be there yet
                last_error = e
            time.sleep(poll)
        raise TimeoutError(f"waited {timeout} s for {what}" + (f" (last error: {last_error})" if last_error else ""))

    def give_file(self, input_id, *paths):
        """Chooses files in the page's file input (what the file dialog does)."""
        self.q(f"#{input_id}").send_keys("\n".join(os.path.abspath(p) for p in paths))

    def drop_file(self, css, path):
        """Drops a file on an element as a drag from the desktop does (a drop event carrying it)."""
        import base64
        with open(path, "rb") as f:
            data = base64.b64encode(f.read()).decode()
        self.js("""
          const [css, name, b64] = arguments;
          const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
          const dt = new DataTransfer();
          dt.items.add(new File([bytes], name));
          const target = document.querySelector(css);
          target.scrollIntoView({block: 'center'});
          for (const type of ['dragenter', 'dragover', 'drop'])
            target.dispatchEvent(new DragEvent(type, {bubbles: true, cancelable: true, dataTransfer: dt}));
        """, css, os.path.basename(path), data)

    def click(self, css):
        el = self.q(css)
        self.driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", el)
        el.click()

    def mark(self, css):
        """Marks what a result area shows now, so result_done() waits for the next run."""
        self.js("""const n = document.querySelector(arguments[0]);
                   const s = n && n.querySelector('.status'); if (s) s.dataset.old = '1';""", css)

    def result_done(self, css, timeout=180):
        """Waits for a result area to show a finished run (not one mark() saw); returns its state."""
        def done():
            r = self.js("""
              const n = document.querySelector(arguments[0]);
              const s = n && n.querySelector('.status');
              if (!s || s.dataset.old || n.classList.contains('is-running')) return null;
              return {cls: n.className, exit: n.dataset.exit, status: n.querySelector('.status').textContent,
                      text: n.innerText, command: (n.querySelector('details.command code') || {}).textContent || ''};
            """, css)
            return r
        return self.wait(done, timeout, f"the result in {css}")

    def download(self, css_link, timeout=60):
        """Clicks a download link; returns (name, bytes) once the file is complete."""
        link = self.q(css_link)
        name = link.get_attribute("download")
        path = os.path.join(self.downloads, name)
        if os.path.exists(path):
            os.remove(path)
        self.driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", link)
        link.click()
        self.wait(lambda: os.path.exists(path) and not os.path.exists(path + ".crdownload")
                  and os.path.getsize(path) > 0, timeout, f"the download of {name}")
        time.sleep(0.2)
        with open(path, "rb") as f:
            return name, f.read()

    def screenshot(self, path):
        """Saves the viewport; the page's clock before and after is kept in self.captures (a
        capture makes the browser paint on the page's thread: a long task of the test's own)."""
        os.makedirs(os.path.dirname(path), exist_ok=True)
        before = self.js("return performance.now()")
        self.driver.save_screenshot(path)
        self.captures.append((before, self.js("return performance.now()"), os.path.basename(path)))

    def long_tasks(self):
        return self.js("return window.__longTasks || []")

    def console_errors(self):
        try:
            logs = self.driver.get_log("browser")
        except Exception:
            return []
        return [e for e in logs if e.get("level") == "SEVERE"]

    def timing(self):
        return json.loads(self.js("""return JSON.stringify({
          ui: window.lutkitPage && window.lutkitPage.uiReadyAt, ready: window.lutkitPage && window.lutkitPage.readyAt,
          version: window.lutkitPage && window.lutkitPage.version})"""))
