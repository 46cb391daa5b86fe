// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sizes an image file declares in its header, checked against the file's length before a codec
// believes them (issue 17: memory bounded by what the file holds, not what it claims; issue 29:
// one rule for every format). No OpenImageIO here: the check runs before the image module opens
// the file. The scanners are in ImageHeaderScan*.cpp, the ratios each codec can reach in
// docs/robustness.md.
#include "imageio/ImageHeaderScan.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace lut::formats {

// The rule on a regular file: throws lut::LimitError "PATH: ..." naming the figure (or lut::Error
// naming the field whose size runs past the file); returns what the header declares (format ""
// when the first bytes are no format it knows: the codec's own checks then apply). nameOrFormat
// tells a TGA, which has no magic number (the path, or a format name).
DeclaredImage checkImageHeader(const std::string& path, const std::string& nameOrFormat);

// The same on bytes in memory (standard input). whole = false: only the bytes read so far, to
// bound the rest (plausibleFileBytes); nothing is refused then.
DeclaredImage checkImageBytes(const std::string& name, const std::string& bytes,
                              const std::string& format, bool whole);

// For lut::Format::maxStreamBytes: the most bytes an image stream that starts with head can take
// (0: it is no image format lutkit knows; lut::limits::kMaxLutFileBytes when its header does not
// bound it).
std::uint64_t imageStreamBytes(std::string_view head, const std::string& format = {});

} // namespace lut::formats
