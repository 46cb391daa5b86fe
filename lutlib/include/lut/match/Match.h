// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit match: a LUT that gives a source picture the look of one or more reference pictures,
// with no correspondence between their pixels (docs/match.md). One implementation for
// `lutkit match` and the editor's "Match to reference...":
//
//   fitMatch   the statistics of the pictures and the transfer (lut/match/MatchTransfer.h) by
//              the method asked for (lut/match/MatchOptions.h); `auto` tries them all;
//   bakeMatch  the transfer, strength and preserve applied (lut/match/MatchFinish.h), as a LUT
//              file: a 1D shaper and a 3D table (or the table alone when the shaper would be the
//              identity); cheap, so the editor re-bakes it while a slider moves;
//   matchLook  both, and the report (lut/match/MatchReport.h) measured with the LUT as baked.
#include "lut/Error.h"
#include "lut/Image.h"
#include "lut/LutFile.h"
#include "lut/Progress.h"
#include "lut/match/MatchOptions.h"
#include "lut/match/MatchReport.h"
#include "lut/match/MatchTransfer.h"

#include <string>
#include <vector>

namespace lut {

struct MatchPicture {
    ImageView pixels;    // stored values as float RGBA (as lut::formats::readImage gives them)
    bool linear = false; // scene-linear values (a float file, lut::decideSceneKind); else
                         // display-encoded (sRGB). A reference of the other kind than the source
                         // is converted to the source's.
    int bitDepth = 0;    // 8 or 16 for integer files, 0 for float
    // Empty = every pixel counts; else the same size as pixels: a pixel counts where the mask's
    // (R + G + B) / 3 * A is at least 0.5 (white and opaque = use, black or transparent = ignore).
    ImageView mask;
    std::string name; // names the picture in messages
    // A large picture read in part (matchSampleStep): pixels and mask hold every step-th column
    // and row, from the first, of a picture (and mask) of fullWidth x fullHeight; the fit takes
    // the same pixels it would take of the whole. 1: pixels is the whole picture.
    int step = 1;
    int fullWidth = 0, fullHeight = 0;
    int maskFullWidth = 0, maskFullHeight = 0;
};

// The step of the regular grid the fit samples a width x height picture on (1: every pixel):
// at most 4 megapixels of the source, 4 / references of each reference (at least 65536). A
// caller may read only that grid of a large file (MatchPicture::step).
int matchSampleStep(int width, int height, bool source, std::size_t references);

struct MatchFitResult {
    MatchTransfer transfer;
    MatchReport report; // method, candidates, notes and timings of the fit; no LUT figures yet
    Diagnostics diagnostics;
};

// Throws lut::Error for no reference, an empty picture, a mask of another size, a picture with
// no usable pixel (all masked or NaN), a size outside 2..129 or a bad strength.
// With `progress` (lut/Progress.h; the editor's worker), the fraction done is reported between
// the fit's steps and a cancel throws CancelledError at the next one; the result is the same.
MatchFitResult fitMatch(const MatchPicture& source, const std::vector<MatchPicture>& references,
                        const MatchOptions& options, const Progress* progress = nullptr);

// The LUT file for a transfer with options' size, strength and preserve: a shaper of the
// transfer's x -> u (4096 entries; 1021 = 4 per 8-bit code for display data) when it has one,
// and a size^3 table of finish(x(u), y(u)) over u's range.
LutFile bakeMatch(const MatchTransfer& transfer, const MatchOptions& options);

struct MatchResult {
    LutFile lut;
    MatchTransfer transfer;
    MatchReport report;
    Diagnostics diagnostics; // the fit's warnings and what the measurement found (clipping)
};

MatchResult matchLook(const MatchPicture& source, const std::vector<MatchPicture>& references,
                      const MatchOptions& options);

} // namespace lut
