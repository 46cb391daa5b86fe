#pragma once
#include <string>
#include <vector>

namespace lut::cli {

struct PreviewOptions {
    std::vector<std::string> inputs; // IN OUT, or with outputDir: files and/or folders
    std::string outputDir;           // -o DIR: batch mode
    std::string lut;                 // grading LUT (default neutral)
    std::string preset = "smash";    // smash | pilot | lecture | none
    bool noBloom = false;
    std::string interp = "trilinear"; // the game samples with hardware trilinear
    bool fromScreenshot = false;      // input went through the game's grading already
    std::string originalLut;          // the LUT the screenshot was graded with (default neutral)
    std::vector<std::string> stageSettings; // "stage.param=value"
    std::vector<std::string> enable;
    std::vector<std::string> disable;
    unsigned long long frame = 0; // frame index (film grain)
    int bitDepth = 0;             // 0 = the input's (float input: 32 for .exr/.hdr, else 16/8)
    int threads = 0;
    bool verbose = false;
    bool listStages = false;
    bool quiet = false;
};

// Renders images through the preview pipeline (lut/pipeline/Pipeline.h) as the game would show
// them, writing display-encoded pixels.
int runPreview(const PreviewOptions& options);

} // namespace lut::cli
