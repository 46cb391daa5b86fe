# SPDX-License-Identifier: Apache-2.0
"""lutkit.mjs's run() under Node (quick checks; the tests' own runner is Chromium's)."""
import base64
import json
import os
import subprocess
import time

from lutkit_runner import ROOT, Result


class NodeRunner:
    def __init__(self, site=None):
        site = site or os.environ.get("LUTKIT_WEB_DIR", os.path.join(ROOT, "build", "web"))
        env = dict(os.environ, NODE_PATH=os.environ.get("NODE_PATH", "/usr/share/nodejs"))
        self._p = subprocess.Popen(["node", "--no-experimental-fetch", os.path.join(os.path.dirname(__file__), "node_run.mjs"),
                                    os.path.abspath(site)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, env=env)

    def run(self, args, files=None, stdin=b""):
        q = {"args": list(args), "files": {k: base64.b64encode(v).decode() for k, v in (files or {}).items()},
             "stdin": base64.b64encode(stdin).decode() if stdin else None}
        t0 = time.monotonic()
        self._p.stdin.write((json.dumps(q) + "\n").encode())
        self._p.stdin.flush()
        r = json.loads(self._p.stdout.readline())
        return Result(r["exitCode"], base64.b64decode(r["stdout"]), r["stderr"],
                      {k: base64.b64decode(v) for k, v in r["files"].items()}, time.monotonic() - t0)

    def close(self):
        self._p.stdin.close()
        self._p.wait()
