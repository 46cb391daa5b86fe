// SPDX-License-Identifier: Apache-2.0
// The nutexb byte codec; the byte layout is described in NutexbCodec.h (docs/specs/nutexb.md).
#include "nutexb/NutexbCodec.h"

#include "LutPrep.h"
#include "nutexb/BlockLinear.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Quantize.h"
#include "lut/io/InputFile.h"

#include <cstdio>
#include <cstring>

namespace lut::formats {
namespace nutexb {

namespace {

std::uint32_t u32At(std::string_view b, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
    return v;
}
std::uint16_t u16At(std::string_view b, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) |
                                      (static_cast<unsigned char>(b[at + 1]) << 8));
}
void putU32(std::string& s, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        s[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
}
void putU16(std::string& s, std::size_t at, std::uint16_t v) {
    s[at] = static_cast<char>(v & 0xFF);
    s[at + 1] = static_cast<char>(v >> 8);
}

std::string hex(std::uint32_t v, int digits = 4) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*x", digits, v);
    return buf;
}

// Names of the image-format codes the game uses, for errors (nutexb.md lists them).
std::string formatCodeName(std::uint32_t f) {
    const char* name = nullptr;
    switch (f) {
    case 0x0400:
        name = "R8G8B8A8_UNORM";
        break;
    case 0x0405:
        name = "R8G8B8A8_SRGB";
        break;
    case 0x0100:
        name = "R8";
        break;
    case 0x0434:
        name = "RGBA32F";
        break;
    case 0x0450:
        name = "B8G8R8A8_UNORM";
        break;
    case 0x0455:
        name = "B8G8R8A8_SRGB";
        break;
    case 0x0180:
        name = "BC4";
        break;
    case 0x0280:
        name = "BC5";
        break;
    case 0x04d7:
        name = "BC6";
        break;
    case 0x04e0:
        name = "BC7";
        break;
    default:
        if (f >= 0x0480 && f < 0x0490)
            name = "BC1";
        else if (f >= 0x0490 && f < 0x04a0)
            name = "BC2";
        else if (f >= 0x04a0 && f < 0x04b0)
            name = "BC3";
        else if (f >= 0x04e0 && f < 0x04f0)
            name = "BC7";
        break;
    }
    return hex(f) + " (" + (name ? name : "unknown") + ")";
}

[[noreturn]] void fail(const std::string& path, const std::string& field,
                       const std::string& message) {
    throw Error(path + ": nutexb " + field + ": " + message);
}

// Footer field offsets (relative to the footer start).
constexpr std::size_t kOffMagic = 0x00, kOffName = 0x04, kOffWidth = 0x44, kOffHeight = 0x48,
                      kOffDepth = 0x4C, kOffFormat = 0x50, kOffType = 0x54, kOffMips = 0x58,
                      kOffTiling = 0x5C, kOffLayers = 0x60, kOffDataSize = 0x64, kOffMagic2 = 0x68,
                      kOffVersion = 0x6C;
constexpr char kMagicXnt[4] = {' ', 'X', 'N', 'T'};
constexpr char kMagicXet[4] = {' ', 'X', 'E', 'T'};

std::string magicStr(std::string_view b, std::size_t at) {
    std::string s;
    for (std::size_t i = 0; i < 4; ++i) {
        char buf[4];
        std::snprintf(buf, sizeof buf, "%02x", static_cast<unsigned char>(b[at + i]));
        s += (i ? " " : "") + std::string(buf);
    }
    return s;
}

std::uint64_t expectedDataSize(const Header& h) {
    const TileGeometry g = tileGeometry(static_cast<int>(h.width), static_cast<int>(h.height),
                                        static_cast<int>(h.depth), kBytesPerTexel);
    return h.tiling == kTilingBlockLinear
               ? tiledSize(g)
               : static_cast<std::uint64_t>(h.width) * h.height * h.depth * kBytesPerTexel;
}

} // namespace

