#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# A plain HM-MKL-HM in numpy (bench/plain_transfer.py), the way colour-transfer scripts write it:
# issue 23's yardstick. float64, numpy's own threads (one, for these operations).
#   python3 bench/match_numpy.py SOURCE.ppm REFERENCE.ppm [TRUTH.ppm]
# Reads binary 8-bit PPMs (P6), prints the seconds of the match (reading excluded) and, with
# TRUTH, the mean and p99 distance of the result (rounded to 8 bits) from it in 8-bit steps.
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plain_transfer import plain_transfer, read_ppm  # noqa: E402


def main():
    src = read_ppm(sys.argv[1])
    ref = read_ppm(sys.argv[2])
    start = time.perf_counter()
    out = plain_transfer(src, ref)(src)
    seconds = time.perf_counter() - start
    line = "numpy_seconds %.3f" % seconds
    if len(sys.argv) > 3:
        truth = read_ppm(sys.argv[3])
        steps = np.abs(np.round(np.clip(out, 0.0, 1.0) * 255.0) - truth * 255.0)
        line += " mean_steps %.2f p99_steps %.0f" % (steps.mean(), np.percentile(steps, 99))
    print(line)


main()
