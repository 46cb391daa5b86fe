// SPDX-License-Identifier: Apache-2.0
#pragma once
// The man page and the bash, zsh and fish completion scripts, generated from the option tables
// (OptionTable.h) by `lutkit --generate KIND` when lutkit is built (cli/CMakeLists.txt), so they
// always list the commands, options and values lutkit has.
#include "OptionTable.h"

#include <string>
#include <vector>

namespace lut::cli {

std::string manPage(const ProgramEntry& program);        // roff, section 1
std::string bashCompletion(const ProgramEntry& program); // defines _lutkit, `complete -F`
std::string zshCompletion(const ProgramEntry& program);  // #compdef lutkit
std::string fishCompletion(const ProgramEntry& program); // `complete -c lutkit ...` lines

std::vector<std::string> generatorKinds(); // "man", "bash", "zsh", "fish"
// One of the above by kind; throws std::invalid_argument for another kind.
std::string generate(const ProgramEntry& program, const std::string& kind);

} // namespace lut::cli
