#pragma once
// "-" on lutkit's command lines: standard input and output, and the LUT writes that go to them
// (or to a device, FIFO, /dev/stdout) in place instead of through a temporary file.
#include "lut/io/Format.h"

#include <cstddef>
#include <string>

namespace lut {

// All of standard input. Throws lut::LimitError past maxBytes ("-: standard input is over the
// limit of N bytes") and lut::Error when it cannot be read.
std::string readStandardInput(std::size_t maxBytes);

// Writes lut with format to path under lut::checkOutput's rules with ExistingOutput::Replace
// (callers that refuse existing outputs check first): "-" and special files in place through
// format.writeMemory, regular files through format.write. writtenBytes, when given, receives the
// bytes of an in-place write (to read them back without a file).
Diagnostics writeLutFile(const Format& format, const std::string& path, const LutFile& lut,
                         const FormatOptions& options, std::string* writtenBytes = nullptr);

} // namespace lut
