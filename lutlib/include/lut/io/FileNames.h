#pragma once
// What a file name says: its extension, the way formats and image writers are chosen.
#include <string>

namespace lut {

// Lower-cased extension of path including the dot ("" if none).
std::string extensionOf(const std::string& path);

} // namespace lut
