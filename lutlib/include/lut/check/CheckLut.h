// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit's LUT check: an automatic health report of a LUT file (docs/check.md says what each
// figure measures and why its threshold is where it is).
//
//  - monotonicity: along every lattice line each output channel must move one way as its own
//    input rises (the way it goes end to end); along the grey, primary, secondary and skin rays
//    every channel that moves must do so one way. A fold-over is a run of lattice steps where it
//    goes back: where (input RGB), how far (8-bit steps), how much of the cube (its lattice
//    edges' share of the volume).
//  - banding: along the same lines, flat runs (the output stops changing: the change lost against
//    the slope around the run), steps (one lattice step jumping at least 4 times as far as both
//    neighbours) and steep slopes (one input step spread over many output steps).
//  - hue: ramps of constant Oklab hue and lightness from grey to the sRGB gamut's edge, every 5
//    degrees of hue at five lightnesses, through the LUT: the hue each comes out with (mean over
//    the ramp, weighted by chroma), the worst hues; and the skin line's drift.
//  - range: NaN/Inf entries, entries outside [0, 1], the share of the cube where each output
//    channel is clipped (held at 0 or 1 while its input moves; the clip's start found between
//    lattice points by extending the slope before it), and the share of the output cube the LUT
//    reaches at all.
//  - smoothness: second differences along every lattice line (8-bit steps, scaled to a 33-point
//    lattice), the worst cells; the total variation against the net change.
//  - invertibility: cells whose tetrahedra are folded (turned inside out against the LUT's
//    orientation) or flat: where `lutkit invert` has no unique answer.
//  - neutral: the LUT's distance from the identity (ΔE2000, 8-bit steps); no threshold.
// With a picture, the same over the picture's colours: every share is the share of its pixels
// (its colours in the LUT's cells, its hues), and what no pixel touches is left out; the share of
// its pixels outside the LUT's domain is reported.
//
// Entries and colours are taken as sRGB-encoded display values (as lut/ops/ColorDifference.h
// does); a file's 1D shaper is applied before its 3D table. NaN entries are reported and counted
// as 0 in every other figure. The library never prints: the front ends show the report.
#include "lut/Image.h"
#include "lut/LutFile.h"
#include "lut/check/CheckFinding.h"
#include "lut/check/CheckThresholds.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lut {

// A picture given a chunk of rows at a time: feed(chunk) for each chunk, in any order.
using ImageRows = std::function<void(const std::function<void(const ImageView& chunk)>& feed)>;

struct CheckOptions {
    CheckThresholds thresholds;
    const ImageView* image = nullptr; // check over this picture's colours (RGB; alpha ignored)
    // Or the picture a chunk of rows at a time (a large file weighed as it is read, never held
    // whole): called once with the function each chunk is to be given to. Takes image's place.
    ImageRows imageRows;
    std::size_t maxFindings = 40; // findings listed, worst first (the rest are counted)
    bool measureNeutral =
        true;         // the distance from neutral (ΔE2000 over the lattice: the slowest part)
    int nthreads = 0; // 0 = all cores
};

// Every figure the check measured, whether or not it crossed a threshold.
struct CheckFigures {
    // monotonicity
    double worstFold = 0.0;     // 8-bit steps
    double foldShare = 0.0;     // of the cube (or the picture)
    double greyWorstFold = 0.0; // 8-bit steps along the grey axis
    // Of the lattice lines, those whose own channel falls from end to end: monotone, the table
    // inverts there (a negative LUT's way); said in the summary beside "monotone".
    double fallingShare = 0.0;
    // banding
    double worstFlat = 0.0; // 8-bit steps lost
    double worstStep = 0.0; // 8-bit steps
    double steepest = 0.0;  // output steps per input step, over every lattice step
    double bandingShare = 0.0;
    // hue
    double worstHueShift = 0.0; // degrees, signed (positive: counter-clockwise in Oklab a, b)
    double worstHue = 0.0;      // the input hue where it happens (Oklab degrees)
    double meanHueShift = 0.0;  // mean |shift| over every hue
    double skinDrift = 0.0;     // degrees, signed
    // range
    std::size_t nonFinite = 0;    // entries
    double outOfRangeShare = 0.0; // of the entries
    glm::vec3 outputMin{0.0f}, outputMax{0.0f};
    std::array<double, 3> clippedShare{}; // per output channel, of the cube (or the picture)
    double gamutCoverage = 0.0;           // of the output cube [0, 1]^3 the LUT reaches
    double imageOutsideDomain = 0.0;      // of the picture's pixels (with an image)
    // smoothness
    double worstRough = 0.0;          // 8-bit steps on a 33-point lattice
    double totalVariationRatio = 1.0; // total variation / net change along the lattice lines
    // invertibility
    double foldedShare = 0.0;    // of the cube's volume (tetrahedra turned inside out)
    double flatShare = 0.0;      // flat tetrahedra
    glm::vec3 worstFolded{0.0f}; // the centre of the cell folded worst (an input colour)
    // neutral (when measured)
    bool neutralMeasured = false;
    double neutralMaxDeltaE = 0.0, neutralMeanDeltaE = 0.0, neutralMaxSteps = 0.0;
};

struct CheckSummary {
    CheckKind kind = CheckKind::Monotonicity;
    CheckStatus status = CheckStatus::Pass;
    std::string text; // the figures in one line: "grey axis monotone; worst fold-over 3.2 ..."
};

struct CheckReport {
    std::string description; // "3D 33^3", "1D 4096 + 3D 33^3", ...
    std::array<CheckSummary, kCheckKindCount> checks{};
    std::vector<CheckFinding> findings; // worst first: failures, then warnings, largest first
    std::size_t findingsLeftOut = 0;    // beyond CheckOptions::maxFindings
    CheckFigures figures;
    bool image = false; // shares are of a picture's pixels
    double seconds = 0.0;

    CheckStatus status() const; // the worst of the checks
    const CheckSummary& check(CheckKind kind) const {
        return checks[static_cast<std::size_t>(kind)];
    }
};

// Checks a LUT file's function (its shaper, then its table). Throws lut::Error for a file with
// neither a shaper nor a table.
CheckReport checkLut(const LutFile& file, const CheckOptions& options = {});
CheckReport checkLut(const Lut3D& lut, const CheckOptions& options = {});

} // namespace lut