Header parseHeader(std::string_view b, const std::string& path) {
    if (b.size() < kMinFileSize)
        fail(path, "file size",
             "truncated: " + std::to_string(b.size()) + " bytes, expected at least " +
                 std::to_string(kMinFileSize) + " (0x40-byte mip table + 0x70-byte footer)");
    const std::size_t F = b.size() - kFooterSize;
    if (std::memcmp(b.data() + F + kOffMagic, kMagicXnt, 4) != 0)
        fail(path, "magic at footer+0x00",
             "found " + magicStr(b, F + kOffMagic) +
                 ", expected 20 58 4e 54 (\" XNT\"); not a nutexb file or truncated");
    if (std::memcmp(b.data() + F + kOffMagic2, kMagicXet, 4) != 0)
        fail(path, "magic at footer+0x68",
             "found " + magicStr(b, F + kOffMagic2) + ", expected 20 58 45 54 (\" XET\")");
    Header h;
    const char* nm = b.data() + F + kOffName;
    h.name.assign(nm, strnlen(nm, kNameSize));
    h.width = u32At(b, F + kOffWidth);
    h.height = u32At(b, F + kOffHeight);
    h.depth = u32At(b, F + kOffDepth);
    h.imageFormat = u32At(b, F + kOffFormat);
    h.textureType = u32At(b, F + kOffType);
    h.mipCount = u32At(b, F + kOffMips);
    h.tiling = u32At(b, F + kOffTiling);
    h.layerCount = u32At(b, F + kOffLayers);
    h.dataSize = u32At(b, F + kOffDataSize);
    h.versionMajor = u16At(b, F + kOffVersion);
    h.versionMinor = u16At(b, F + kOffVersion + 2);

    auto n = [](std::uint32_t v) { return std::to_string(v); };
    if (h.width == 0)
        fail(path, "width", "found 0, expected > 0");
    if (h.height == 0)
        fail(path, "height", "found 0, expected > 0");
    if (h.depth == 0)
        fail(path, "depth", "found 0, expected > 0");
    if (h.depth == 1)
        fail(path, "depth", "found 1, expected > 1 (a 2D texture, not a 3D LUT volume)");
    // A LUT volume is a cube: the field that disagrees with the two others is the bad one (a
    // corrupted width is reported as the width, not as a height that differs from it).
    if (h.width != h.height && h.height == h.depth)
        fail(path, "width",
             "found " + n(h.width) + ", expected " + n(h.height) +
                 " (equal to height and depth for a LUT)");
    if (h.height != h.width)
        fail(path, "height",
             "found " + n(h.height) + ", expected " + n(h.width) + " (equal to width for a LUT)");
    if (h.depth != h.width)
        fail(path, "depth",
             "found " + n(h.depth) + ", expected " + n(h.width) + " (equal to width for a LUT)");
    // Before anything is sized from these numbers: a LUT edge is 2..256.
    if (h.width < static_cast<std::uint32_t>(limits::kMin3DSize) ||
        h.width > static_cast<std::uint32_t>(limits::kMax3DSize))
        fail(path, "width",
             "found " + n(h.width) + ", expected a LUT size " + std::to_string(limits::kMin3DSize) +
                 ".." + std::to_string(limits::kMax3DSize));
    if (h.textureType != kTextureType3D)
        fail(path, "texture type",
             "found " + n(h.textureType) + ", expected 8 (3D)" +
                 (h.textureType == 4   ? "; 4 is 2D"
                  : h.textureType == 9 ? "; 9 is cube/array"
                                       : ""));
    if (h.layerCount != 1)
        fail(path, "layer count", "found " + n(h.layerCount) + ", expected 1");
    if (h.mipCount < 1 || h.mipCount > kMipTableSize / 4)
        fail(path, "mip count",
             "found " + n(h.mipCount) + ", expected 1.." + std::to_string(kMipTableSize / 4) +
                 " (1 for a LUT)");
    if (h.imageFormat != kFormatRgba8 && h.imageFormat != kFormatRgba8Srgb)
        fail(path, "image format",
             "found " + formatCodeName(h.imageFormat) +
                 ", expected 0x0400 (R8G8B8A8_UNORM) or 0x0405 (R8G8B8A8_SRGB)");
    if (h.tiling != kTilingBlockLinear && h.tiling != kTilingLinear)
        fail(path, "tiling",
             "found " + hex(h.tiling) + ", expected 0x1000 (block-linear) or 0x0000 (linear)");

    const std::uint64_t mip0 = expectedDataSize(h);
    const std::uint64_t tableBytes = kMipTableSize * h.layerCount;
    const std::uint64_t room = b.size() - kFooterSize - tableBytes; // bytes before the mip table
    if (h.mipCount == 1 ? h.dataSize != mip0 : h.dataSize < mip0)
        fail(path, "data size",
             "found " + n(h.dataSize) + ", expected " + std::to_string(mip0) + " (" +
                 (h.tiling == kTilingBlockLinear ? "block-linear tiled" : "linear") + " " +
                 n(h.width) + "x" + n(h.height) + "x" + n(h.depth) + " RGBA8" +
                 (h.mipCount == 1 ? "" : ", mip 0 alone") + ")");
    if (h.dataSize > room)
        fail(path, "data size",
             "found " + n(h.dataSize) + ", past the mip table: the file has room for " +
                 std::to_string(room) + " bytes of data (file truncated?)");
    const std::uint64_t expectedFile =
        static_cast<std::uint64_t>(h.dataSize) + tableBytes + kFooterSize;
    if (b.size() != expectedFile)
        fail(path, "file size",
             "found " + std::to_string(b.size()) + " bytes, expected " +
                 std::to_string(expectedFile) + " (data size " + n(h.dataSize) +
                 " + 0x40 mip table + 0x70 footer)");
    return h;
}

