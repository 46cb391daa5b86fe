// SPDX-License-Identifier: Apache-2.0
#pragma once
// The program's arguments and its console: what lutkit's command line (cli/CommandLine.cpp) asks
// of the system before and after a command runs. POSIX: the arguments as given, nothing to set
// up, no window of its own. Windows: the arguments from the wide command line in UTF-8, the
// standard streams in binary mode (no CRLF added: a .cube written to "-" has the bytes it has on
// Linux) and the console's code page UTF-8 for the program's life, escapes only where the console
// says it takes them, and the wait for a key when the console window is the program's own.
#include <string>
#include <vector>

namespace lut::os {

// The arguments after the program's name, in UTF-8 (Windows: from GetCommandLineW, whatever the
// code page; argv is ignored there).
std::vector<std::string> programArguments(int argc, const char* const* argv);

// Sets up standard input, output and error for bytes (Windows: binary mode, UTF-8 console output,
// restored at exit). Idempotent.
void prepareStandardStreams();

// Whether descriptor fd is a terminal (a console; never a pipe, a file or NUL).
bool isTerminal(int fd);
// Whether fd is a terminal that takes ANSI escapes ("\033[K", colours). Windows: a console that
// accepts virtual-terminal processing (switched on by this call); Wine's console and pipes do not.
bool terminalTakesEscapes(int fd);

// Whether the console window is the program's own (Windows: started from Explorer, by a double
// click or files dropped on it, so the window closes when the program ends) and someone can press
// a key in it (standard input is that console). Always false on POSIX.
bool consoleIsOwnWindow();
// Prints prompt to standard error and waits for a key in the console.
void waitForKey(const std::string& prompt);

} // namespace lut::os
