#pragma once
// Options structs and run functions of the lutkit subcommands. CLI11 parsing lives in main.cpp
// only (one translation unit); each cmd_*.cpp implements one run function and returns the exit
// code: 0 success, 1 bad input or failed operation, 2 bad usage.
#include "lut/io/Layout.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lut::cli {

enum ExitCode { kExitOk = 0, kExitFailure = 1, kExitUsage = 2 };

// A bad option value found after parsing (exit code 2, like CLI11's own usage errors).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The layout an option names ("" = not given); throws UsageError naming the option.
std::optional<LutLayout> layoutOption(const std::string& option, const std::string& value);

} // namespace lut::cli