LutFile readBytes(std::string_view b, const std::string& path) {
    using S = Diagnostic::Severity;
    const Header h = parseHeader(b, path);
    const int n = static_cast<int>(h.width);
    const std::size_t untiledBytes = static_cast<std::size_t>(n) * n * n * kBytesPerTexel;
    LutFile file;
    file.format = "nutexb";
    file.purpose = LutPurpose::Smash; // the game applies it: the game's LUT by its format
    file.dialect = h.tiling == kTilingBlockLinear ? "tiled" : "linear";
    file.sourceBitDepth = 8;

    const std::size_t tableAt = h.dataSize;
    const std::uint32_t mipEntry = u32At(b, tableAt);
    if (mipEntry != untiledBytes)
        file.diagnostics.push_back(makeDiagnostic(
            S::Warning, path,
            "nutexb mip table[0]: found " + std::to_string(mipEntry) + ", expected " +
                std::to_string(untiledBytes) + " (the untiled size of mip 0); ignored"));
    if (h.mipCount > 1)
        file.diagnostics.push_back(makeDiagnostic(S::Info, path,
                                                  "nutexb: " + std::to_string(h.mipCount - 1) +
                                                      " mip level(s) after the first ignored"));
    if (h.versionMajor != kVersionMajor || h.versionMinor != kVersionMinor)
        file.diagnostics.push_back(
            makeDiagnostic(S::Info, path,
                           "nutexb version: found " + std::to_string(h.versionMajor) + "." +
                               std::to_string(h.versionMinor) + ", expected 1.2"));
    if (h.imageFormat == kFormatRgba8Srgb)
        file.diagnostics.push_back(makeDiagnostic(S::Info, path,
                                                  "nutexb image format 0x0405 (sRGB): the stored "
                                                  "bytes are taken as the values, as for 0x0400"));

    const auto* data = reinterpret_cast<const std::uint8_t*>(b.data());
    std::vector<std::uint8_t> linearStore;
    const std::uint8_t* linear = data;
    const std::string volume = std::to_string(n) + "^3";
    if (h.tiling == kTilingBlockLinear) {
        allocating(path, "untiling the " + volume + " volume", untiledBytes,
                   [&] { linearStore = untile(tileGeometry(n, n, n, kBytesPerTexel), data); });
        linear = linearStore.data();
    }
    const std::uint64_t tableBytes = static_cast<std::uint64_t>(n) * n * n * sizeof(glm::vec3);
    Lut3D lut = allocating(path, "the " + volume + " table", tableBytes, [&] { return Lut3D(n); });
    std::size_t alphaOff = 0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::uint8_t* t = linear + lut.index(x, y, z) * kBytesPerTexel;
                lut.at(x, y, z) = glm::vec3(fromUnorm8(t[0]), fromUnorm8(t[1]), fromUnorm8(t[2]));
                if (t[3] != 255)
                    ++alphaOff;
            }
    if (alphaOff)
        file.diagnostics.push_back(makeDiagnostic(S::Info, path,
                                                  "nutexb: alpha ignored (" +
                                                      std::to_string(alphaOff) +
                                                      " texels have alpha other than 255)"));
    lut.setTitle(h.name);
    file.cube = std::move(lut);
    return file;
}

