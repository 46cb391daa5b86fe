#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Writes the match tests' known grade (tests/match/MatchTestUtil.h: channel mix, a lift and gamma
# on red, an S-curve on green, a gain on blue, saturation 1.25 about Rec.709 luma; float64) as a
# 65^3 .cube, red fastest, for ffmpeg's lut3d to grade pictures with in the match benchmarks.
#   python3 bench/grade_cube.py OUT.cube
import math
import sys


def grade(r, g, b):
    m = ((0.86, 0.10, 0.04), (0.06, 0.84, 0.10), (0.02, 0.14, 0.84))
    x = [m[i][0] * r + m[i][1] * g + m[i][2] * b for i in range(3)]
    c = [0.04 + 0.96 * max(x[0], 0.0) ** 0.85,
         0.5 + 0.5 * math.tanh(2.4 * (x[1] - 0.5)) / math.tanh(1.2),
         0.92 * x[2] + 0.02]
    luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
    return [luma + 1.25 * (v - luma) for v in c]


n = 65
with open(sys.argv[1], "w") as f:
    f.write("LUT_3D_SIZE %d\n" % n)
    for b in range(n):
        for g in range(n):
            for r in range(n):
                f.write("%.7f %.7f %.7f\n" % tuple(grade(r / (n - 1), g / (n - 1), b / (n - 1))))
