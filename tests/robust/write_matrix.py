#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The write matrix (issue 41): every image format lutkit writes, from inputs with and without
Exif, ICC and sRGB tags, 8/16-bit and float, with and without alpha, tiled and multi-part, each
output read back by other programs and its pixels compared with numpy.

Nothing here is lutkit's: the inputs are made by oiiotool and ImageMagick (the ICC profile by
icc_profile() below, from the ICC.1 layout), the LUT is a 2^3 .cube of an affine map (every
interpolation of an affine map is exact, so the oracle is the formula in affine()), the input's
pixels are OpenImageIO's reading of it (`oiiotool --dumpdata`, alpha unassociated as lutkit
reads it), and each output is read by oiiotool, by ImageMagick (`convert OUT rgba:-`) and, for
TIFF, by libtiff's tiffinfo and tiffdump.

Usage: write_matrix.py LUTKIT WORKDIR inputs          make the inputs in WORKDIR/in (once)
       write_matrix.py LUTKIT WORKDIR GROUP           run one group, print one line per failure

Groups: apply:FMT (every input, written as FMT), structure (tiled, multi-page, multi-part),
stdout (-o - --format FMT), compression (every --compression), preview, embed.
Exit status: 0 when every check passed, 1 otherwise (each failure on its own line).
"""
import os
import re
import struct
import subprocess
import sys
import zlib

import numpy as np

# --- The inputs ------------------------------------------------------------------------------

W, H = 23, 13
# Corner colours of the bilinear fill (RGBA), inside (0, 1) so the LUT's domain clamps nothing.
CORNERS = "topleft=0.05,0.2,0.3,1:topright=0.9,0.1,0.55,0.8:bottomleft=0.4,0.85,0.2,0.35:" \
          "bottomright=0.7,0.6,0.95,0.05"
FLASH = 16  # Exif:Flash (a SHORT in the Exif directory): "no flash, flash suppression"
UNIQUE_ID = "0123456789abcdef0123456789abcdef"  # Exif:ImageUniqueID (ASCII, 32 hex digits)
OUTPUTS = ["png", "jpg", "tif", "exr", "bmp", "tga", "hdr", "webp", "dpx", "gif", "ppm"]

# What each output format holds (the promise the checks hold lutkit to).
# GIF: OpenImageIO 2.4 writes it opaque, so lutkit drops alpha for it (and says so).
HOLDS_ALPHA = {"png", "tif", "exr", "tga", "webp", "dpx"}
HOLDS_EXIF = {"png", "jpg", "tif"}
HOLDS_ICC = {"png", "jpg", "tif"}
HOLDS_SRGB = {"png", "jpg", "tif"}  # the sRGB chunk, Exif ColorSpace 1
LOSSY = {"jpg", "webp", "gif"}


def icc_profile():
    """A small ICC v2.1 RGB display profile (matrix and gamma 2.2 curves), from the ICC.1 layout:
    a 128-byte header, a tag table, then the tags, each 4-byte aligned."""
    def s15(v):
        return struct.pack(">i", int(round(v * 65536)))

    def xyz(x, y, z):
        return b"XYZ " + bytes(4) + s15(x) + s15(y) + s15(z)

    def curv(g):
        return b"curv" + bytes(4) + struct.pack(">IH", 1, int(round(g * 256))) + bytes(2)

    def desc(t):
        a = t.encode() + b"\0"
        return b"desc" + bytes(4) + struct.pack(">I", len(a)) + a + bytes(8) + bytes(3) + bytes(67)

    tags = [(b"desc", desc("lutkit write matrix")), (b"cprt", b"text" + bytes(4) + b"none\0"),
            (b"wtpt", xyz(0.9642, 1.0, 0.8249)), (b"rXYZ", xyz(0.4361, 0.2225, 0.0139)),
            (b"gXYZ", xyz(0.3851, 0.7169, 0.0971)), (b"bXYZ", xyz(0.1431, 0.0606, 0.7141)),
            (b"rTRC", curv(2.2)), (b"gTRC", curv(2.2)), (b"bTRC", curv(2.2))]
    first = 128 + 4 + 12 * len(tags)
    table, data = b"", b""
    for sig, body in tags:
        data += bytes((-(first + len(data))) % 4)
        table += sig + struct.pack(">II", first + len(data), len(body))
        data += body
    body = struct.pack(">I", len(tags)) + table + data
    header = (struct.pack(">I", 128 + len(body)) + b"lkit" + struct.pack(">I", 0x02100000) +
              b"mntr" + b"RGB " + b"XYZ " + struct.pack(">6H", 2020, 1, 1, 0, 0, 0) + b"acsp" +
              bytes(4) + bytes(4) + bytes(16) + bytes(4) + s15(0.9642) + s15(1.0) +
              s15(0.8249) + b"lkit" + bytes(44))
    assert len(header) == 128
    return header + body


def affine(rgb):
    """The LUT's map, in float64: what every interpolation of the 2^3 lattice gives."""
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    return np.stack([0.1 + 0.8 * g, 0.95 - 0.9 * r, 0.2 + 0.3 * r + 0.5 * b], axis=-1)


