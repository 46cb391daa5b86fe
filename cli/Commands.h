#pragma once
// Options structs and run functions of the lutkit subcommands. CLI11 parsing lives in main.cpp
// only (one translation unit); each cmd_*.cpp implements one run function and returns the exit
// code: 0 success, 1 bad input or failed operation, 2 bad usage.
#include <string>
#include <vector>

namespace lut::cli {

enum ExitCode { kExitOk = 0, kExitFailure = 1, kExitUsage = 2 };

} // namespace lut::cli
