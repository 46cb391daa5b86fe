// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one write of a LUT file in a given format, for the registry (FormatRegistry::write),
// lutkit convert and bake: the output rule (lut/io/OutputPolicy.h) decides where the bytes go, a
// regular file through the format's own atomic write, "-" and special files (a device, a FIFO,
// /dev/stdout) in place from the format's memory form.
#include "lut/io/Format.h"

#include <string>

namespace lut {

// Writes lut with format to path under lut::checkOutput's rules with ExistingOutput::Replace
// (callers that refuse existing outputs check first): "-" and special files in place through
// format.writeMemory, regular files through format.write. writtenBytes, when given, receives the
// bytes of an in-place write (to read them back without a file).
Diagnostics writeLutFile(const Format& format, const std::string& path, const LutFile& lut,
                         const FormatOptions& options, std::string* writtenBytes = nullptr);

} // namespace lut
