// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "lut/io/FormatRegistry.h"

namespace lut::formats {

// Registers every built-in format into FormatRegistry::instance() (idempotent). The one list of
// formats lives in formats/src/Registry.cpp.
void registerBuiltinFormats();

// Reads a LUT file with the built-in formats registered (convenience for callers). A path
// "builtin:NAME" is a LUT known by name (lut/io/BuiltinLut.h: format "builtin", dialect NAME).
LutFile readLut(const std::string& path, const FormatOptions& options = {},
                const std::string& formatName = {});
Diagnostics writeLut(const std::string& path, const LutFile& lut, const FormatOptions& options = {},
                     const std::string& formatName = {});

} // namespace lut::formats
