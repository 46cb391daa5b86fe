// SPDX-License-Identifier: Apache-2.0
#pragma once
// The thresholds of lutkit's LUT check (lut/check/CheckLut.h): for each figure, the value at
// which it warns and the value at which it fails (a figure at or above `fail` fails, at or above
// `warn` warns). docs/check.md explains each figure; `lutkit check --thresholds FILE` reads a file
// of lines `NAME = WARN FAIL` (or `NAME.warn = V`, `NAME.fail = V`), '#' starting a comment.
#include <string>
#include <string_view>
#include <vector>

namespace lut {

struct Threshold {
    double warn = 0.0;
    double fail = 0.0;
};

struct CheckThresholds {
    // Monotonicity: 8-bit steps an output channel falls back while its input rises.
    Threshold foldOver{0.5, 2.0};
    // Banding: 8-bit steps of output change a flat run loses against the slope around it.
    Threshold flat{4.0, 12.0};
    // Banding: 8-bit steps an output jumps across one lattice step beyond its neighbours.
    Threshold step{4.0, 12.0};
    // Banding: output 8-bit steps per input 8-bit step across one lattice step.
    Threshold steep{4.0, 16.0};
    // Hue: degrees the hue of a constant-hue ramp turns (mean over the ramp).
    Threshold hueShift{12.0, 25.0};
    // Hue: degrees the skin line's hue drifts.
    Threshold skinDrift{8.0, 20.0};
    // Range: NaN or infinite entries.
    Threshold nonFinite{1.0, 1.0};
    // Range: per cent of the entries outside [0, 1] by more than half an 8-bit step.
    Threshold outOfRange{0.5, 20.0};
    // Range: per cent of the cube where an output channel is clipped (held at 0 or 1).
    Threshold clip{2.0, 10.0};
    // Smoothness: second difference in 8-bit steps, scaled to a 33-point lattice.
    Threshold rough{6.0, 24.0};
    // Invertibility: per cent of the cube where the LUT folds over (cells turned inside out).
    Threshold folded{0.01, 5.0};
};

// One threshold's name (as the file spells it), what it measures and its unit, for the file
// parser, the documentation and `lutkit check --help`.
struct ThresholdKey {
    const char* name;
    Threshold CheckThresholds::*member;
    const char* unit;
    const char* meaning;
};
const std::vector<ThresholdKey>& thresholdKeys();

// Parses a thresholds file's text over `base`. Throws lut::ParseError naming path, line and
// column for an unknown name (with the closest known one), a missing or bad number, or a fail
// value below the warn value.
CheckThresholds parseCheckThresholds(std::string_view text, const std::string& path,
                                     const CheckThresholds& base = {});

} // namespace lut
