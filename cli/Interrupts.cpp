// SPDX-License-Identifier: Apache-2.0
#include "Interrupts.h"

#include "Usage.h"

#include "lut/io/TempFiles.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace lut::cli {

namespace {

std::atomic<int> g_cooperative{0};
std::atomic<int> g_signals{0};

void say(const char* text) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

// Async-signal-safe only: atomics, unlink/rmdir (inside removeTempFilesInFlight), write, _exit.
extern "C" void onSignal(int sig) {
    lut::removeTempFilesInFlight();
    lut::markInterrupted(sig);
    if (g_cooperative.load() > 0 && g_signals.fetch_add(1) == 0)
        return; // the batch runner stops and reports
    say(sig == SIGTERM ? "\nlutkit: interrupted (SIGTERM); unfinished outputs removed\n"
                       : "\nlutkit: interrupted (SIGINT); unfinished outputs removed\n");
    ::_exit(kExitInterrupted);
}

} // namespace

void installInterruptHandlers() {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true))
        return;
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    for (int sig : {SIGINT, SIGTERM}) {
        struct sigaction old {};
        // A signal the caller chose to ignore (nohup, a background job) stays ignored.
        if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        ::sigaction(sig, &sa, nullptr);
    }
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
