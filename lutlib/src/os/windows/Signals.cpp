// SPDX-License-Identifier: Apache-2.0
// lut/os/Signals.h on Windows: the console's control events. The handler runs on a thread the
// system starts for it; Ctrl-C and Ctrl-Break are SIGINT, a closed window, log-off or shutdown
// SIGTERM (the system ends the program when the handler returns from those).
#include "lut/os/Signals.h"

#include "Wide.h"

#include <atomic>
#include <csignal>
#include <cstdlib>

namespace lut::os {

namespace {

std::atomic<InterruptHandler> g_handler{nullptr};

BOOL WINAPI onConsoleEvent(DWORD event) {
    const InterruptHandler handler = g_handler.load();
    if (!handler)
        return FALSE;
    switch (event) {
    case CTRL_C_EVENT:
    case CTRL_BREAK_EVENT:
        handler(SIGINT);
        return TRUE;
    case CTRL_CLOSE_EVENT:
    case CTRL_LOGOFF_EVENT:
    case CTRL_SHUTDOWN_EVENT:
        handler(SIGTERM);
        return TRUE;
    default:
        return FALSE;
    }
}

} // namespace

void installInterruptHandler(InterruptHandler handler) {
    // A process started with Ctrl-C ignored (a background job) never sees it: the flag is the
    // console's, inherited, and the system does not call handlers for it.
    if (g_handler.exchange(handler) == nullptr)
        ::SetConsoleCtrlHandler(onConsoleEvent, TRUE);
}

void exitNow(int code) noexcept {
    std::_Exit(code);
}

} // namespace lut::os
