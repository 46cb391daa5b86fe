// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit convert IN OUT: any readable LUT file to any writable one, saying what it cost
// (lut::formats::convertLut does the work; this prints its report as text or JSON).
#include "Notes.h"
#include "Outputs.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/formats/ColorTransform.h"
#include "lut/formats/Convert.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Layout.h"
#include "lut/ops/Strength.h"

#include <functional>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct ConvertOptions {
    std::string input;
    std::string output;
    std::string format;                // output format name ("" = from the extension)
    std::string inFormat;              // input format name ("" = from the extension)
    std::optional<LutLayout> layout;   // output image layout
    std::optional<LutLayout> inLayout; // input image layout
    std::string cccid;                 // the correction of a .ccc/.cdl input (id or index)
    int size = 0;  // output lattice size (0 = the format's fixed size, else the input's)
    int level = 0; // Hald level L: size L^2, layout hald
    Interpolation interp = Interpolation::Tetrahedral;
    int bitDepth = 0; // image output bit depth (0 = the format's default)
    bool dither = false;
    std::string name; // nutexb name field
    bool json = false;
    OutputOptions overwrite; // -o (or the positional OUT), -y, -n
    // What the output is for (raw | smash); "" = smash for a .nutexb output, else what IN is
    // for. An edit (raw) to smash: OUT is the game's LUT that shows it; the game's LUT to raw:
    // OUT is the edit it makes of the game's picture (lut/formats/Convert.h).
    std::string target;
    std::string inTarget;    // what IN is for ("" = what the file says, else raw)
    std::string originalLut; // smash: the stage's LUT (default neutral)
    std::string screenshot;  // smash: the colours that occur (default: an input grid)
    bool refine = false;     // smash: write the least-squares refinement
    // --config, --from, --to ...: the LUT baked with colour conversions around it
    // (lut/formats/Bake.h), e.g. a display LUT made for sRGB turned into one for ACEScg input.
    formats::ColorSpec color;
    int shaperSize = 0;
    StrengthOptions strength; // --strength, --luma-strength, --chroma-strength
    Verbosity verbosity;
};

int runConvert(const ConvertOptions& options);
// A folder IN (or a folder output): every LUT file in it, files in parallel as apply does
// images, each converted under its own name into the output folder as --format (default
// nutexb: the game's LUT, each with its in-game error) (ConvertBatch.cpp).
bool isConvertBatch(const ConvertOptions& options);
int runConvertBatch(const ConvertOptions& options);

// --original-lut and --screenshot, read once and held while the conversions run: `into`'s
// purpose options point at them, measured, refined as --refine says (Convert.cpp).
struct PurposeInputs {
    Lut3D stage;
    Image shot;
    ImageView shotView;
};
void preparePurposeInputs(const ConvertOptions& options, PurposeInputs& held,
                          formats::ConvertOptions& into);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupConvert(CLI::App& app, std::function<void(const ConvertOptions&)> onParsed);

} // namespace lut::cli
