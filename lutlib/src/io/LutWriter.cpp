// SPDX-License-Identifier: Apache-2.0
// The one write of a LUT file; see lut/io/LutWriter.h.
#include "lut/io/LutWriter.h"

#include "lut/io/OutputFile.h"

namespace lut {

Diagnostics writeLutFile(const Format& format, const std::string& path, const LutFile& lut,
                         const FormatOptions& options, std::string* writtenBytes) {
    const OutputTarget target = checkOutput(path, ExistingOutput::Replace);
    if (!target.inPlace())
        return format.write(target.writePath, lut, options);
    Diagnostics d;
    std::string bytes = format.writeMemory(lut, path, options, &d);
    writeOutputBytes(target, bytes);
    if (writtenBytes)
        *writtenBytes = std::move(bytes);
    return d;
}

} // namespace lut
