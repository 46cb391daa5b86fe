#pragma once
#include <string>

namespace lut::cli {

struct InfoOptions {
    std::string input;
    std::string format; // input format name ("" = from the extension)
    std::string layout; // image layout
    int size = 0;       // lattice size when sampling foreign (OpenColorIO) formats
    bool json = false;
};

// "near" neutral: every entry within half an 8-bit step of the identity, so an 8-bit store of it
// is exactly the 8-bit neutral.
constexpr double kNearNeutralTolerance = 0.5 / 255.0;
constexpr double kExactNeutralTolerance = 1e-6;

int runInfo(const InfoOptions& options);

} // namespace lut::cli
