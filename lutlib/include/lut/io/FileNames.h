// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a file name says: its extension, the way formats and image writers are chosen; the name a
// new file takes beside one it must not replace; and where the running program lives, the way its
// installed files are found.
#include <string>
#include <string_view>

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

// Text as it may be printed in a one-line message: control characters (a newline, a carriage
// return, ESC, DEL ...) written as C escapes ("\n", "\r", "\x1b"), so a file name cannot break a
// message into lines or drive the terminal. The one helper every message of lutkit's goes
// through (cli: the error, warning and note lines; the names in a batch's lines).
std::string printable(std::string_view text);

} // namespace lut
