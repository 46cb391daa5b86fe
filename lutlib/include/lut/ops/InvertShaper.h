// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inverting a 3D table A into a 1D shaper then a 3D table (DaVinci Resolve's .cube form), for
// where the inverse is steep: the inverse of x^2.2 rises 64 times faster near black than a
// 33^3 lattice's first cell can follow, so one table alone leaves ~15 8-bit steps in the round
// trip. The shaper S is the per-channel inverse of A's neutral axis, d_c(t) = A(t, t, t)_c
// (piecewise linear on A's lattice diagonal, inverted exactly at S's entries, normalised onto
// [0, 1]); the table T at lattice point u holds the x with A(x) = d(u) (lut::invert's solver with
// InvertOptions::targetOf). So A^-1 = T(S(y)), and T is close to the identity where A acts per
// channel. Needs each d_c strictly increasing (else no shaper: `made` is false).
//
// The report's residual |A(T(S(y))) - y| over the inverse's domain and roundTrip |T(S(A(x))) - x|
// over A's domain are measured on points the solve did not use, bounds as lut/ops/ErrorBound.h
// builds them; the other fields are the table's solve (InvertReport).
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/ops/Invert.h"

namespace lut {

struct ShaperInvertResult {
    bool made = false; // false: A's neutral axis is not strictly increasing in every channel
    LutFile lut;       // shaper + table (no title: Resolve's dialect has none with a shaper)
    InvertReport report;
};

// options.size is the table's edge (0 = A's); shaperSize the shaper's entries.
ShaperInvertResult invertWithShaper(const Lut3D& a, const InvertOptions& options = {},
                                    int shaperSize = 4096);

} // namespace lut
