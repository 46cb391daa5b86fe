// SPDX-License-Identifier: Apache-2.0
// lut/os/Console.h on POSIX: the arguments are bytes already, the streams have no text mode, and
// a terminal belongs to whoever started the program.
#include "lut/os/Console.h"

#include <cstdio>
#include <unistd.h>

namespace lut::os {

std::vector<std::string> programArguments(int argc, const char* const* argv) {
    return std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc);
}

void prepareStandardStreams() {}

bool isTerminal(int fd) {
    return ::isatty(fd) == 1;
}

bool terminalTakesEscapes(int fd) {
    return isTerminal(fd);
}

bool consoleIsOwnWindow() {
    return false;
}

void waitForKey(const std::string& prompt) {
    std::fputs(prompt.c_str(), stderr);
    std::fflush(stderr);
    for (int c = std::getchar(); c != EOF && c != '\n'; c = std::getchar()) {
    }
}

} // namespace lut::os
