// SPDX-License-Identifier: Apache-2.0
#include "Interrupts.h"

#include "Usage.h"

#include "lut/io/TempFiles.h"
#include "lut/os/Files.h"
#include "lut/os/Signals.h"

#include <atomic>
#include <csignal>
#include <cstring>

namespace lut::cli {

namespace {

std::atomic<int> g_cooperative{0};
std::atomic<int> g_signals{0};

void say(const char* text) {
    const std::ptrdiff_t ignored = os::writeBytes(2, text, std::strlen(text));
    (void)ignored;
}

// Async-signal-safe only: atomics, unlink/rmdir (inside removeTempFilesInFlight), write, _exit
// (lut/os/Signals.h: on Windows it runs on the console's own thread).
extern "C" void onSignal(int sig) {
    lut::removeTempFilesInFlight();
    lut::markInterrupted(sig);
    if (g_cooperative.load() > 0 && g_signals.fetch_add(1) == 0)
        return; // the batch runner stops and reports
    say(sig == SIGTERM ? "\nlutkit: interrupted (SIGTERM); unfinished outputs removed\n"
                       : "\nlutkit: interrupted (SIGINT); unfinished outputs removed\n");
    os::exitNow(kExitInterrupted);
}

} // namespace

void installInterruptHandlers() {
    os::installInterruptHandler(onSignal);
}

CooperativeInterrupts::CooperativeInterrupts() {
    g_cooperative.fetch_add(1);
}

CooperativeInterrupts::~CooperativeInterrupts() {
    g_cooperative.fetch_sub(1);
}

const char* signalName(int sig) {
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
}

} // namespace lut::cli
