// SPDX-License-Identifier: Apache-2.0
// Format's defaults: a file read and written as the bytes of the memory forms, and the stream
// bound. The registry is FormatRegistry.cpp.
#include "lut/io/Format.h"

#include "lut/Limits.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/InputFile.h"

namespace lut {

Format::~Format() = default;

std::uint64_t Format::maxStreamBytes(std::string_view head) const {
    return head.find('\0') == std::string_view::npos ? limits::kMaxLutFileBytes : 0;
}

LutFile Format::read(const std::string& path, const FormatOptions& options) const {
    return readMemory(readFile(path, static_cast<std::size_t>(limits::kMaxLutFileBytes)), path,
                      options);
}

Diagnostics Format::write(const std::string& path, const LutFile& lut,
                          const FormatOptions& options) const {
    Diagnostics diagnostics;
    const std::string bytes = writeMemory(lut, path, options, &diagnostics);
    writeFileAtomically(path, bytes);
    return diagnostics;
}

} // namespace lut
