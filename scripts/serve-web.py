#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Serve lutkit's page (scripts/build-web.sh's folder) on 127.0.0.1, for this computer only.

    scripts/serve-web.py [DIR] [--port N]     (default DIR build/web, port 8000 or the next free)

Python's http.server takes its types from the system's MIME table, which may lack .mjs and
.wasm (a module script served as text/plain is refused by browsers; .wasm without
application/wasm loses streaming compilation), so they are set here. Every answer says
no-cache: a rebuilt site is picked up on reload. The tests (tests/web) serve the page with this.
"""
import argparse
import errno
import functools
import http.server
import os
import sys

TYPES = {
    ".html": "text/html; charset=utf-8",
    ".js": "text/javascript; charset=utf-8",
    ".mjs": "text/javascript; charset=utf-8",
    ".wasm": "application/wasm",
    ".css": "text/css; charset=utf-8",
    ".png": "image/png",
    ".svg": "image/svg+xml",
    ".json": "application/json",
    ".md": "text/plain; charset=utf-8",
}


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = dict(http.server.SimpleHTTPRequestHandler.extensions_map, **TYPES)
    quiet = False

    def end_headers(self):
        self.send_header("Cache-Control", "no-cache")
        self.send_header("X-Content-Type-Options", "nosniff")
        super().end_headers()

    def log_message(self, fmt, *args):
        if not self.quiet:
            super().log_message(fmt, *args)


class QuietHandler(Handler):
    quiet = True


class Server(http.server.ThreadingHTTPServer):
    daemon_threads = True

    def handle_error(self, request, client_address):
        # A browser that leaves a page mid-download resets the connection: nothing to report.
        if isinstance(sys.exc_info()[1], ConnectionError):
            return
        super().handle_error(request, client_address)


def make_server(folder, port=8000, quiet=False, tries=20):
    """An HTTP server for `folder` on 127.0.0.1 (port 0: any free port)."""
    handler = functools.partial(QuietHandler if quiet else Handler, directory=folder)
    last = None
    for p in ([0] if port == 0 else range(port, port + tries)):
        try:
            return Server(("127.0.0.1", p), handler)
        except OSError as e:
            if e.errno != errno.EADDRINUSE:
                raise
            last = e
    raise last


def main():
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    parser = argparse.ArgumentParser(description="Serve lutkit's page on 127.0.0.1.")
    parser.add_argument("dir", nargs="?", default=os.path.join(root, "build", "web"))
    parser.add_argument("--port", type=int, default=8000)
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.dir, "index.html")):
        sys.exit(f"serve-web: {args.dir}: no index.html (scripts/build-web.sh builds the page)")
    server = make_server(args.dir, args.port)
    print(f"lutkit's page: http://127.0.0.1:{server.server_address[1]}/  (serving {args.dir}; Ctrl-C stops)",
          flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()


if __name__ == "__main__":
    main()
