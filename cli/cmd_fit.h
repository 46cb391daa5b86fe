#pragma once
// lutkit fit BEFORE AFTER OUT: fit a 3D LUT to a before/after image pair.
#include <string>

namespace lut::cli {

struct FitOptions {
    std::string before;
    std::string after;
    std::string output;
    int size = 33;
    double smoothness = 1.0;
    bool noRobust = false;
    std::string format;
    std::string layout;
};

int runFit(const FitOptions& options);

} // namespace lut::cli
