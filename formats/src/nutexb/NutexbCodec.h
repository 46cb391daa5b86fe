// SPDX-License-Identifier: Apache-2.0
#pragma once
// The nutexb byte codec (docs/specs/nutexb.md): the footer, reading a whole file's bytes into a
// LutFile and writing a Lut3D as bytes. Internal to formats/; tests and fuzzers reach it through
// the lutkit::formats_internal CMake target. The public face is lut/formats/Nutexb.h.
//
// No header: the file is [image data][0x40-byte mip-size table per layer][0x70-byte footer] and a
// reader works backward from the end. The footer holds " XNT", a 64-byte name, width, height,
// depth, image format (0x0400 RGBA8 UNORM, 0x0405 its sRGB twin with the same bytes), texture
// type (8 = 3D), mip count, tiling (0x1000 block-linear, 0 linear rows), layer count, data size,
// " XET" and version 1.2. Texel (x, y, z) = (r, g, b) holds the entry as 8-bit UNORM, alpha 255.
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/formats/Nutexb.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace lut::formats::nutexb {

// Format constants, in one place.
constexpr std::size_t kFooterSize = 0x70;
constexpr std::size_t kMipTableSize = 0x40;                       // per layer
constexpr std::size_t kMinFileSize = kMipTableSize + kFooterSize; // 0xB0
constexpr std::size_t kNameSize = 64;
constexpr std::uint32_t kFormatRgba8 = 0x0400;
constexpr std::uint32_t kFormatRgba8Srgb = 0x0405;
constexpr std::uint32_t kTextureType3D = 8;
constexpr std::uint32_t kTilingBlockLinear = 0x1000;
constexpr std::uint32_t kTilingLinear = 0;
constexpr std::uint16_t kVersionMajor = 1;
constexpr std::uint16_t kVersionMinor = 2;
constexpr int kBytesPerTexel = 4; // RGBA8

// What the footer says.
struct Header {
    std::string name;
    std::uint32_t width = 0, height = 0, depth = 0;
    std::uint32_t imageFormat = 0, textureType = 0, mipCount = 0, tiling = 0, layerCount = 0;
    std::uint32_t dataSize = 0;
    std::uint16_t versionMajor = 0, versionMinor = 0;
};
// Parses and checks the footer and mip table of a whole file's bytes; throws lut::Error naming
// `path` and the field (value found and expected) for any departure nutexb.md forbids. Every size
// is checked against the bytes the file holds before anything is allocated.
Header parseHeader(std::string_view bytes, const std::string& path);
// Reads a whole file held in memory. Entry = byte/255, alpha ignored (diagnostic if not 255).
LutFile readBytes(std::string_view bytes, const std::string& path);
// Writes an RGBA8 volume of lut's own size (the caller resamples); name "" = color_grading_lut.
// tiled = block-linear (0x1000), else linear rows. clampedCount (optional) receives the number
// of channel values outside [0,1] that were clamped.
std::string writeBytes(const Lut3D& lut, const std::string& name, bool tiled,
                       std::size_t* clampedCount = nullptr);

// The largest file a legal nutexb LUT can be: a 256^3 block-linear volume, its mip table and
// footer. Readers refuse bigger files before reading them.
std::uint64_t maxFileSize();

} // namespace lut::formats::nutexb
