// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit apply --lut LUT IN... -o OUT: a LUT on the stored pixel values of images, streamed in
// chunks in the file's own type (lut/formats/ApplyImage.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/formats/ColorTransform.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Layout.h"
#include "lut/ops/Strength.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct ApplyOptions {
    std::string lut;                    // LUT file (any readable format; - = standard input)
    std::optional<LutLayout> lutLayout; // the LUT's layout when it is an image (default: detected)
    std::string lutTarget;              // what the LUT is for ("" = its tag, else raw)
    std::vector<std::string> inputs;    // files, folders, frame patterns, or -
    OutputOptions output;               // -o FILE | DIR/ | PATTERN | -, -y, -n
    std::string frames;                 // --frames 1-100 (with a frame pattern)
    std::string inFormat;               // --in-format: the image format of standard input
    std::string format;                 // --format: the image format written to standard output
    int bitDepth = 0;                   // 0 = the input's type
    std::string compression;            // "" = the input's (EXR, TIFF)
    std::string maxMemory;              // --max-memory (default half the RAM)
    int subimage = -1;                  // --subimage: one image of a file holding several
    Interpolation interp = Interpolation::Tetrahedral;
    int threads = 0;          // 0 = all cores
    formats::ColorSpec color; // --config, --from, --to ...: the LUT runs in its own space
    StrengthOptions strength; // the LUT blended with neutral first
    Verbosity verbosity;
};

// Applies the LUT to the stored pixel values, alpha, data type, compression and metadata kept --
// what Photoshop's Color Lookup does, file by file. No colour conversion unless --from/--to...
// ask for one: then OpenColorIO converts into the LUT's space and out of it
// (lut/formats/ColorTransform.h). Values outside the LUT's domain are counted and reported.
int runApply(const ApplyOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupApply(CLI::App& app, std::function<void(const ApplyOptions&)> onParsed);

} // namespace lut::cli
