// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the Windows side of lut/os shares: UTF-8 <-> UTF-16 and the system's error codes as errno
// values (so messages say the words they say on Linux).
#include <string>

#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>

namespace lut::os::windows {

// UTF-8 to UTF-16 and back (malformed sequences become U+FFFD).
std::wstring widen(const std::string& utf8);
std::string narrow(const wchar_t* utf16, std::size_t length);
inline std::string narrow(const std::wstring& utf16) {
    return narrow(utf16.data(), utf16.size());
}

// GetLastError()'s code as the errno value POSIX would give (ENOENT, EACCES, EEXIST, ENOSPC ...).
int errnoFrom(DWORD error);
// Sets errno from GetLastError() and returns -1.
int failWithLastError();

// The file behind a C runtime descriptor (INVALID_HANDLE_VALUE with errno EBADF when none).
HANDLE handleOf(int fd);

} // namespace lut::os::windows
