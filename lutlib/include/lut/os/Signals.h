// SPDX-License-Identifier: Apache-2.0
#pragma once
// The user stopping lutkit: SIGINT and SIGTERM on POSIX (Ctrl-C, kill); on Windows the console's
// Ctrl-C and Ctrl-Break (SIGINT) and its window closed, a log-off or a shutdown (SIGTERM). The
// handler runs in a signal handler (POSIX) or on a thread of the console's (Windows): only
// async-signal-safe calls in it (lut::removeTempFilesInFlight, lut::markInterrupted,
// os::writeBytes, os::exitNow). cli/Interrupts.cpp installs lutkit's.
namespace lut::os {

using InterruptHandler = void (*)(int signal); // SIGINT or SIGTERM (<csignal>)

// Installs handler for the interrupts above, once; a signal the caller chose to ignore (nohup, a
// background job) stays ignored. When the handler returns, the program goes on (Windows: for a
// closed window, the system ends it soon after).
void installInterruptHandler(InterruptHandler handler);

// Ends the process at once with code, running no destructor or atexit function (_exit()).
[[noreturn]] void exitNow(int code) noexcept;

} // namespace lut::os
