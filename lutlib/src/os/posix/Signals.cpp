// SPDX-License-Identifier: Apache-2.0
// lut/os/Signals.h on POSIX: SIGINT and SIGTERM through sigaction.
#include "lut/os/Signals.h"

#include <atomic>
#include <csignal>
#include <initializer_list>
#include <unistd.h>

namespace lut::os {

void installInterruptHandler(InterruptHandler handler) {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true))
        return;
    struct sigaction sa {};
    sa.sa_handler = handler;
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

void exitNow(int code) noexcept {
    ::_exit(code);
}

} // namespace lut::os
