// SPDX-License-Identifier: Apache-2.0
#pragma once
// Baking colour conversions into LUT files: what ociobakelut does, and more.
//
// What is baked (exactly one of):
//  - a conversion of an OpenColorIO config: inputSpace -> outputSpace (with looks), or to a
//    display's view;
//  - LUT files of any format OpenColorIO reads, applied in order (ociobakelut --lut/--invlut,
//    --cccid for .ccc/.cdl), through OCIO's WHOLE processor, never an inner table's lattice;
//  - a LUT file read by lutkit with colour conversions around it (lutkit convert --from/--to:
//    lut/formats/ColorTransform.h's plan), so it runs in the space it was made for.
//
// How: the function is sampled at every lattice point of a cubeSize^3 table; when its input is
// HDR or log a 1D shaper comes first (--shaperspace S: OCIO's input -> S; log2: the input space's
// lg2 allocation, or -6.5..+6.5 stops around 0.18; an input range: a straight shaper) and the
// lattice lies in the shaper's coordinates. Formats that hold a shaper (.cube Resolve, .clf, .ctf,
// .csp) keep it; for the others the table covers [0,1] and the loss is said. A conversion that
// mixes no channels becomes a 1D table of shaperSize entries instead (where the format holds one
// and no --cubesize asks for a lattice). The file is written
// through the format registry (any writable format, or ociobakelut's format names), read back,
// and compared with the function on a probe grid between the lattice points (evenly spread in the
// shaper's coordinates): that error, max and mean, is reported with the time each step took.
#include "lut/ErrorStats.h"
#include "lut/formats/ColorTransform.h"
#include "lut/io/FormatOptions.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lut::formats {

enum class ShaperChoice {
    Auto, // a log2 shaper when the input is scene-linear and the format holds a shaper, an input
          // range when the source has one, else none
    None, // the table covers [0,1]
    Log2
};

struct BakeFileStep {
    std::string path;
    std::string cccid;    // for .ccc/.cdl files holding several corrections
    bool inverse = false; // ociobakelut --invlut
};

struct BakeOptions {
    // A conversion of a config.
    std::string config; // "" = $OCIO, else lutkit's own
    std::string inputSpace, outputSpace, looks, display, view;
    // Or LUT files through OpenColorIO (config-free).
    std::vector<BakeFileStep> files;
    // Or a LUT read by lutkit, with the conversions of `around` on either side.
    std::string lut;
    std::string lutFormat; // "" = by extension
    FormatOptions lutRead; // e.g. the layout of a LUT image
    ColorSpec around;      // around.config is ignored: `config` is used

    std::string shaperSpace; // a colour space of the config to shape the input with
    ShaperChoice shaper = ShaperChoice::Auto;
    int shaperSize = 0; // shaper (or 1D table) entries; 0 = kDefaultShaperSize
    // 0 = the format's fixed size, else ociobakelut's for the format (OpenColorIO 2.1's bakers):
    // flame 17, lustre 33, cinespace, truelight and iridas_cube 32, resolve_cube, iridas_itx,
    // houdini, clf and ctf 64; 33 for a .cube named without a dialect, .spi3d and lutkit's own
    // formats (or a 1D table: see above).
    int cubeSize = 0;
    std::string format; // output format name or alias ("" = by the output's extension)
    FormatOptions write;
    int nthreads = 0;
};

constexpr int kDefaultBakeSize = 33;
constexpr int kDefaultShaperSize = 4096;

struct BakeReport {
    std::string what;       // "ACEScg -> sRGB", "grade.cube, 2 files ..."
    std::string configUsed; // ConfigLocation::describe(), "" for config-free bakes
    std::string outputFormat;
    int cubeSize = 0;   // 0 = a 1D table only (shaperSize entries, described by `shaper`)
    int shaperSize = 0; // 0 = no shaper
    std::string shaper; // "none", "log2 -8.97..4.03 stops", "colour space 'ACEScct'" ...
    glm::vec3 domainMin{0.0f}, domainMax{1.0f}; // input range the table covers
    ErrorStats error; // the file as read back against the baked function (error.seconds: the
                      // measurement)
    bool measuredFile = false; // false: the written file could not be read back (then error is
                               // the table in memory)
    std::string readBackError;
    Diagnostics diagnostics;
    double sampleSeconds = 0.0, writeSeconds = 0.0, totalSeconds = 0.0;
};

// Throws ColorOptionError (bad usage: unknown names, no or several sources, a shaper space with
// channel crosstalk), lut::Error (unreadable files or config, a failed write; the old output is
// left as it was). Never writes over an input.
BakeReport bake(const std::string& output, const BakeOptions& options);

} // namespace lut::formats
