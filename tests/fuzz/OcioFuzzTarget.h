// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz target for the OpenColorIO bridge: the files OCIO reads, through our "ocio" format reader
// (formats/src/ocio/OcioReader.cpp): a session that serialises OCIO, its exceptions turned into
// lut::Error, the processor inspected and sampled onto a lattice.
//   byte 0: which extension the file gets (OCIO picks its parser by it), modulo the list below
//   byte 1: the lattice size asked for: 0 = the file's own, else 2 + (byte % 16)
//   rest:   the file
// Contract: a well-formed LutFile or lut::Error; anything else escaping is a finding.
#include "FuzzTargets.h"

namespace lut::fuzz {

inline Outcome runOcio(const std::uint8_t* data, std::size_t size) {
    if (size < 2)
        return Outcome::Refused;
    // clang-format off
    static const char* const kExtensions[] = {
        ".3dl", ".cc", ".ccc", ".cdl", ".clf", ".ctf", ".csp", ".lut", ".icc", ".pf",
        ".itx", ".look", ".mga", ".m3d", ".spi1d", ".spi3d", ".spimtx", ".cub", ".vf"};
    // clang-format on
    constexpr std::size_t kCount = sizeof(kExtensions) / sizeof(kExtensions[0]);
    const std::string ext = kExtensions[data[0] % kCount];
    FormatOptions options;
    options.size = data[1] == 0 ? 0 : 2 + data[1] % 16;
    const std::string path = writeScratch("ocio" + ext, data + 2, size - 2);
    const Outcome o = checkedCall([&] { return formats::readLut(path, options, "ocio"); });
    std::remove(path.c_str());
    return o;
}

} // namespace lut::fuzz
