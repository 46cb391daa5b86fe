// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers shared by the robustness tests: writing crafted files and stripping the test folder
// from error messages so exact texts can be asserted.
#include "TestSupport.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace lut::robust {

inline void writeBytes(const std::string& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

using lut::test::fileBytes;

// Replaces every occurrence of dir + "/" in text by "" (messages name the full path).
inline std::string stripDir(std::string text, const std::string& dir) {
    const std::string prefix = dir + "/";
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;)
        text.erase(at, prefix.size());
    return text;
}

// Files in dir (names only), sorted, hidden ones included: temporary files must not survive.
inline std::vector<std::string> listDir(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A neutral .cube text of edge n (exact decimal values are irrelevant to these tests).
inline std::string neutralCube(int n, const std::string& header = {}) {
    std::string s = header + "LUT_3D_SIZE " + std::to_string(n) + "\n";
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                s += std::to_string(r / double(n - 1)) + " " + std::to_string(g / double(n - 1)) +
                     " " + std::to_string(b / double(n - 1)) + "\n";
    return s;
}

// nutexb footer fields (nutexb.md), for crafting malformed volumes byte by byte.
struct NutexbFields {
    std::uint32_t width = 2, height = 2, depth = 2, format = 0x0400, type = 8, mips = 1,
                  tiling = 0x1000, layers = 1, dataSize = 1024;
    const char* magic1 = " XNT";
    const char* magic2 = " XET";
};

inline void putU32(std::string& s, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        s[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

// data bytes + 0x40 mip table + 0x70 footer.
inline std::string nutexbFile(const NutexbFields& f, std::size_t dataBytes) {
    std::string s(dataBytes + 0x40 + 0x70, '\0');
    putU32(s, dataBytes, 32); // mip table[0]: untiled size of 2^3 RGBA8
    const std::size_t F = dataBytes + 0x40;
    std::memcpy(s.data() + F, f.magic1, 4);
    std::memcpy(s.data() + F + 4, "color_grading_lut", 17);
    const std::uint32_t v[] = {f.width, f.height, f.depth,  f.format,  f.type,
                               f.mips,  f.tiling, f.layers, f.dataSize};
    for (int i = 0; i < 9; ++i)
        putU32(s, F + 0x44 + 4 * static_cast<std::size_t>(i), v[i]);
    std::memcpy(s.data() + F + 0x68, f.magic2, 4);
    s[F + 0x6C] = 1;
    s[F + 0x6E] = 2;
    return s;
}

inline std::string be32(std::uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG chunk as the PNG specification (section 5.3) lays it out: the data's length, big-endian,
// the type, the data, and the CRC-32 of type and data (ISO 3309's polynomial, bit by bit).
inline std::string pngChunk(const std::string& type, const std::string& data) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char ch : type + data) {
        c ^= ch;
        for (int k = 0; k < 8; ++k)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(~c);
}

// A PNG whose header claims width x height, 8-bit, of this colour type (2 RGB, 6 RGBA), with one
// IDAT chunk holding `idat` (libpng stops reading the header at the first IDAT).
inline std::string craftedPng(std::uint32_t width, std::uint32_t height, char colourType,
                              const std::string& idat) {
    return std::string("\x89PNG\r\n\x1a\n", 8) +
           pngChunk("IHDR", be32(width) + be32(height) + std::string{'\x08', colourType} +
                                std::string(3, '\0')) +
           pngChunk("IDAT", idat) + pngChunk("IEND", "");
}

} // namespace lut::robust
