// SPDX-License-Identifier: Apache-2.0
#pragma once
// Paths are UTF-8 std::strings everywhere in lutkit; std::filesystem::path is built from and read
// back to them here only. On Windows a std::filesystem::path built from a char string reads it in
// the C library's locale, not as UTF-8 (a name such as "été.cube" would not be found), so these
// convert through UTF-16 explicitly; on POSIX they are the plain constructor and string().
#include <filesystem>
#include <string>

namespace lut::os {

std::filesystem::path toPath(const std::string& utf8);
std::string fromPath(const std::filesystem::path& path);

// The characters that separate a path's folders: "/" on POSIX, "/\\" on Windows (with the
// drive's ':' handled by std::filesystem).
const char* pathSeparators();
bool isPathSeparator(char c);

// The running program's own file (/proc/self/exe, GetModuleFileNameW), "" when it cannot be told.
std::string executablePath();

} // namespace lut::os
