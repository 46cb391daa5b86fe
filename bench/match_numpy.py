#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# A plain HM-MKL-HM in numpy, the way colour-transfer scripts write it (issue 23's yardstick):
# per-channel histogram matching by np.unique and np.interp of the cumulative distributions, the
# Monge-Kantorovich linear map (F. Pitie, A. Kokaram, "The linear Monge-Kantorovitch linear colour
# mapping for example-based colour transfer", CVMP 2007) from the two covariances by eigh, then
# histogram matching again. float64, numpy's own threads (one, for these operations).
#   python3 bench/match_numpy.py SOURCE.ppm REFERENCE.ppm [TRUTH.ppm]
# Reads binary 8-bit PPMs (P6), prints the seconds of the match (reading excluded) and, with
# TRUTH, the mean and p99 distance of the result (rounded to 8 bits) from it in 8-bit steps.
import sys
import time

import numpy as np


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; comments skipped
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P6" and fields[3] == b"255", path + ": not an 8-bit P6 PPM"
    w, h = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(data, dtype=np.uint8, count=w * h * 3, offset=pos + 1)
    return pixels.reshape(-1, 3).astype(np.float64) / 255.0


def histogram_match(src, ref):
    """Per channel: T = Q_ref(F_src), distribution functions by unique values and counts."""
    out = np.empty_like(src)
    for c in range(3):
        s_values, s_index, s_counts = np.unique(src[:, c], return_inverse=True,
                                                return_counts=True)
        r_values, r_counts = np.unique(ref[:, c], return_counts=True)
        s_cdf = np.cumsum(s_counts).astype(np.float64)
        s_cdf /= s_cdf[-1]
        r_cdf = np.cumsum(r_counts).astype(np.float64)
        r_cdf /= r_cdf[-1]
        out[:, c] = np.interp(s_cdf, r_cdf, r_values)[s_index]
    return out


def mkl(src, ref, eps=1e-10):
    a = np.cov(src.T)
    b = np.cov(ref.T)
    da2, ua = np.linalg.eigh(a)
    da = np.sqrt(np.maximum(da2, eps))
    c = np.diag(da) @ ua.T @ b @ ua @ np.diag(da)
    dc2, uc = np.linalg.eigh(c)
    dc = np.sqrt(np.maximum(dc2, eps))
    t = ua @ np.diag(1.0 / da) @ uc @ np.diag(dc) @ uc.T @ np.diag(1.0 / da) @ ua.T
    return (src - src.mean(axis=0)) @ t + ref.mean(axis=0)


def main():
    src = read_ppm(sys.argv[1])
    ref = read_ppm(sys.argv[2])
    start = time.perf_counter()
    out = histogram_match(mkl(histogram_match(src, ref), ref), ref)
    seconds = time.perf_counter() - start
    line = "numpy_seconds %.3f" % seconds
    if len(sys.argv) > 3:
        truth = read_ppm(sys.argv[3])
        steps = np.abs(np.round(np.clip(out, 0.0, 1.0) * 255.0) - truth * 255.0)
        line += " mean_steps %.2f p99_steps %.0f" % (steps.mean(), np.percentile(steps, 99))
    print(line)


main()
