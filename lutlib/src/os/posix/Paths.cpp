// SPDX-License-Identifier: Apache-2.0
// lut/os/Paths.h on POSIX: paths are bytes, and UTF-8 by convention.
#include "lut/os/Paths.h"

#include "lut/os/Files.h"

namespace lut::os {

std::filesystem::path toPath(const std::string& utf8) {
    return std::filesystem::path(utf8);
}

std::string fromPath(const std::filesystem::path& path) {
    return path.string();
}

const char* pathSeparators() {
    return "/";
}

bool isPathSeparator(char c) {
    return c == '/';
}

std::string executablePath() {
    return linkTarget("/proc/self/exe");
}

} // namespace lut::os
