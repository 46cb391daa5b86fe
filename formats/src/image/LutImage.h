// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: LUT images shared by StripFormat.cpp ("strip": pilot, unity, smush and, when asked,
// hald) and HaldFormat.cpp ("hald").
#include "lut/formats/Hald.h"
#include "lut/io/Format.h"
#include "lut/io/Layout.h"

#include <optional>
#include <string>
#include <string_view>

namespace lut::formats {

// Reads a LUT image. forced: the layout to use whatever options.layout says (the "hald" format);
// otherwise options.layout, else auto-detection (StripFormat.cpp's header explains the rule).
LutFile readLutImage(const std::string& path, const FormatOptions& options,
                     std::optional<LutLayout> forced = std::nullopt);
// Writes a LUT image in `layout`; bit depth from options (0 = 8 for PNG/TIFF, float for EXR).
Diagnostics writeLutImage(const std::string& path, const LutFile& file,
                          const FormatOptions& options, LutLayout layout);
// The same from and to bytes in memory (Format::readMemory/writeMemory): `name` stands for the
// data in messages and its extension picks the image format; the same codecs and checks, no
// temporary file. The header and pixels come from one decoder (bytes cannot change between).
LutFile readLutImageMemory(std::string_view bytes, const std::string& name,
                           const FormatOptions& options,
                           std::optional<LutLayout> forced = std::nullopt);
// Whether a LUT image written at `path` keeps its LUTKIT_PURPOSE description: the containers
// whose description lutkit writes and reads (PNG, TIFF, OpenEXR; a name without extension is a
// PNG).
bool lutImageKeepsPurpose(const std::string& path);
std::string writeLutImageMemory(const std::string& name, const LutFile& file,
                                const FormatOptions& options, LutLayout layout,
                                Diagnostics* diagnostics);

} // namespace lut::formats
