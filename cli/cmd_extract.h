#pragma once
// lutkit extract EDITED OUT: find the patch in an edited screenshot and write the LUT it shows.
#include <string>

namespace lut::cli {

struct ExtractOptions {
    std::string input;
    std::string output;
    std::string target = "raw"; // raw | smash
    std::string originalLut;    // smash: the stage's LUT the screenshot was taken with
    int size = 0;               // output size (0: raw = patch size, smash/nutexb = 16)
    std::string format;         // output format name ("" = by extension)
    std::string layout;         // output layout for LUT images
};

int runExtract(const ExtractOptions& options);

} // namespace lut::cli