std::string writeBytes(const Lut3D& lut, const std::string& nameIn, bool tiled,
                       std::size_t* clampedCount) {
    const std::string name = nameIn.empty() ? std::string(kDefaultName) : nameIn;
    if (name.size() >= kNameSize)
        throw Error("nutexb name '" + name + "' is " + std::to_string(name.size()) +
                    " bytes, at most " + std::to_string(kNameSize - 1) + " fit");
    if (name.find('\0') != std::string::npos)
        throw Error("nutexb name contains a NUL byte");
    const int n = lut.size();
    if (n < 2)
        throw Error("nutexb: cannot write an empty LUT");
    const std::size_t untiledBytes = static_cast<std::size_t>(n) * n * n * kBytesPerTexel;
    std::vector<std::uint8_t> linear(untiledBytes);
    std::size_t clamped = 0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::vec3 v = lut.at(x, y, z);
                std::uint8_t* t = linear.data() + lut.index(x, y, z) * kBytesPerTexel;
                for (int c = 0; c < 3; ++c) {
                    if (!(v[c] >= 0.0f && v[c] <= 1.0f))
                        ++clamped;
                    t[c] = toUnorm8(v[c]);
                }
                t[3] = 255;
            }
    if (clampedCount)
        *clampedCount = clamped;
    std::vector<std::uint8_t> tiledStore;
    const std::vector<std::uint8_t>* data = &linear;
    if (tiled) {
        tiledStore = tile(tileGeometry(n, n, n, kBytesPerTexel), linear.data());
        data = &tiledStore;
    }
    const std::size_t dataSize = data->size();
    if (dataSize > 0xFFFFFFFFull)
        throw Error("nutexb: data too large for the 32-bit size field");
    std::string out(dataSize + kMipTableSize + kFooterSize, '\0');
    std::memcpy(out.data(), data->data(), dataSize);
    putU32(out, dataSize, static_cast<std::uint32_t>(untiledBytes));
    const std::size_t F = dataSize + kMipTableSize;
    std::memcpy(out.data() + F + kOffMagic, kMagicXnt, 4);
    std::memcpy(out.data() + F + kOffName, name.data(), name.size());
    putU32(out, F + kOffWidth, static_cast<std::uint32_t>(n));
    putU32(out, F + kOffHeight, static_cast<std::uint32_t>(n));
    putU32(out, F + kOffDepth, static_cast<std::uint32_t>(n));
    putU32(out, F + kOffFormat, kFormatRgba8);
    putU32(out, F + kOffType, kTextureType3D);
    putU32(out, F + kOffMips, 1);
    putU32(out, F + kOffTiling, tiled ? kTilingBlockLinear : kTilingLinear);
    putU32(out, F + kOffLayers, 1);
    putU32(out, F + kOffDataSize, static_cast<std::uint32_t>(dataSize));
    std::memcpy(out.data() + F + kOffMagic2, kMagicXet, 4);
    putU16(out, F + kOffVersion, kVersionMajor);
    putU16(out, F + kOffVersion + 2, kVersionMinor);
    return out;
}

std::uint64_t maxFileSize() {
    const TileGeometry g =
        tileGeometry(limits::kMax3DSize, limits::kMax3DSize, limits::kMax3DSize, kBytesPerTexel);
    return tiledSize(g) + kMipTableSize + kFooterSize;
}

} // namespace nutexb

} // namespace lut::formats
