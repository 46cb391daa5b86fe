// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor script's commands (ScriptRunner.h lists them for the user): one row each, its name,
// its arguments as the user writes them, and what it does with a ScriptContext. Adding a command
// is adding a row (ScriptCommands.cpp), as a subcommand is added to the CLI's CommandLine.cpp.
#include <QLatin1StringView>

#include <span>

namespace lut::gui {

struct ScriptContext;

struct ScriptCommand {
    QLatin1StringView name;
    const char* arguments; // the synopsis, e.g. "PATH [LAYOUT]"
    void (*run)(ScriptContext& c);
};

std::span<const ScriptCommand> scriptCommands();
// The row of that name, or null.
const ScriptCommand* findScriptCommand(const QString& name);

} // namespace lut::gui
