// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a file name says: its extension, the way formats and image writers are chosen; the name a
// new file takes beside one it must not replace; and where the running program lives, the way its
// installed files are found.
#include <string>

namespace lut {

// Lower-cased extension of path including the dot ("" if none).
std::string extensionOf(const std::string& path);

// path itself when nothing is there, else the first of "STEM (2).EXT", "STEM (3).EXT", ... in the
// same folder that nothing is (the way Windows names a copy). For outputs that never replace a
// file: lutkit FILE... (the drop) writing color_grading_lut.nutexb beside its input.
std::string firstFreeName(const std::string& path);

// The folder of the running executable (lut::os::executablePath), "" when it cannot be told:
// where the image module and lutkit's own OpenColorIO config are looked for.
std::string executableDir();

} // namespace lut