def cube_text():
    lines = ["LUT_3D_SIZE 2"]
    for b in (0, 1):
        for g in (0, 1):
            for r in (0, 1):
                o = affine(np.array([r, g, b], dtype=np.float64))
                lines.append(" ".join(repr(float(v)) for v in o))
    return "\n".join(lines) + "\n"


def run(args, stdin=None, check=False):
    p = subprocess.run(args, input=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if check and p.returncode != 0:
        raise RuntimeError(" ".join(args) + ": " + p.stderr.decode(errors="replace"))
    return p


# name -> (file, {"exif", "icc", "srgb"} it carries); frames of one input format form a sequence
# in.NNNN.ext so one lutkit run writes them all.
def input_plan():
    plan = []  # (format, depth, alpha, tag)
    for depth in ("uint8", "uint16"):
        for alpha in (False, True):
            for tag in ("none", "exif", "icc", "srgb"):
                plan.append(("png", depth, alpha, tag))
    for depth in ("uint8", "uint16", "float"):
        for alpha in (False, True):
            for tag in ("none", "exif", "icc", "srgb"):
                plan.append(("tif", depth, alpha, tag))
    for tag in ("none", "exif", "icc"):
        plan.append(("jpg", "uint8", False, tag))
    for depth in ("half", "float"):
        for alpha in (False, True):
            for tag in ("none", "exif"):
                plan.append(("exr", depth, alpha, tag))
    return plan


EXIF_ATTRS = ["--attrib:type=int", "Exif:Flash", str(FLASH),
              "--attrib", "Exif:ImageUniqueID", UNIQUE_ID]


def make_inputs(work):
    d = os.path.join(work, "in")
    os.makedirs(d, exist_ok=True)
    profile = os.path.join(d, "test.icc")
    with open(profile, "wb") as f:
        f.write(icc_profile())
    with open(os.path.join(work, "affine.cube"), "w") as f:
        f.write(cube_text())
    counters = {}
    cmd = ["oiiotool", "--nosoftwareattrib"]
    later = []  # ImageMagick steps: attach the profile, strip a JPEG
    for fmt, depth, alpha, tag in input_plan():
        counters[fmt] = counters.get(fmt, 0) + 1
        name = os.path.join(d, "%s.%04d.%s" % (fmt, counters[fmt], fmt))
        cmd += ["--pattern", "fill:" + CORNERS, "%dx%d" % (W, H), "4"]
        if not alpha:
            cmd += ["--ch", "R,G,B"]
        cmd += ["--eraseattrib", "oiio:ColorSpace"]
        if tag == "exif" and fmt != "png":
            cmd += EXIF_ATTRS
        if tag == "srgb":
            cmd += ["--attrib", "oiio:ColorSpace", "sRGB"]
        out = name
        if tag == "icc" and depth == "float":
            out = name + ".16.tif"  # ImageMagick (16-bit) attaches it, oiiotool makes it float
        elif tag == "icc" or (fmt == "jpg" and tag == "none") or (fmt == "png" and tag == "exif"):
            out = name + ".pre." + fmt
        cmd += ["-d", depth if out == name else ("uint16" if depth == "float" else depth),
                "-o", out, "--pop"]
        if out != name:
            later.append((fmt, depth, tag, out, name))
    run(cmd, check=True)
    # OpenImageIO writes a PNG's Exif as text: a PNG's eXIf chunk holds the Exif block
    # ImageMagick takes out of a JPEG oiiotool wrote with the tags.
    exif_jpg = os.path.join(d, "exif-source.jpg")
    run(["oiiotool", "--nosoftwareattrib", "--pattern", "constant:color=0.5,0.5,0.5", "8x8", "3"] +
        EXIF_ATTRS + ["-d", "uint8", "-o", exif_jpg], check=True)
    exif = run(["convert", exif_jpg, "exif:-"], check=True).stdout
    exif = exif[6:] if exif.startswith(b"Exif\0\0") else exif
    os.remove(exif_jpg)
    for fmt, depth, tag, pre, name in later:
        if fmt == "png" and tag == "exif":
            with open(pre, "rb") as f:
                png = f.read()
            with open(name, "wb") as f:
                f.write(png_with_chunk(png, b"eXIf", exif))
        elif tag == "icc" and depth == "float":
            tagged = pre + ".icc.tif"
            run(["convert", pre, "-profile", profile, tagged], check=True)
            run(["oiiotool", tagged, "-d", "float", "-o", name], check=True)
            os.remove(tagged)
        elif tag == "icc":
            run(["convert", pre, "-profile", profile, name], check=True)
        else:
            run(["convert", pre, "-strip", name], check=True)
        os.remove(pre)
    # Structure: tiled, multi-page and multi-part inputs (with Exif where the format keeps it).
    s = os.path.join(work, "struct")
    os.makedirs(s, exist_ok=True)
    pat = ["--pattern", "fill:" + CORNERS, "%dx%d" % (40, 36), "4"]
    other = "fill:" + CORNERS.replace("0.05,0.2", "0.5,0.25")
    pat2 = ["--pattern", other, "%dx%d" % (24, 20), "3"]  # a page of another size
    part2 = ["--pattern", other, "%dx%d" % (40, 36), "3"]  # OpenEXR's parts share a display window
    run(["oiiotool", "--nosoftwareattrib"] + pat + EXIF_ATTRS + ["-d", "uint16", "--tile", "16", "16", "-o",
                                             os.path.join(s, "tiled.tif")], check=True)
    run(["oiiotool", "--nosoftwareattrib"] + pat + ["-d", "half", "--tile", "16", "16", "-o",
                              os.path.join(s, "tiled.exr")], check=True)
    run(["oiiotool", "--nosoftwareattrib"] + pat + EXIF_ATTRS + ["-d", "uint8"] + pat2 + ["-d", "uint8", "--siappend",
                                                                    "-o", os.path.join(s, "pages.tif")],
        check=True)
    run(["oiiotool", "--nosoftwareattrib"] + pat + EXIF_ATTRS + ["-d", "uint8", "-otex",
                                                             os.path.join(s, "mip.tif")], check=True)
    run(["oiiotool", "--nosoftwareattrib"] + pat + ["-d", "half", "-otex",
                                                    os.path.join(s, "mip.exr")], check=True)
    run(["oiiotool", "--nosoftwareattrib"] + pat + ["-d", "half"] + part2 + ["-d", "float", "--siappend", "-o",
                                                     os.path.join(s, "parts.exr")], check=True)
    return d


def inputs_of(work, fmt):
    """The frames of one input format, in order, with their plan entries."""
    d = os.path.join(work, "in")
    rows = [p for p in input_plan() if p[0] == fmt]
    return [(os.path.join(d, "%s.%04d.%s" % (fmt, i + 1, fmt)), p) for i, p in enumerate(rows)]


# --- Readers ---------------------------------------------------------------------------------

HEAD = re.compile(r"^(\S.*?)\s*:\s+(\d+) x\s+(\d+), (\d+) channel, (\w+) (\w+)")
SUB = re.compile(r"^ subimage\s+(\d+):\s+(\d+) x\s+(\d+), (\d+) channel, (\w+) (\w+)")
PIX = re.compile(r"^\s+Pixel \((-?\d+), (-?\d+)\): (.*)$")


def oiio_read(paths):
    """OpenImageIO's reading of files (oiiotool --dumpdata, alpha unassociated as lutkit reads
    it): for each path a list of images (one per subimage), each a dict of the float pixels
    (H, W, C), type, format and the attributes `--info -v` prints; or a message when oiiotool
    cannot read it."""
    result = {}
    for start in range(0, len(paths), 40):
        chunk = paths[start:start + 40]
        if not parse_dump(chunk, result):
            for path in chunk:  # oiiotool stops at the first file it cannot read
                parse_dump([path], result)
    return result


def parse_dump(chunk, result):
    args = ["oiiotool", "-a", "--info", "-v", "--dumpdata"]
    for path in chunk:
        args += ["--iconfig", "oiio:UnassociatedAlpha", "1", path]
    p = run(args)
    if p.returncode != 0 and len(chunk) > 1:
        return False
    text = p.stdout.decode(errors="replace")
    err = p.stderr.decode(errors="replace")
    found = {}
    cur_file, images = None, None
    for line in text.splitlines():
        m = HEAD.match(line)
        if m and m.group(1).strip() in chunk:
            cur_file = m.group(1).strip()
            images = found.setdefault(cur_file, [])
            images.append({"w": int(m.group(2)), "h": int(m.group(3)), "c": int(m.group(4)),
                           "type": m.group(5), "fmt": m.group(6), "px": {}, "attrs": ""})
            continue
        m = SUB.match(line)
        if m and images is not None:
            img = {"w": int(m.group(2)), "h": int(m.group(3)), "c": int(m.group(4)),
                   "type": m.group(5), "fmt": m.group(6), "px": {}, "attrs": ""}
            if int(m.group(1)) == 0 and images and not images[-1]["px"]:
                img["attrs"] = images[-1]["attrs"]
                images[-1] = img
            else:
                images.append(img)
            continue
        m = PIX.match(line)
        if m and images:
            vals = m.group(3)
            if "(" in vals:  # integer types: "13107 26214 (0.2 0.4)"
                vals = vals[vals.index("(") + 1:vals.rindex(")")]
            images[-1]["px"][(int(m.group(1)), int(m.group(2)))] = [float(v) for v in vals.split()]
            continue
        if images and not line.startswith("Reading "):
            images[-1]["attrs"] += line + "\n"
    for path in chunk:
        if p.returncode != 0 or path not in found:
            result[path] = "oiiotool could not read it: " + (err.strip().splitlines() or [""])[0][:300]
            continue
        for img in found[path]:
            arr = np.zeros((img["h"], img["w"], img["c"]))
            xs = sorted({k[0] for k in img["px"]})
            ys = sorted({k[1] for k in img["px"]})
            x0, y0 = (xs[0] if xs else 0), (ys[0] if ys else 0)
            for (x, y), v in img["px"].items():
                arr[y - y0, x - x0, :len(v)] = v
            if len(img["px"]) != img["w"] * img["h"]:
                img["error"] = "oiiotool gave %d of %d pixels" % (len(img["px"]), img["w"] * img["h"])
            img["pixels"] = arr
            del img["px"]
        result[path] = found[path]
    return True


def magick_read(path, w, h, stored="uint16", index=0):
    """Another decoder's reading, RGBA as 16-bit stored values (no colour conversion):
    ImageMagick's (turned upright: it keeps a TGA's bottom-up rows as an orientation), or for DPX
    ffmpeg's (ImageMagick 6.9 cannot read OpenImageIO's DPX files of odd widths: "unable to read
    image data", oiiotool's own too)."""
    if path.endswith(".dpx"):
        # 8-bit as 8-bit: ffmpeg widens 8 to 16 bits by shifting (v * 256), not v * 257.
        eight = stored == "uint8"
        p = run(["ffmpeg", "-v", "error", "-i", path, "-f", "rawvideo", "-pix_fmt",
                 "rgba" if eight else "rgba64le", "-"])
        if p.returncode == 0 and eight:
            a = np.frombuffer(p.stdout, dtype=np.uint8)
            if a.size < w * h * 4:
                return "ffmpeg gave %d samples, not %d" % (a.size, w * h * 4)
            return a[:w * h * 4].reshape(h, w, 4).astype(np.float64) / 255.0
        who = "ffmpeg"
    else:
        p = run(["convert", "%s[%d]" % (path, index), "-auto-orient", "-set", "colorspace",
                 "sRGB", "-depth", "16", "rgba:-"])
        who = "ImageMagick"
    if p.returncode != 0:
        return who + " could not read it: " + p.stderr.decode(errors="replace").strip()[:300]
    a = np.frombuffer(p.stdout, dtype="<u2")
    if a.size < w * h * 4:
        return "%s gave %d samples, not %d" % (who, a.size, w * h * 4)
    return a[:w * h * 4].reshape(h, w, 4).astype(np.float64) / 65535.0


def magick_icc(path):
    p = run(["convert", path, "icc:-"])
    return p.stdout if p.returncode == 0 else b""


def png_with_chunk(png, kind, data):
    """The PNG with one more chunk before its first IDAT (PNG: length, type, data, CRC-32)."""
    chunk = struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    at = 8
    while at + 8 <= len(png):
        n = struct.unpack(">I", png[at:at + 4])[0]
        if png[at + 4:at + 8] == b"IDAT":
            return png[:at] + chunk + png[at:]
        at += 12 + n
    raise ValueError("no IDAT")


def png_chunks(path):
    with open(path, "rb") as f:
        data = f.read()
    names, at = [], 8
    while at + 8 <= len(data):
        n = struct.unpack(">I", data[at:at + 4])[0]
        names.append(data[at + 4:at + 8].decode("latin-1"))
        at += 12 + n
    return names


# --- Checks ----------------------------------------------------------------------------------

def step(img_type):
    return {"uint8": 1 / 255.0, "uint16": 1 / 65535.0}.get(img_type, 0.0)


def tolerance(fmt, img_type, expected):
    """Most a lossless output may differ from the float64 oracle: half a step of its type (the
    rounding), float32 arithmetic, half's 11 bits, RGBE's 8-bit mantissa."""
    if fmt == "hdr":
        return np.max(np.abs(expected), axis=-1, keepdims=True) / 128.0 + 1e-6
    if img_type == "half":
        return np.abs(expected) * 2.0 ** -11 + 1e-6
    if img_type in ("float", "double"):
        return np.abs(expected) * 1e-6 + 2e-6
    return step(img_type) * 0.5 + 2e-6


class Checker:
    def __init__(self):
        self.failures = []
        self.checked = 0
        self.pending = []

    def fail(self, what, why):
        self.failures.append("%s: %s" % (what, why))

    def later(self, what, path, check):
        """check(images) once the file is read: every pending file in one oiiotool run."""
        self.pending.append((what, path, check))

    def flush(self):
        pending, self.pending = self.pending, []
        read = oiio_read([p for _, p, _ in pending])
        for what, path, check in pending:
            if isinstance(read.get(path), str) or path not in read:
                self.fail(what, read.get(path, "not read"))
            else:
                check(read[path])

    def compare(self, what, got, want, tol, lossy):
        self.checked += 1
        if got.shape != want.shape:
            self.fail(what, "shape %s, expected %s" % (got.shape, want.shape))
            return
        diff = np.abs(got - want)
        if lossy:
            # Measured on these inputs (23x13 gradients): JPEG (4:2:0, quality 98) 2.7 steps of
            # 255 on average and 15.5 at most, WebP 1.6 and 11, GIF 0.9 and 18. A wrong LUT, a
            # channel swap or another picture is off by a tenth and more on average.
            if diff.mean() > 4.0 / 255 or diff.max() > 0.1:
                self.fail(what, "lossy output off by %.4f on average, %.4f at most" %
                          (diff.mean(), diff.max()))
            return
        over = diff > tol
        if over.any():
            at = tuple(np.argwhere(over)[0])
            where = "(%d, %d) channel %d" % (at[1], at[0], at[2]) if len(at) == 3 else str(at)
            self.fail(what, "%d samples off, first at %s: %.6f, expected %.6f" %
                      (int(over.sum()), where, got[at], want[at]))


def expected_output(inp, out_fmt, out_channels):
    """The oracle: the affine map of OpenImageIO's reading of the input, alpha as it was."""
    px = inp["pixels"]
    out = affine(px[..., :3])
    if out_channels >= 4 and px.shape[-1] >= 4:
        out = np.concatenate([out, px[..., 3:4]], axis=-1)
    elif out_channels >= 4:  # a format that always reads RGBA (GIF): opaque
        out = np.concatenate([out, np.ones(out.shape[:2] + (1,))], axis=-1)
    return out


def check_tiff(ck, what, path, has_exif):
    info = run(["tiffinfo", path])
    err = info.stderr.decode(errors="replace")
    text = info.stdout.decode(errors="replace")
    if info.returncode != 0 or "Error" in err or "MissingRequired" in err:
        ck.fail(what, "tiffinfo: " + (err.strip().splitlines() or ["exit %d" % info.returncode])[0])
        return
    dump = run(["tiffdump", path]).stdout.decode(errors="replace")
    first = dump.split("Directory 1:")[0]
    for tag in ("ImageWidth (256)", "ImageLength (257)"):
        if tag not in first:
            ck.fail(what, "tiffdump: the first directory has no " + tag)
    if has_exif:
        if not re.search(r"^(ExifIFD )?\(?34665", first, re.M) and "(34665)" not in first:
            ck.fail(what, "tiffdump: the first directory has no Exif directory (34665)")
        if "Flash: %d" % FLASH not in text:
            ck.fail(what, "tiffinfo: the Exif directory lost Flash")


def check_output(ck, what, out_path, out_fmt, inp, tags, lossy=None, alpha_expected=None):
    """One output against its input image (OpenImageIO's reading), once ck.flush() reads it."""
    ck.later(what, out_path, lambda read: check_image(ck, what, out_path, out_fmt, read, inp, tags,
                                                      lossy, alpha_expected))


def check_image(ck, what, out_path, out_fmt, read, inp, tags, lossy=None, alpha_expected=None,
                index=0):
    img = read[index]
    if "error" in img:
        ck.fail(what, img["error"])
        return
    lossy = out_fmt in LOSSY if lossy is None else lossy
    if (img["w"], img["h"]) != (inp["w"], inp["h"]):
        ck.fail(what, "%dx%d, not %dx%d" % (img["w"], img["h"], inp["w"], inp["h"]))
        return
    in_alpha = inp["c"] >= 4
    if alpha_expected is None:
        alpha_expected = in_alpha and out_fmt in HOLDS_ALPHA
    # OpenImageIO's GIF reader gives RGBA: an opaque alpha is no alpha.
    got_alpha = img["c"] >= 4 and not (out_fmt == "gif" and np.all(img["pixels"][..., 3] == 1.0))
    if got_alpha != alpha_expected:
        ck.fail(what, "alpha %s, expected %s" % (got_alpha, alpha_expected))
    channels = 4 if got_alpha else 3
    want = expected_output(inp, out_fmt, channels)
    got = img["pixels"][..., :channels]
    # A half input keeps half's precision in a float output (TIFF stores half as float).
    kind = "half" if inp["type"] == "half" and img["type"] == "float" else img["type"]
    tol = tolerance(out_fmt, kind, want)
    if out_fmt == "ppm" and img["type"] == "uint16":
        tol = tol + 1.0 / 65535  # OpenImageIO 2.4's PNM reader: 16-bit 59309 read as 59308
    webp_alpha = out_fmt == "webp" and got.shape[-1] == 4
    if webp_alpha:
        # OpenImageIO 2.4's WebP writer changes colour with alpha (lutkit warns: WEBP with
        # alpha): only the alpha is held to the oracle.
        got, want = got[..., 3:4], want[..., 3:4]
        tol = tol[..., 3:4] if np.ndim(tol) else tol
    ck.compare(what + " (oiiotool)", got, want, tol, lossy)
    # ImageMagick: the same file through another decoder.
    # ImageMagick 6.9 reads an OpenEXR's first part only.
    im = magick_read(out_path, img["w"], img["h"], img["type"], index) \
        if not (index > 0 and out_fmt == "exr") else None
    if im is None:
        pass
    elif isinstance(im, str):
        ck.fail(what, im)
    else:
        im_want = np.clip(want, 0, 1)
        im_got = im[..., :channels][..., 3:4] if webp_alpha else im[..., :channels]
        # ImageMagick 6.9 reads OpenEXR through half (ImfRgba).
        im_kind = "half" if out_fmt == "exr" else kind
        ck.compare(what + " (%s)" % ("ffmpeg" if out_fmt == "dpx" else "ImageMagick"),
                   im_got, im_want, tolerance(out_fmt, im_kind, im_want) + 1.0 / 65535, lossy)
    check_tags(ck, what, out_path, out_fmt, img["attrs"], tags)


def check_tags(ck, what, out_path, out_fmt, attrs, tags):
    """The tags the output must carry (tags_of), read by oiiotool, ImageMagick (the ICC
    profile's bytes), the PNG's chunk list and libtiff."""
    if "exif" in tags and "Exif:Flash: %d" % FLASH not in attrs:
        ck.fail(what, "the Exif tags were lost (no Exif:Flash)")
    if "icc" in tags and magick_icc(out_path) != icc_profile():
        ck.fail(what, "the ICC profile was lost or changed")
    if "srgb" in tags:
        if out_fmt == "png" and "sRGB" not in png_chunks(out_path):
            ck.fail(what, "the sRGB chunk was lost")
        if out_fmt in ("tif", "jpg") and "Exif:ColorSpace: 1" not in attrs:
            ck.fail(what, "the sRGB tag (Exif:ColorSpace 1) was lost")
    if out_fmt == "tif":
        check_tiff(ck, what, out_path, "exif" in tags)


def tags_of(plan_entry, out_fmt):
    """The tags of an input that its output must carry: Exif, the ICC profile and the sRGB tag
    where the output format holds them (an OpenEXR's Exif-named attributes in OpenEXR only)."""
    in_fmt, tag = plan_entry[0], plan_entry[3]
    if tag == "exif" and (out_fmt == "exr" if in_fmt == "exr" else out_fmt in HOLDS_EXIF):
        return {"exif"}
    if tag == "icc" and out_fmt in HOLDS_ICC:
        return {"icc"}
    if tag == "srgb" and out_fmt in HOLDS_SRGB:
        return {"srgb"}
    return set()


def lutkit(lk, args):
    return run([lk] + args)


def group_apply(ck, lk, work, out_fmt):
    outdir = os.path.join(work, "apply-" + out_fmt)
    os.makedirs(outdir, exist_ok=True)
    cube = os.path.join(work, "affine.cube")
    for in_fmt in ("png", "tif", "jpg", "exr"):
        frames = inputs_of(work, in_fmt)
        pattern = os.path.join(work, "in", in_fmt + ".%04d." + in_fmt)
        out_pattern = os.path.join(outdir, in_fmt + ".%04d." + out_fmt)
        p = lutkit(lk, ["apply", "-q", "-y", "--lut", cube, pattern, "-o", out_pattern])
        if p.returncode != 0:
            ck.fail("apply %s -> %s" % (in_fmt, out_fmt),
                    "exit %d: %s" % (p.returncode, p.stderr.decode(errors="replace").strip()[:400]))
            continue
        if out_fmt == "webp" and any(plan[2] for _, plan in frames):
            ck.checked += 1
            if "WEBP with alpha" not in p.stderr.decode(errors="replace"):
                ck.fail("apply %s -> webp" % in_fmt, "no warning that WebP's alpha changes colour")
        ins = oiio_read([f for f, _ in frames])
        outs = oiio_read([out_pattern % (i + 1) for i in range(len(frames))])
        for i, (f, plan) in enumerate(frames):
            out_path = out_pattern % (i + 1)
            what = "apply %s (%s %s%s, %s) -> %s" % (os.path.basename(f), plan[1],
                                                    "RGBA" if plan[2] else "RGB",
                                                    "", plan[3], out_fmt)
            if isinstance(ins[f], str):
                ck.fail(what, "the input: " + ins[f])
                continue
            if isinstance(outs.get(out_path), str) or out_path not in outs:
                ck.fail(what, outs.get(out_path, "not written"))
                continue
            check_image(ck, what, out_path, out_fmt, outs[out_path], ins[f][0], tags_of(plan, out_fmt))


def group_structure(ck, lk, work):
    s = os.path.join(work, "struct")
    cube = os.path.join(work, "affine.cube")
    cases = [("tiled.tif", "tif", {"exif"}), ("tiled.tif", "exr", set()), ("tiled.exr", "exr", set()),
             ("tiled.exr", "tif", set()), ("pages.tif", "tif", {"exif"}), ("pages.tif", "exr", set()),
             ("parts.exr", "exr", set()), ("parts.exr", "tif", set()),
             ("mip.tif", "tif", {"exif"}), ("mip.exr", "tif", set()), ("mip.exr", "exr", set())]
    for name, out_fmt, tags in cases:
        src = os.path.join(s, name)
        out = os.path.join(s, "out-%s.%s" % (name.replace(".", "-"), out_fmt))
        what = "apply %s -> %s" % (name, out_fmt)
        p = lutkit(lk, ["apply", "-q", "-y", "--lut", cube, src, "-o", out])
        if p.returncode != 0:
            ck.fail(what, "exit %d: %s" % (p.returncode, p.stderr.decode(errors="replace").strip()[:400]))
            continue
        ins, outs = oiio_read([src])[src], oiio_read([out]).get(out)
        if isinstance(outs, str):
            ck.fail(what, outs)
            continue
        if len(outs) != len(ins):
            ck.fail(what, "%d images, the input has %d" % (len(outs), len(ins)))
            continue
        for k in range(len(ins)):
            check_image(ck, "%s image %d" % (what, k + 1), out, out_fmt, outs, ins[k],
                        tags if k == 0 else set(), index=k)
        if name.startswith("mip"):
            levels = [re.search(r"MIP-map levels: (.*)", img["attrs"]) for img in (ins[0], outs[0])]
            if not levels[1] or levels[0].group(1) != levels[1].group(1):
                ck.fail(what, "MIP levels %s, the input's %s" % (
                    levels[1].group(1) if levels[1] else "none", levels[0].group(1)))
        if name.startswith("tiled") and out_fmt == name.split(".")[1]:
            if "tile size:" not in outs[0]["attrs"] and "tile" not in outs[0]["attrs"].lower():
                ck.fail(what, "not tiled")


def group_stdout(ck, lk, work):
    """-o - --format FMT: the bytes written to standard output, kept in a file by the shell."""
    cube = os.path.join(work, "affine.cube")
    d = os.path.join(work, "stdout")
    os.makedirs(d, exist_ok=True)
    picks = [p for p in inputs_of(work, "jpg") if p[1][3] == "exif"] + \
            [p for p in inputs_of(work, "tif") if p[1][1:] == ("uint16", True, "exif")] + \
            [p for p in inputs_of(work, "png") if p[1][1:] == ("uint8", False, "srgb")]
    ins = oiio_read([f for f, _ in picks])
    for f, plan in picks:
        for out_fmt in OUTPUTS:
            out = os.path.join(d, "%s.%s" % (os.path.basename(f), out_fmt))
            what = "apply %s -o - --format %s" % (os.path.basename(f), out_fmt)
            with open(out, "wb") as sink:
                p = subprocess.run([lk, "apply", "-q", "--lut", cube, f, "-o", "-", "--format",
                                    out_fmt], stdout=sink, stderr=subprocess.PIPE)
            if p.returncode != 0:
                ck.fail(what, "exit %d: %s" % (p.returncode, p.stderr.decode(errors="replace").strip()[:300]))
                continue
            check_output(ck, what, out, out_fmt, ins[f][0], tags_of(plan, out_fmt))
    ck.flush()


def group_compression(ck, lk, work):
    cube = os.path.join(work, "affine.cube")
    d = os.path.join(work, "compression")
    os.makedirs(d, exist_ok=True)
    jpg = [p for p in inputs_of(work, "jpg") if p[1][3] == "exif"][0]
    tif16 = [p for p in inputs_of(work, "tif") if p[1][1:] == ("uint16", True, "exif")][0]
    exr = [p for p in inputs_of(work, "exr") if p[1][1:] == ("half", True, "exif")][0]
    cases = [(jpg, "tif", c) for c in ("none", "zip", "lzw", "packbits", "jpeg")] + \
            [(tif16, "tif", c) for c in ("none", "zip", "lzw", "packbits")] + \
            [(exr, "exr", c) for c in ("none", "zip", "zips", "rle", "piz", "pxr24", "b44",
                                       "b44a", "dwaa", "dwab")] + [(jpg, "exr", "piz")]
    ins = oiio_read(sorted({c[0][0] for c in cases}))
    for (f, plan), out_fmt, comp in cases:
        out = os.path.join(d, "%s-%s.%s" % (os.path.basename(f), comp, out_fmt))
        what = "apply %s --compression %s -> %s" % (os.path.basename(f), comp, out_fmt)
        p = lutkit(lk, ["apply", "-q", "-y", "--lut", cube, f, "--compression", comp, "-o", out])
        if p.returncode != 0:
            ck.fail(what, "exit %d: %s" % (p.returncode, p.stderr.decode(errors="replace").strip()[:300]))
            continue
        lossy = comp in ("jpeg", "pxr24", "b44", "b44a", "dwaa", "dwab") or None
        check_output(ck, what, out, out_fmt, ins[f][0], tags_of(plan, out_fmt), lossy=lossy)
    ck.flush()


def group_preview(ck, lk, work):
    """preview --preset none --scene with the neutral LUT gives the input back (sRGB decode and
    encode): every output format from inputs carrying each tag."""
    d = os.path.join(work, "preview")
    os.makedirs(d, exist_ok=True)
    picks = [p for p in inputs_of(work, "jpg") if p[1][3] in ("exif", "icc")] + \
            [p for p in inputs_of(work, "png") if p[1][1:] in (("uint16", False, "srgb"),
                                                              ("uint8", True, "icc"))] + \
            [p for p in inputs_of(work, "tif") if p[1][1:] == ("uint8", False, "exif")]
    ins = oiio_read([f for f, _ in picks])
    for f, plan in picks:
        for out_fmt in ("png", "jpg", "tif", "webp", "bmp", "tga", "dpx", "ppm"):
            out = os.path.join(d, "%s.%s" % (os.path.basename(f), out_fmt))
            what = "preview %s -> %s" % (os.path.basename(f), out_fmt)
            p = lutkit(lk, ["preview", "-q", "-y", "--preset", "none", "--scene", "--lut",
                            "builtin:neutral", f, "-o", out])
            if p.returncode != 0:
                ck.fail(what, "exit %d: %s" % (p.returncode, p.stderr.decode(errors="replace").strip()[:300]))
                continue
            inp = dict(ins[f][0])
            # The oracle is the input itself: the inverse of affine() makes expected_output give it.
            inp["pixels"] = inverse_affine_input(inp["pixels"])
            check_output(ck, what, out, out_fmt, inp, tags_of(plan, out_fmt))
    ck.flush()


def inverse_affine_input(px):
    """The pixels whose affine() is px (so an identity can reuse the affine oracle)."""
    r = (0.95 - px[..., 1]) / 0.9
    g = (px[..., 0] - 0.1) / 0.8
    b = (px[..., 2] - 0.2 - 0.3 * r) / 0.5
    rgb = np.stack([r, g, b], axis=-1)
    return np.concatenate([rgb, px[..., 3:]], axis=-1)


def group_embed(ck, lk, work):
    """embed: the screenshot's pixels outside the patch kept, its tags kept, the file valid."""
    d = os.path.join(work, "embed")
    os.makedirs(d, exist_ok=True)
    shots = []
    for tag in ("exif", "icc", "srgb"):
        src = os.path.join(d, "shot-%s.%s" % (tag, "jpg" if tag != "srgb" else "png"))
        cmd = ["oiiotool", "--pattern", "fill:" + CORNERS, "96x64", "3", "--eraseattrib",
               "oiio:ColorSpace"]
        if tag == "exif":
            cmd += EXIF_ATTRS
        if tag == "srgb":
            cmd += ["--attrib", "oiio:ColorSpace", "sRGB"]
        cmd += ["-d", "uint8", "-o", src if tag != "icc" else src + ".pre.jpg"]
        run(cmd, check=True)
        if tag == "icc":
            run(["convert", src + ".pre.jpg", "-profile", os.path.join(work, "in", "test.icc"), src],
                check=True)
        shots.append((src, tag))
    ins = oiio_read([s for s, _ in shots])
    for src, tag in shots:
        for out_fmt in ("png", "tif", "jpg", "webp", "bmp", "tga", "ppm", "dpx"):
            out = os.path.join(d, "%s.%s" % (os.path.basename(src), out_fmt))
            what = "embed %s -> %s" % (os.path.basename(src), out_fmt)
            p = lutkit(lk, ["embed", "-q", "-y", "--target", "raw", "--size", "5", "--scale", "1",
                            "--margin", "0", src, out])
            if p.returncode != 0:
                ck.fail(what, "exit %d: %s" % (p.returncode, p.stderr.decode(errors="replace").strip()[:300]))
                continue
            ck.later(what, out, lambda read, what=what, src=src, out=out, out_fmt=out_fmt, tag=tag:
                     check_embedded(ck, what, ins[src][0], out, out_fmt, read, tag, d))
    ck.flush()


def check_embedded(ck, what, src_image, out, out_fmt, read, tag, d):
    inp = dict(src_image)
    # Outside the patch (29x9 at (14, 14) and the JPEG grid around it: rows 32 on) the
    # screenshot is kept.
    keep = inp["pixels"][32:]
    inp["pixels"] = inverse_affine_input(keep)
    inp["h"] = keep.shape[0]
    img = dict(read[0])
    img["pixels"] = img["pixels"][32:]
    img["h"] = keep.shape[0]
    cut = os.path.join(d, "cut-%s" % os.path.basename(out))
    # ImageMagick reads the same rows of the output.
    run(["convert", out, "-auto-orient", "-crop", "%dx%d+0+32" % (inp["w"], inp["h"]), "+repage",
         cut])
    check_image(ck, what, cut, out_fmt, [img], inp, set(), out_fmt in LOSSY)
    # The tags: on the whole file.
    plan = ("png" if tag == "srgb" else "jpg", "uint8", False, tag)
    check_tags(ck, what, out, out_fmt, read[0]["attrs"], tags_of(plan, out_fmt))


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    lk, work, group = sys.argv[1], sys.argv[2], sys.argv[3]
    if group == "inputs":
        make_inputs(work)
        return 0
    ck = Checker()
    if group.startswith("apply:"):
        group_apply(ck, lk, work, group.split(":", 1)[1])
    elif group == "structure":
        group_structure(ck, lk, work)
    elif group == "stdout":
        group_stdout(ck, lk, work)
    elif group == "compression":
        group_compression(ck, lk, work)
    elif group == "preview":
        group_preview(ck, lk, work)
    elif group == "embed":
        group_embed(ck, lk, work)
    else:
        print("unknown group " + group)
        return 2
    for f in ck.failures:
        print(f)
    print("%d comparisons, %d failures" % (ck.checked, len(ck.failures)))
    return 1 if ck.failures or ck.checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
