// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenColorIO reads LUT files by path only (its FileTransform opens the file itself), so bytes
// in memory it is to read (standard input, a LUT in an archive) are first put in a file of a
// private temporary folder, removed afterwards. The one temporary folder of lutkit's formats:
// every other format reads and writes bytes (lut/io/Format.h). Messages name the caller's name
// for the bytes, not the temporary file.
#include "lut/LutFile.h"

#include <functional>
#include <string>
#include <string_view>

namespace lut::formats {

// `bytes` written to a temporary file with `name`'s extension, read by read(path); its
// diagnostics and errors say `name` where they said the temporary file's path.
LutFile readThroughTemporaryFile(std::string_view bytes, const std::string& name,
                                 const std::function<LutFile(const std::string& path)>& read);

} // namespace lut::formats
