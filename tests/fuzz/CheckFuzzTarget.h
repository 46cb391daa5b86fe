// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz target for lutkit check (tests/fuzz/fuzz_check.cpp and the regression replay): the bytes
// are a thresholds file, a line "%%", then a .cube file (no "%%" line: all of it is the .cube).
// The thresholds parser returns or throws lut::ParseError naming a line; a .cube the reader
// accepts (up to 17^3, to keep a run short) is checked: every figure finite, shares within
// [0, 1], the verdict at least as bad as every finding, the findings within the cap.
#include "FuzzTargets.h"

#include "lut/check/CheckLut.h"

#include <cstring>

namespace lut::fuzz {

inline Outcome runCheck(const std::uint8_t* data, std::size_t size) {
    const std::string_view all(reinterpret_cast<const char*>(data), size);
    std::string_view thresholdsText, cubeText = all;
    if (const std::size_t at = all.find("\n%%\n"); at != std::string_view::npos) {
        thresholdsText = all.substr(0, at + 1);
        cubeText = all.substr(at + 4);
    }
    CheckOptions options;
    options.measureNeutral = false;
    options.nthreads = 1;
    options.maxFindings = 12;
    try {
        options.thresholds = parseCheckThresholds(thresholdsText, "fuzz.txt");
    } catch (const ParseError& e) {
        invariant(e.line() >= 1, "a thresholds error without its line");
    }
    LutFile file;
    try {
        file = formats::parseCube(cubeText, "fuzz.cube");
    } catch (const lut::Error&) {
        return Outcome::Refused;
    }
    checkLutFile(file);
    if (file.cube && file.cube->size() > 17)
        return Outcome::Accepted;
    const CheckReport r = checkLut(file, options);
    const CheckFigures& f = r.figures;
    for (double v : {f.worstFold, f.foldShare, f.greyWorstFold, f.worstFlat, f.worstStep,
                     f.steepest, f.bandingShare, f.worstHueShift, f.worstHue, f.meanHueShift,
                     f.skinDrift, f.outOfRangeShare, f.gamutCoverage, f.worstRough,
                     f.totalVariationRatio, f.foldedShare, f.flatShare})
        invariant(std::isfinite(v), "a check figure is not finite");
    invariant(r.findings.size() <= options.maxFindings, "more findings than the cap");
    for (const CheckFinding& x : r.findings) {
        invariant(std::isfinite(x.size) && x.size >= 0.0, "a finding's size");
        invariant(std::isfinite(x.share) && x.share >= 0.0 && x.share <= 1.0 + 1e-4,
                  "a finding's share");
        invariant(std::isfinite(x.input.x) && std::isfinite(x.input.y) && std::isfinite(x.input.z),
                  "a finding's place");
        invariant(x.severity != CheckStatus::Pass, "a finding that passes");
        invariant(r.status() >= x.severity, "a verdict better than a finding");
    }
    return Outcome::Accepted;
}

} // namespace lut::fuzz
