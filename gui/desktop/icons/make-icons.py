#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes lutkit-editor's icon and renders the PNG sizes (gui/desktop/icons/, run from anywhere).

The icon is an RGB colour cube seen from its white corner; each visible face is an NxN lattice of
flat cells, each cell the colour of the cube at its centre, as a 3D LUT's lattice. Small sizes
get fewer, larger cells so the faces still read (16 px: 2x2, 32 and 48 px: 3x3, larger: 4x4).

    hicolor/scalable/apps/lutkit-editor.svg       4x4 cells, the icon at any size
    sources/lutkit-editor-2x2.svg, -3x3.svg       the small-size drawings
    hicolor/<S>x<S>/apps/lutkit-editor.png        rendered with rsvg-convert (librsvg2-bin)

The PNGs are committed, so a build needs no SVG renderer; run this again after changing the
drawing and commit what it writes.
"""
import math
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
CENTRE = (128.0, 132.0)
RADIUS = 112.0  # centre to an outer vertex of the hexagon


def vertex(angle):  # degrees, 0 = up, clockwise
    a = math.radians(angle)
    return (CENTRE[0] + RADIUS * math.sin(a), CENTRE[1] - RADIUS * math.cos(a))


def svg(cells, gap):
    top, upper_right, lower_right, bottom, lower_left, upper_left = (
        vertex(a) for a in (0, 60, 120, 180, 240, 300))

    def edge(p):
        return (p[0] - CENTRE[0], p[1] - CENTRE[1])

    # The white corner is the hexagon's centre; magenta upper left, cyan upper right, yellow at
    # the bottom; the faces are b = 1 (top), r = 1 (left) and g = 1 (right).
    faces = [
        ("top", edge(upper_left), edge(upper_right), lambda u, v: (1 - v, 1 - u, 1)),
        ("left", edge(upper_left), edge(bottom), lambda u, v: (1, 1 - u, 1 - v)),
        ("right", edge(upper_right), edge(bottom), lambda u, v: (1 - u, 1, 1 - v)),
    ]
    hexagon = " ".join(f"{x:.1f},{y:.1f}" for x, y in
                       (top, upper_right, lower_right, bottom, lower_left, upper_left))
    out = [
        '<svg xmlns="http://www.w3.org/2000/svg" width="256" height="256" viewBox="0 0 256 256">',
        "  <title>lutkit-editor</title>",
        f"  <!-- An RGB colour cube seen from its white corner; each face a {cells}x{cells} lattice"
        " of cells in the cube's colour at the cell centre (gui/desktop/icons/make-icons.py). -->",
        f'  <polygon points="{hexagon}" fill="#1f2026" stroke="#1f2026" stroke-width="12"'
        ' stroke-linejoin="round"/>',
    ]
    for name, a, b, colour in faces:
        out.append(f'  <g id="{name}">')
        for i in range(cells):
            for j in range(cells):
                u0, u1 = i / cells + gap, (i + 1) / cells - gap
                v0, v1 = j / cells + gap, (j + 1) / cells - gap
                points = " ".join(
                    f"{CENTRE[0] + u * a[0] + v * b[0]:.1f},{CENTRE[1] + u * a[1] + v * b[1]:.1f}"
                    for u, v in ((u0, v0), (u1, v0), (u1, v1), (u0, v1)))
                rgb = colour((i + 0.5) / cells, (j + 0.5) / cells)
                fill = "#%02x%02x%02x" % tuple(round(255 * c) for c in rgb)
                out.append(f'    <polygon points="{points}" fill="{fill}"/>')
        out.append("  </g>")
    out.append("</svg>")
    return "\n".join(out) + "\n"


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def main():
    scalable = os.path.join(HERE, "hicolor/scalable/apps/lutkit-editor.svg")
    write(scalable, svg(4, 0.035))
    small = {2: os.path.join(HERE, "sources/lutkit-editor-2x2.svg"),
             3: os.path.join(HERE, "sources/lutkit-editor-3x3.svg")}
    write(small[2], svg(2, 0.1))
    write(small[3], svg(3, 0.05))
    for size, source in ((16, small[2]), (32, small[3]), (48, small[3]), (64, scalable),
                         (128, scalable), (256, scalable)):
        png = os.path.join(HERE, f"hicolor/{size}x{size}/apps/lutkit-editor.png")
        os.makedirs(os.path.dirname(png), exist_ok=True)
        subprocess.run(["rsvg-convert", "-w", str(size), "-h", str(size), source, "-o", png],
                       check=True)


if __name__ == "__main__":
    main()
