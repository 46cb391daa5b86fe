// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit preview IN... -o OUT: images as the game would show them, through the
// post-processing chain (lut/pipeline/Pipeline.h) with a LUT, written display-encoded.
#include "Notes.h"
#include "Outputs.h"

#include "lut/formats/ColorTransform.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Layout.h"
#include "lut/ops/Strength.h"
#include "lut/pipeline/Pipeline.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct PreviewOptions {
    std::vector<std::string> inputs;    // files, folders, frame patterns, or -
    OutputOptions output;               // -o FILE | DIR/ | PATTERN | -, -y, -n
    std::string frames;                 // --frames 1-100 (with a frame pattern)
    std::string inFormat;               // --in-format: the image format of standard input
    std::string format;                 // --format: the image format written to standard output
    std::string maxMemory;              // --max-memory (default half the RAM)
    int subimage = -1;                  // --subimage: one image of a file holding several
    std::string lut;                    // grading LUT (default neutral)
    std::optional<LutLayout> lutLayout; // the LUT's layout when it is an image
    std::string lutTarget;              // what the LUT is for ("" = its tag, else raw)
    StrengthOptions strength;           // --lut blended with neutral first
    Preset preset = Preset::Smash;      // smash | filmic | cinematic | none
    bool noBloom = false;
    Interpolation interp = Interpolation::Trilinear; // the game samples with hardware trilinear
    bool fromScreenshot = false;            // inputs are screenshots (default for integer files)
    bool scene = false;                     // inputs are linear scenes (default for float files)
    std::string originalLut;                // the LUT the screenshot was graded with (neutral)
    std::vector<std::string> stageSettings; // "stage.param=value"
    std::vector<std::string> enable;
    std::vector<std::string> disable;
    unsigned long long frame = 0; // frame index (film grain)
    int bitDepth = 0;             // 0 = the input's (float input: 32 for .exr/.hdr, else 16/8)
    int threads = 0;
    bool listStages = false;
    // --config, --from, --look, --to: the input converted to sRGB before the pipeline, the
    // output from sRGB after it (lut/formats/ColorTransform.h, planPreviewColor).
    formats::ColorSpec color;
    Verbosity verbosity; // -v: the stages that ran and their time
};

int runPreview(const PreviewOptions& options);

// The stages of a pipeline with every parameter, its value and range (--list-stages).
std::string stageList(const Pipeline& pipeline);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupPreview(CLI::App& app, std::function<void(const PreviewOptions&)> onParsed);

} // namespace lut::cli
