// SPDX-License-Identifier: Apache-2.0
#pragma once
// What went wrong, and lutkit's exit code for it (README "Exit codes"), decided once, by the
// error's type (never its text): CommandLine maps every error a command throws through here.
#include <exception>

namespace lut::cli {

enum class ErrorKind {
    Usage,       // 2: the command line's UsageError; the library's RequestError (a request that
                 // cannot be) and ColorOptionError (a name the config lacks)
    Input,       // 1: bad input or a failed operation: lut::ParseError, LimitError, lut::Error
    Io,          // 1: lut::IoError, a read or write the system refused (a full disk...)
    Interrupted, // 130: InterruptedError, a write refused after SIGINT/SIGTERM
    Other,       // 1: any other exception
};

ErrorKind errorKind(const std::exception& e);
int exitCode(ErrorKind kind);

} // namespace lut::cli
