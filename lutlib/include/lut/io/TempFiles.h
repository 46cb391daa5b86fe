// SPDX-License-Identifier: Apache-2.0
#pragma once
// Temporary files in flight and interrupts, in one place. Every temporary file (AtomicFile's
// hidden sibling of an output, a private scratch folder) is listed here while it lives, so a
// SIGINT/SIGTERM handler (Windows: the console's Ctrl-C handler; lut/os/Signals.h) can remove
// them all with async-signal-safe calls. The library installs no handler and never exits: the
// program does (lutkit's CommandLine), calling removeTempFilesInFlight() and markInterrupted()
// from its handler. After markInterrupted(),
// AtomicFile refuses to start or commit a write (InterruptedError), so a file is either complete
// under its final name or gone.
#include "lut/Error.h"

#include <string>

namespace lut {

// A write stopped because the program was interrupted (what the CLI maps to exit code 130).
class InterruptedError : public Error {
public:
    using Error::Error;
};

// Removes every registered temporary file, then every registered temporary folder (empty by
// then). Async-signal-safe: only atomic loads, os::removeFile and os::removeFolder (unlink() and
// rmdir()). Safe to call repeatedly.
void removeTempFilesInFlight() noexcept;

// Records that signal sig arrived (async-signal-safe). interrupted() is true from then on.
void markInterrupted(int sig) noexcept;
bool interrupted() noexcept;
int interruptSignal() noexcept; // the signal passed to markInterrupted, 0 if none

// Throws InterruptedError("WHAT: interrupted") if interrupted().
void throwIfInterrupted(const std::string& what);

// Lists path for removeTempFilesInFlight() while this object lives (a file, or with isFolder a
// folder whose files are registered too). Unregistering never frees a path that a signal handler
// may be reading. Move-only.
class TempPathRegistration {
public:
    TempPathRegistration() = default;
    explicit TempPathRegistration(const std::string& path, bool isFolder = false);
    ~TempPathRegistration();
    TempPathRegistration(TempPathRegistration&& other) noexcept;
    TempPathRegistration& operator=(TempPathRegistration&& other) noexcept;
    TempPathRegistration(const TempPathRegistration&) = delete;
    TempPathRegistration& operator=(const TempPathRegistration&) = delete;
    void release() noexcept; // unregister now (the path was renamed or removed)

private:
    void* m_registry = nullptr;
    int m_slot = -1;
};

// The registry is per copy of lutlib. A plug-in module that links its own copy (lutkit_imageio.so)
// must use the program's one, or the handler would not see the module's temporary files: the
// loader passes tempFileRegistry() to the module, which calls useTempFileRegistry() with it
// before its first write.
void* tempFileRegistry() noexcept;
void useTempFileRegistry(void* registry) noexcept;

} // namespace lut
