#pragma once
#include <string>

namespace lut::cli {

struct ConvertOptions {
    std::string input;
    std::string output;
    std::string format;   // output format name ("" = from the extension)
    std::string inFormat; // input format name ("" = from the extension)
    std::string layout;   // output image layout
    std::string inLayout; // input image layout
    int size = 0;         // output lattice size (0 = the format's fixed size, else the input's)
    std::string interp = "tetrahedral";
    int bitDepth = 0; // image output bit depth (0 = the format's default)
    bool dither = false;
    std::string name; // nutexb name field
    bool json = false;
};

// Reads input, resamples when the output needs another size, writes output atomically, reads it
// back and reports the resampling and storage (quantisation) errors separately, with timings.
int runConvert(const ConvertOptions& options);

} // namespace lut::cli
