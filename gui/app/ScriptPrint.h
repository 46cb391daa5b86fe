// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor script's `print WHAT` (ScriptRunner.h): one line "WHAT VALUE" of the window's state
// on the script's output; a table of what can be printed, as ScriptCommands.h is of commands.
#include <QString>

namespace lut::gui {

struct ScriptContext;

// Prints "WHAT VALUE\n"; an unknown WHAT is a ScriptFailure ("print: unknown 'WHAT'").
void printState(ScriptContext& c, const QString& what);

} // namespace lut::gui
