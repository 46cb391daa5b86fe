// SPDX-License-Identifier: Apache-2.0
// lut/os/Console.h on Windows: the wide command line, binary standard streams, the console's
// UTF-8 code page, and the window the program owns when Explorer started it.
#include "lut/os/Console.h"

#include "Wide.h"

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <io.h>
#include <shellapi.h>

namespace lut::os {

namespace {

UINT g_outputCodePage = 0;

void restoreCodePage() {
    if (g_outputCodePage != 0)
        ::SetConsoleOutputCP(g_outputCodePage);
}

bool consoleMode(int fd, DWORD& mode) {
    const intptr_t h = ::_get_osfhandle(fd);
    return h != -1 && h != -2 && ::GetConsoleMode(reinterpret_cast<HANDLE>(h), &mode);
}

} // namespace

std::vector<std::string> programArguments(int argc, const char* const* argv) {
    int n = 0;
    LPWSTR* wide = ::CommandLineToArgvW(::GetCommandLineW(), &n);
    if (!wide) // cannot happen short of memory: the bytes as given
        return std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc);
    std::vector<std::string> args;
    for (int i = 1; i < n; ++i)
        args.push_back(windows::narrow(wide[i], std::wcslen(wide[i])));
    ::LocalFree(wide);
    return args;
}

void prepareStandardStreams() {
    static bool done = false;
    if (done)
        return;
    done = true;
    // Bytes in and out as they are: "\n" stays one byte (a .cube or an image to "-", reports).
    std::fflush(stdout);
    std::fflush(stderr);
    ::_setmode(0, _O_BINARY);
    ::_setmode(1, _O_BINARY);
    ::_setmode(2, _O_BINARY);
    // lutkit writes UTF-8 (file names in messages); the console shows it as such while it runs.
    const UINT old = ::GetConsoleOutputCP();
    if (old != 0 && old != CP_UTF8 && ::SetConsoleOutputCP(CP_UTF8)) {
        g_outputCodePage = old;
        std::atexit(restoreCodePage);
    }
}

bool isTerminal(int fd) {
    DWORD mode = 0;
    return consoleMode(fd, mode);
}

bool terminalTakesEscapes(int fd) {
    DWORD mode = 0;
    if (!consoleMode(fd, mode))
        return false;
    if (mode & ENABLE_VIRTUAL_TERMINAL_PROCESSING)
        return true;
    const HANDLE h = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
    return ::SetConsoleMode(h, mode | ENABLE_VIRTUAL_TERMINAL_PROCESSING) != 0;
}

bool consoleIsOwnWindow() {
    DWORD ids[2] = {};
    // One process on the console: it was made for this program (Explorer, a shortcut, a drop),
    // not inherited from a command prompt, and it closes when the program ends.
    return ::GetConsoleProcessList(ids, 2) == 1 && isTerminal(0);
}

void waitForKey(const std::string& prompt) {
    std::fputs(prompt.c_str(), stderr);
    std::fflush(stderr);
    const HANDLE in = ::GetStdHandle(STD_INPUT_HANDLE);
    ::FlushConsoleInputBuffer(in);
    for (;;) {
        INPUT_RECORD record{};
        DWORD got = 0;
        if (!::ReadConsoleInputW(in, &record, 1, &got) || got == 0)
            return;
        if (record.EventType == KEY_EVENT && record.Event.KeyEvent.bKeyDown)
            return;
    }
}

} // namespace lut::os
