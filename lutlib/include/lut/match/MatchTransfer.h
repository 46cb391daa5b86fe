// SPDX-License-Identifier: Apache-2.0
#pragma once
// A fitted colour match as a function of the source's stored values, in the form a LUT file
// holds it: a per-channel shaper, then a 3D table (docs/match.md):
//
//   w = E(x)                          the working encoding (lut/match/WorkingSpace.h)
//   u = pre(w)                        per-channel curves: the first histogram matching
//   v = post(A u + b) + residual(u)   the MKL map, the second histogram matching, and the
//                                     regularised method's smooth correction (trilinear over
//                                     its own lattice on u's range)
//   y = E^-1(v)                       the matched colour, a stored value of the source's kind
//
// The gradient-map method replaces the middle line by
//   v = tone(lumaMatch(0.2126 u.r + 0.7152 u.g + 0.0722 u.b))
// (lumaMatch the source's luma histogram-matched to the reference's, steps kept; tone the
// reference's mean colour at each luma, linear between knots): not separable, so the file is a
// table alone.
// Each method leaves out what it does not use (identity curves, A = I and b = 0, no residual).
// The shaper of the exported file is x -> u, the table u -> y: HM-MKL-HM is exact in that form
// up to the table's interpolation of post(A u + b).
#include "lut/match/ChannelCurve.h"
#include "lut/match/MatchOptions.h"
#include "lut/match/MongeKantorovich.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace lut {

struct MatchTransfer {
    MatchMethod method = MatchMethod::HmMklHm;
    bool linear = false;              // scene-linear stored values: E is ACEScct
    glm::dvec3 domainMin{0.0};        // the stored values the LUT covers (the source's range
    glm::dvec3 domainMax{1.0};        // and at least [0, 1])
    std::array<ChannelCurve, 3> pre;  // empty = identity
    AffineColourMap affine;           // identity unless the method has MKL
    std::array<ChannelCurve, 3> post; // empty = identity
    int residualSize = 0;             // 0 = no residual
    glm::dvec3 residualMin{0.0}, residualMax{1.0}; // its lattice's range of u
    std::vector<glm::vec3> residual;               // residualSize^3, red fastest (as Lut3D)
    ChannelCurve lumaMatch;                        // gradient map: empty otherwise
    std::vector<glm::dvec3> tone;                  // its colours at knots over [toneMin, toneMax]
    double toneMin = 0.0, toneMax = 1.0;

    // Whether the file needs a shaper: pre is not the identity, or E is not.
    bool hasShaper() const;
    glm::dvec3 toLattice(const glm::dvec3& stored) const; // x -> u
    glm::dvec3 fromLattice(const glm::dvec3& u) const;    // u -> x (pre is strictly increasing)
    glm::dvec3 latticeOutput(const glm::dvec3& u) const;  // u -> y
    glm::dvec3 operator()(const glm::dvec3& stored) const {
        return latticeOutput(toLattice(stored));
    }
    // The working-space value before E^-1 (what the statistics compare).
    glm::dvec3 workingOutput(const glm::dvec3& u) const;
    glm::dvec3 residualAt(const glm::dvec3& u) const; // trilinear; zero without a residual
};

} // namespace lut
