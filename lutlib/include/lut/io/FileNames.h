// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a file name says: its extension, the way formats and image writers are chosen; and where
// the running program lives, the way its installed files are found.
#include <string>
#include <string_view>

namespace lut {

// Lower-cased extension of path including the dot ("" if none).
std::string extensionOf(const std::string& path);

// The folder of the running executable (/proc/self/exe), "" when it cannot be told: where the
// image module and lutkit's own OpenColorIO config are looked for.
std::string executableDir();

// Text as it may be printed in a one-line message: control characters (a newline, a carriage
// return, ESC, DEL ...) written as C escapes ("\n", "\r", "\x1b"), so a file name cannot break a
// message into lines or drive the terminal. The one helper every message of lutkit's goes
// through (cli: the error, warning and note lines; the names in a batch's lines).
std::string printable(std::string_view text);

} // namespace lut
