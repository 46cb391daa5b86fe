// SPDX-License-Identifier: Apache-2.0
// lut/os/Paths.h on Windows: UTF-8 <-> the UTF-16 std::filesystem::path holds.
#include "lut/os/Paths.h"

#include "Wide.h"

namespace lut::os {

std::filesystem::path toPath(const std::string& utf8) {
    return std::filesystem::path(windows::widen(utf8));
}

std::string fromPath(const std::filesystem::path& path) {
    return windows::narrow(path.native());
}

const char* pathSeparators() {
    return "/\\";
}

bool isPathSeparator(char c) {
    return c == '/' || c == '\\';
}

std::string executablePath() {
    std::wstring buf(MAX_PATH, L'\0');
    for (;;) {
        const DWORD n = ::GetModuleFileNameW(nullptr, buf.data(), static_cast<DWORD>(buf.size()));
        if (n == 0)
            return {};
        if (n < buf.size())
            return windows::narrow(buf.data(), n);
        if (buf.size() >= 32768)
            return {};
        buf.resize(buf.size() * 2);
    }
}

} // namespace lut::os
