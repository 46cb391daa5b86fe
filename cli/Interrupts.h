// SPDX-License-Identifier: Apache-2.0
#pragma once
// SIGINT and SIGTERM (Ctrl-C, kill): lutkit removes every temporary file in flight
// (lut/io/TempFiles.h) and exits with code 130 (README "Exit codes"). A finished output is
// complete under its name, an unfinished one does not exist: nothing half-written is left.
//  - By default the handler does it at once: removes the temporary files, prints
//    "lutkit: interrupted" and exits.
//  - While a CooperativeInterrupts lives (the batch runner), the first signal only removes the
//    temporary files and marks the program interrupted: jobs in flight stop at their next write
//    (lut::InterruptedError), no new job starts, and the batch prints what was finished before
//    it returns kExitInterrupted. A second signal exits at once.
namespace lut::cli {

// Installs the handlers (idempotent). CommandLine::run(argc, argv) calls it.
void installInterruptHandlers();

class CooperativeInterrupts {
public:
    CooperativeInterrupts();
    ~CooperativeInterrupts();
    CooperativeInterrupts(const CooperativeInterrupts&) = delete;
    CooperativeInterrupts& operator=(const CooperativeInterrupts&) = delete;
};

// "SIGINT", "SIGTERM" (or "a signal") for messages.
const char* signalName(int sig);

} // namespace lut::cli
