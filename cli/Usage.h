// SPDX-License-Identifier: Apache-2.0
#pragma once
// Exit codes of lutkit (README "Exit codes") and the error for bad usage found after parsing.
#include <stdexcept>

namespace lut::cli {

// 130 = 128 + SIGINT, the shell's code for a command stopped by Ctrl-C, used for SIGTERM too.
enum ExitCode { kExitOk = 0, kExitFailure = 1, kExitUsage = 2, kExitInterrupted = 130 };

// A bad option value or combination found after parsing: exit code 2, like CLI11's own usage
// errors. Library failures are lut::Error (exit code 1).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace lut::cli
