// SPDX-License-Identifier: Apache-2.0
#pragma once
// One finding of lutkit's LUT check (lut/check/CheckLut.h): what is wrong, where, how large, how
// much of the cube (or of a picture) it touches, and the region of input colours it concerns, so
// a front end can highlight those colours on a screenshot.
#include "lut/Image.h"
#include "lut/Lut1D.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lut {

// The checks, in the order reports list them.
enum class CheckKind { Monotonicity, Banding, Hue, Range, Smoothness, Invertibility, Neutral };
constexpr int kCheckKindCount = 7;
const char* toString(CheckKind kind); // "monotonicity", "banding", ...

enum class CheckStatus { Pass, Warn, Fail };
const char* toString(CheckStatus status); // "pass", "warn", "fail"

enum class FindingKind {
    FoldOver,   // an output channel falls while its input rises (monotonicity)
    Flat,       // the output stops changing while the input changes (banding: slope collapse)
    Step,       // the output jumps across one lattice step (banding: slope spike)
    Steep,      // one input step spreads over many output steps (banding)
    HueShift,   // constant-hue ramps come out with another hue (hue)
    SkinDrift,  // the skin line comes out with another hue (hue)
    NonFinite,  // NaN or infinite entries (range)
    OutOfRange, // entries outside [0, 1] (range)
    Clip,       // an output channel held at 0 or 1 over a region (range)
    Rough       // large second differences (smoothness)
};
const char* toString(FindingKind kind); // "fold-over", "flat", "step", ...
CheckKind checkOf(FindingKind kind);

// The unit of CheckFinding::size.
enum class SizeUnit {
    Steps8,  // 8-bit steps of output (value x 255)
    Slope,   // output 8-bit steps per input 8-bit step
    Degrees, // Oklab hue angle
    Entries  // a count of table entries
};
const char* toString(SizeUnit unit); // "8-bit steps", "steps per input step", "degrees", ...

// The input colours a finding concerns (input colours in the LUT's domain, as the file takes
// them: a file's 1D shaper is applied first where the region is given on its 3D table).
struct FindingRegion {
    enum class Type {
        None,
        Cells,       // cells of the 3D table
        Hue,         // an Oklab hue band of colours with some chroma
        ChannelRange // one input channel within [lo, hi] (1D tables)
    };
    Type type = Type::None;
    // Cells: indices r + (N - 1) (g + (N - 1) b) of the table's (N - 1)^3 cells, sorted, unique.
    std::vector<std::uint32_t> cells;
    int latticeSize = 0;
    glm::vec3 domainMin{0.0f}, domainMax{1.0f}; // the table's domain
    std::shared_ptr<const Lut1D> shaper;        // applied before the cell lookup, when set
    // Hue: Oklab hue within hueHalfWidth degrees of hueCentre, chroma >= minChroma (the input
    // taken as sRGB-encoded, mapped from the domain to [0, 1]).
    double hueCentre = 0.0, hueHalfWidth = 0.0, minChroma = 0.0;
    glm::vec3 inputMin{0.0f}, inputMax{1.0f}; // the file's input domain (hue regions)
    // ChannelRange: input channel `channel` within [lo, hi].
    int channel = 0;
    double lo = 0.0, hi = 0.0;

    bool contains(glm::vec3 input) const;
};

// One byte per pixel of image (RGB, alpha ignored): 1 where the pixel's colour is in region.
std::vector<std::uint8_t> regionMask(const FindingRegion& region, const ImageView& image,
                                     int nthreads = 0);

struct CheckFinding {
    FindingKind kind = FindingKind::FoldOver;
    CheckStatus severity = CheckStatus::Warn; // Warn or Fail
    int channel = -1;       // the output channel concerned (0 R, 1 G, 2 B), -1 = several or none
    std::string where;      // "along red", "on the grey axis", "yellows (hue 95-125)", ...
    glm::vec3 input{0.0f};  // the worst place: an input colour in the file's domain
    glm::vec3 output{0.0f}; // the LUT's output there
    glm::ivec3 cell{-1};    // the 3D table's cell holding it (-1 without a 3D table)
    double size = 0.0;      // in `unit`
    SizeUnit unit = SizeUnit::Steps8;
    double share = 0.0; // of the cube's volume, or of the picture's pixels (CheckReport::image)
    std::string detail; // more about it: "falls from 0.62 to 0.60", "levels 0.1 apart", ...
    FindingRegion region;

    // One line: "fold-over: output R falls 3.2 8-bit steps while input R rises, along red, at RGB
    // (0.61, 0.09, 0.09), 4.1% of the cube".
    std::string text(bool imageShare = false) const;
};

} // namespace lut
