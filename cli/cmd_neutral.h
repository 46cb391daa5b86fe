#pragma once
#include <string>

namespace lut::cli {

struct NeutralOptions {
    std::string output;
    std::string format; // output format name ("" = from the extension)
    std::string layout; // image layout
    int size = 0;       // 0 = default for the format (see defaultNeutralSize)
    int bitDepth = 0;
    std::string name; // nutexb name field
    std::string title;
};

// The lattice size `lutkit neutral` writes when --size is not given: the format's fixed size if
// it has one (nutexb: 16); 16 for LUT images (the 256x16 strip every engine expects; a Hald of
// level 4); 33 for every text/float LUT format (.cube, .3dl, .csp, .clf ... the size grading
// tools default to).
int defaultNeutralSize(const std::string& path, int formatFixedSize);

int runNeutral(const NeutralOptions& options);

} // namespace lut::cli
