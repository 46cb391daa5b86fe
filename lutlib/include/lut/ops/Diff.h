// SPDX-License-Identifier: Apache-2.0
#pragma once
// How two LUTs differ: per channel in 8-bit steps, in ΔE2000 (lut/ops/ColorDifference.h: entries
// are taken as sRGB-encoded), and where (lut/ops/Regions.h), over the LUT's lattice or over the
// colours of an image (e.g. a screenshot: the differences a player would see, weighted by how
// often each colour occurs). Heat-map pictures of the same are in lut/ops/HeatMap.h.
//
// NaN entries count as 0 and infinities as +-65504 (their number is reported): every figure is
// finite. diff(A, A) is exactly 0.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/Progress.h"
#include "lut/interp/Interpolation.h"
#include "lut/ops/Regions.h"

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace lut {

struct DiffOptions {
    Interpolation method = Interpolation::Tetrahedral;
    // Lattice diffs: the edge of the lattice compared on, spanning A's domain; 0 = the larger of
    // the two sizes. When A and B have this size and the same domain, their entries are compared
    // directly (no interpolation).
    int size = 0;
    int nthreads = 0; // 0 = all cores
    // Colours compared so far; a cancel stops the diff (CancelledError) within a few thousand
    // colours.
    const Progress* progress = nullptr;
    // Lattice diffs of two lattices that differ (size or domain): also bound |A - B| over every
    // input of A's domain, between the compared points too (DiffReport::boundSteps8).
    bool boundBetween = false;
};

struct DiffPoint {
    glm::vec3 input{0.0f}; // where (an input colour)
    glm::vec3 a{0.0f};     // A's output there
    glm::vec3 b{0.0f};     // B's output there
    double deltaE = 0.0;
};

struct RegionDiff {
    Region region = Region::Shadows;
    std::size_t count = 0; // colours compared in this region
    double meanDeltaE = 0.0;
    double maxDeltaE = 0.0;
    glm::dvec3 maxSteps8{0.0};  // largest |A - B| * 255 per channel
    glm::vec3 worstInput{0.0f}; // the input with the largest ΔE in this region
};

struct DiffReport {
    std::size_t count = 0;      // colours compared
    glm::dvec3 maxSteps8{0.0};  // largest |A - B| * 255 per channel R, G, B
    glm::dvec3 meanSteps8{0.0}; // mean |A - B| * 255 per channel
    double maxDeltaE = 0.0;
    double meanDeltaE = 0.0;
    double p95DeltaE = 0.0;                         // 95th percentile
    DiffPoint worst;                                // the colour with the largest ΔE2000
    std::array<RegionDiff, kRegionCount> regions{}; // indexed by Region
    std::size_t sanitizedEntriesA = 0; // entries of A that were NaN, infinite or beyond 65504
    std::size_t sanitizedEntriesB = 0;
    double seconds = 0.0;
    // What maxSteps8 covers. A lattice diff of two tables of one lattice (the same size and
    // domain, any interpolation) compares their entries, and between the points each interpolant
    // blends its entries with the same weights, so the difference there is a blend of the
    // entries' differences: maxSteps8 is the exact maximum over every input (maxEveryInput).
    // Otherwise it is the maximum at the colours compared; between them |A - B| may be larger:
    // with DiffOptions::boundBetween, boundSteps8 is a bound over every input of A's domain
    // (lut/ops/ErrorBound.h: held-out points plus the slope between them; NaN when not computed).
    // ΔE2000 is measured at the colours compared only.
    bool maxEveryInput = false;
    double boundSteps8 = NAN;

    bool identical() const { return maxDeltaE == 0.0 && maxSteps8 == glm::dvec3(0.0); }
    // The regions that had colours, largest mean ΔE first (ties: largest max ΔE first).
    std::vector<RegionDiff> rankedRegions() const;
};

// Over a lattice (see DiffOptions::size).
DiffReport diffLuts(const Lut3D& a, const Lut3D& b, const DiffOptions& options = {});
// Over a list of input colours.
DiffReport diffLutsOnColors(const Lut3D& a, const Lut3D& b, std::span<const glm::vec3> colors,
                            const DiffOptions& options = {});
// Over every pixel of an image (RGB; alpha ignored).
DiffReport diffLutsOnImage(const Lut3D& a, const Lut3D& b, const ImageView& image,
                           const DiffOptions& options = {});

// The same for two functions of a colour (what the game shows with a game LUT:
// lut/smash/PurposeOps.h's diffForPurpose): over a size^3 lattice over [0,1] (options.size;
// 0 = 33), or every pixel of an image. options.method is not used; the maps must be callable
// from several threads.
using ColourMap = std::function<glm::vec3(glm::vec3)>;
DiffReport diffMaps(const ColourMap& a, const ColourMap& b, const DiffOptions& options = {});
DiffReport diffMapsOnImage(const ColourMap& a, const ColourMap& b, const ImageView& image,
                           const DiffOptions& options = {});

} // namespace lut
