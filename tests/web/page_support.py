# SPDX-License-Identifier: Apache-2.0
"""What the page tests share: test pictures made by outside programs, the native CLI run on the
command line the page shows, PNG pixels read by ImageMagick, the screenshots' folder."""
import os
import shlex
import shutil
import struct
import subprocess
import tempfile
import zlib

from page_browser import NATIVE, ROOT

SHOTS = os.environ.get("LUTKIT_PAGE_SHOTS", os.path.join(ROOT, "build", "page-shots"))


def read(path):
    with open(path, "rb") as f:
        return f.read()


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)


def magick(*args):
    """ImageMagick, the outside image editor of these tests."""
    subprocess.run(["convert", *map(str, args)], check=True)


def outside_edit(src, dst):
    """A global edit as a user makes it in an image editor: curves on red and blue, saturation."""
    magick(src, "-channel", "R", "-evaluate", "multiply", "1.08", "-channel", "B", "-gamma", "0.9",
           "+channel", "-modulate", "100,115,100", dst)


def screenshot_png(path, width=1280, height=720):
    """An 8-bit in-game screenshot: the sample scene at a screenshot's size."""
    magick(os.path.join(ROOT, "samples", "sample_scene.png"), "-filter", "Lanczos", "-resize",
           f"{width}x{height}!", "-strip", path)


def png_claiming(path, width, height):
    """A tiny PNG whose header claims width x height pixels (a few hundred bytes of data)."""
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    idat = zlib.compress(b"\0" * 4096)
    write(path, b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b""))


def pixels(path_or_bytes):
    """The image's size and 16-bit RGBA samples (an 8-bit file's scaled exactly), by ImageMagick;
    a path or PNG bytes."""
    source = "png:-" if isinstance(path_or_bytes, bytes) else path_or_bytes
    stdin = path_or_bytes if isinstance(path_or_bytes, bytes) else None
    size = subprocess.run(["identify", "-format", "%wx%h %z ", source], input=stdin, check=True,
                          capture_output=True).stdout
    samples = subprocess.run(["convert", source, "-depth", "16", "rgba:-"], input=stdin, check=True,
                             capture_output=True).stdout
    return size + samples


def run_native(command_line, inputs, env=None):
    """Runs the command line the page showed ("lutkit ...") with the native CLI in a fresh folder
    holding `inputs` (name -> bytes); returns (exit code, output, {name: bytes} written)."""
    argv = shlex.split(command_line)
    assert argv[0] == "lutkit", command_line
    folder = tempfile.mkdtemp(prefix="lutkit-page-native-")
    try:
        for name, data in inputs.items():
            write(os.path.join(folder, name), data)
        p = subprocess.run([NATIVE] + argv[1:], cwd=folder, capture_output=True,
                           env=dict(os.environ, LC_ALL="C", **(env or {})))
        written = {}
        for name in os.listdir(folder):
            if name not in inputs or read(os.path.join(folder, name)) != inputs[name]:
                written[name] = read(os.path.join(folder, name))
        return p.returncode, p.stdout.decode() + p.stderr.decode(), written
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def shot(page, name, css=None):
    """Saves a screenshot of the page (scrolled to `css` first) as SHOTS/name.png."""
    if css:
        page.js("document.querySelector(arguments[0]).scrollIntoView({block: 'start'}); window.scrollBy(0, -8)", css)
    page.js("document.activeElement && document.activeElement.blur && document.activeElement.blur()")
    path = os.path.join(SHOTS, f"{name}.png")
    page.screenshot(path)
    return path


def work_periods_long_tasks(page, since_ms, limit_ms=100):
    """Long tasks after `since_ms` (the page's clock) over `limit_ms`, each with the screenshot it
    overlaps, if any."""
    slow = [dict(t) for t in page.long_tasks() if t["start"] >= since_ms and t["duration"] > limit_ms]
    for t in slow:
        for start, end, name in page.captures:
            if t["start"] < end and t["start"] + t["duration"] > start:
                t["capture"] = name
    return slow
