// SPDX-License-Identifier: Apache-2.0
#pragma once
// A format that encodes in memory: write() puts writeMemory()'s bytes on disk atomically
// (lut::writeFileAtomically: a temporary file renamed into place, an old file untouched when the
// write fails), so each such format writes only its encoder, and a file and the editor's export
// preview get the same bytes.
#include "lut/io/AtomicFile.h"
#include "lut/io/Format.h"

namespace lut::formats {

class EncodedFormat : public Format {
public:
    Diagnostics write(const std::string& path, const LutFile& lut,
                      const FormatOptions& options) const final {
        Diagnostics diagnostics;
        const std::string bytes = writeMemory(lut, path, options, &diagnostics);
        writeFileAtomically(path, bytes);
        return diagnostics;
    }
    std::string writeMemory(const LutFile& lut, const std::string& name,
                            const FormatOptions& options,
                            Diagnostics* diagnostics) const override = 0;
};

} // namespace lut::formats
