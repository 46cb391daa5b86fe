#pragma once
// lutkit apply --lut LUT IN OUT (or IN... -o DIR): a LUT on the stored pixel values of images.
#include "Notes.h"

#include "lut/formats/ColorTransform.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Layout.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct ApplyOptions {
    std::string lut;                    // LUT file (any readable format)
    std::optional<LutLayout> lutLayout; // the LUT's layout when it is an image (default: detected)
    std::vector<std::string> inputs;    // IN OUT, or with outputDir: files and/or folders
    std::string outputDir;              // -o DIR: batch mode
    Interpolation interp = Interpolation::Tetrahedral;
    int threads = 0;          // 0 = all cores
    formats::ColorSpec color; // --config, --from, --to ...: the LUT runs in its own space
    Verbosity verbosity;
};

// Applies the LUT to the stored pixel values (no colour conversion unless --from/--to... ask for
// one: then OpenColorIO converts into the LUT's space and out of it, lut/formats/
// ColorTransform.h), alpha kept, output bit depth = the input's, rounded to nearest -- what
// Photoshop's Color Lookup does. Values outside the LUT's domain are counted and reported.
// Batch: Batch.h.
int runApply(const ApplyOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupApply(CLI::App& app, std::function<void(const ApplyOptions&)> onParsed);

} // namespace lut::cli
