// SPDX-License-Identifier: Apache-2.0
// File-name rules: the running program's folder, a path's extension, a free name; see
// lut/io/FileNames.h.
#include "lut/io/FileNames.h"

#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <algorithm>
#include <cctype>

namespace lut {

std::string executableDir() {
    const std::string p = os::executablePath();
    const auto slash = p.find_last_of(os::pathSeparators());
    return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

std::string extensionOf(const std::string& path) {
    const auto slash = path.find_last_of(os::pathSeparators());
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c != 0x7f) {
            out += ch;
            continue;
        }
        switch (c) {
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default: {
            static const char* const kHex = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
        }
    }
    return out;
}

std::string firstFreeName(const std::string& path) {
    os::FileInfo info;
    if (os::linkInfo(path, info) != 0)
        return path;
    const std::size_t stemEnd = path.size() - extensionOf(path).size();
    const std::string stem = path.substr(0, stemEnd);
    for (int n = 2; n < 10000; ++n) {
        std::string candidate = stem + " (" + std::to_string(n) + ")" + path.substr(stemEnd);
        if (os::linkInfo(candidate, info) != 0)
            return candidate;
    }
    return path; // ten thousand copies: the write refuses the name taken
}

} // namespace lut
