// SPDX-License-Identifier: Apache-2.0
#pragma once
// `lutkit FILE...`, no command: what Windows does when files are dropped on lutkit.exe (or on its
// shortcut), and what Smush-LUT's users expect of it. Each file is converted as
// `lutkit convert FILE DIR/color_grading_lut.nutexb` would (the game's LUT, compensated for its
// brighten pass, the report printed), into the folder the file is in; a .nutexb already there is
// never replaced: the first free name ("color_grading_lut (2).nutexb") is taken and said.
// CommandLine::run decides it (isDrop) and runs each file as its own convert; lutkit with no
// arguments prints howToUse(). The wait for a key before the window closes is the program's
// (CommandLine::run(argc, argv), lut/os/Console.h), only where the console is its own window.
#include <string>
#include <vector>

namespace lut::cli {

// Whether args are a drop: the first names an existing file (not a folder) and is no command,
// and none is an option (starts with '-').
bool isDrop(const std::vector<std::string>& args, const std::vector<std::string>& commands);

// Where a dropped file's game LUT goes: `usual` is color_grading_lut.nutexb beside it, `output`
// the same or, when that name is taken, the first free one; or `refused` says why the file is not
// one to convert (a .nutexb already), output empty.
struct DropTarget {
    std::string output;
    std::string usual;
    std::string refused;
};
DropTarget dropTarget(const std::string& input);

// The short "how to use" lutkit prints when started with no arguments (a double click).
std::string howToUse();

} // namespace lut::cli
