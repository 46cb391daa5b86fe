// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a file name says: its extension, the way formats and image writers are chosen; and where
// the running program lives, the way its installed files are found.
#include <string>

namespace lut {

// Lower-cased extension of path including the dot ("" if none).
std::string extensionOf(const std::string& path);

// The folder of the running executable (/proc/self/exe), "" when it cannot be told: where the
// image module and lutkit's own OpenColorIO config are looked for.
std::string executableDir();

} // namespace lut
