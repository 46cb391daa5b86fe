// SPDX-License-Identifier: Apache-2.0
// lut/os/Files.h on Windows: the wide API (UTF-16 names), files opened by CreateFileW shared for
// reading, writing and deletion (an interrupt removes a temporary file lutkit still writes) and
// handed to the C runtime as binary descriptors; positional reads and writes by moving the file
// pointer under a lock (readBytesAt says why); the atomic rename by MoveFileExW.
#include "lut/os/Files.h"

#include "Wide.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <fcntl.h>
#include <io.h>
#include <mutex>
#include <sys/stat.h>

namespace lut::os {

using windows::errnoFrom;
using windows::failWithLastError;
using windows::handleOf;
using windows::widen;

namespace {

constexpr DWORD kShareAll = FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE;
// 1601-01-01 to 1970-01-01 in FILETIME's 100 ns steps.
constexpr std::int64_t kUnixEpoch = 116444736000000000LL;

std::uint64_t join(DWORD high, DWORD low) {
    return (static_cast<std::uint64_t>(high) << 32) | low;
}

int infoOf(HANDLE h, FileInfo& info, bool linkItself) {
    info = FileInfo{};
    ::SetLastError(NO_ERROR); // FILE_TYPE_UNKNOWN is a failure only with an error set
    switch (::GetFileType(h)) {
    case FILE_TYPE_CHAR:
        info.type = FileType::CharacterDevice;
        info.permissions = 0666;
        return 0;
    case FILE_TYPE_PIPE:
        info.type = FileType::Fifo;
        info.permissions = 0666;
        return 0;
    case FILE_TYPE_DISK:
        break;
    default:
        if (::GetLastError() != NO_ERROR)
            return errnoFrom(::GetLastError());
        info.type = FileType::Other;
        return 0;
    }
    BY_HANDLE_FILE_INFORMATION bh{};
    if (!::GetFileInformationByHandle(h, &bh))
        return errnoFrom(::GetLastError());
    info.type =
        (bh.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) ? FileType::Directory : FileType::Regular;
    if (linkItself && (bh.dwFileAttributes & FILE_ATTRIBUTE_REPARSE_POINT)) {
        FILE_ATTRIBUTE_TAG_INFO tag{};
        if (::GetFileInformationByHandleEx(h, FileAttributeTagInfo, &tag, sizeof tag) &&
            tag.ReparseTag == IO_REPARSE_TAG_SYMLINK)
            info.type = FileType::SymbolicLink;
    }
    info.size = join(bh.nFileSizeHigh, bh.nFileSizeLow);
    const auto written = static_cast<std::int64_t>(
        join(bh.ftLastWriteTime.dwHighDateTime, bh.ftLastWriteTime.dwLowDateTime));
    info.modifiedNs = (written - kUnixEpoch) * 100;
    info.changedNs = info.modifiedNs;
    info.device = bh.dwVolumeSerialNumber;
    info.inode = join(bh.nFileIndexHigh, bh.nFileIndexLow);
    const bool readOnly = (bh.dwFileAttributes & FILE_ATTRIBUTE_READONLY) != 0;
    info.permissions = (info.type == FileType::Directory ? 0555u : 0444u) | (readOnly ? 0u : 0222u);
    return 0;
}

int infoOfPath(const std::string& path, FileInfo& info, bool linkItself) {
    if (path.empty())
        return ENOENT;
    // No access asked for: the attributes only, so a file another program holds open exclusively
    // can still be looked at; FILE_FLAG_BACKUP_SEMANTICS opens folders too.
    const HANDLE h = ::CreateFileW(
        widen(path).c_str(), 0, kShareAll, nullptr, OPEN_EXISTING,
        FILE_FLAG_BACKUP_SEMANTICS | (linkItself ? FILE_FLAG_OPEN_REPARSE_POINT : 0), nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return errnoFrom(::GetLastError());
    const int rc = infoOf(h, info, linkItself);
    ::CloseHandle(h);
    return rc;
}

// Whether a failed call failed on the read-only attribute of path (which POSIX ignores when a
// file is renamed over or removed).
bool isReadOnly(const wchar_t* path) {
    const DWORD attr = ::GetFileAttributesW(path);
    return attr != INVALID_FILE_ATTRIBUTES && (attr & FILE_ATTRIBUTE_READONLY);
}

} // namespace

int fileInfo(const std::string& path, FileInfo& info) {
    return infoOfPath(path, info, false);
}

int linkInfo(const std::string& path, FileInfo& info) {
    return infoOfPath(path, info, true);
}

int openFileInfo(int fd, FileInfo& info) {
    const HANDLE h = handleOf(fd);
    if (h == INVALID_HANDLE_VALUE)
        return EBADF;
    return infoOf(h, info, false);
}

bool exists(const std::string& path) {
    FileInfo info;
    return fileInfo(path, info) == 0;
}

bool isDirectory(const std::string& path) {
    FileInfo info;
    return fileInfo(path, info) == 0 && info.type == FileType::Directory;
}

int openFile(const std::string& path, OpenFor how) {
    DWORD access = GENERIC_WRITE;
    DWORD disposition = OPEN_EXISTING;
    int flags = _O_BINARY | _O_NOINHERIT | _O_WRONLY;
    switch (how) {
    case OpenFor::Read:
        access = GENERIC_READ;
        flags = _O_BINARY | _O_NOINHERIT | _O_RDONLY;
        break;
    case OpenFor::WriteInPlace:
        break;
    case OpenFor::CreateNew:
        disposition = CREATE_NEW;
        break;
    case OpenFor::Append:
        flags |= _O_APPEND;
        break;
    }
    if (path.empty()) {
        errno = ENOENT;
        return -1;
    }
    const HANDLE h = ::CreateFileW(widen(path).c_str(), access, kShareAll, nullptr, disposition,
                                   FILE_ATTRIBUTE_NORMAL, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return failWithLastError();
    const int fd = ::_open_osfhandle(reinterpret_cast<intptr_t>(h), flags);
    if (fd < 0) {
        ::CloseHandle(h);
        errno = EMFILE;
        return -1;
    }
    return fd;
}

std::FILE* openStream(const std::string& path, const char* mode) {
    return ::_wfopen(widen(path).c_str(), widen(mode).c_str());
}

std::ptrdiff_t readBytes(int fd, void* data, std::size_t bytes) {
    return ::_read(fd, data, static_cast<unsigned>(std::min<std::size_t>(bytes, INT_MAX)));
}

std::ptrdiff_t writeBytes(int fd, const void* data, std::size_t bytes) {
    return ::_write(fd, data, static_cast<unsigned>(std::min<std::size_t>(bytes, INT_MAX)));
}

// One lock for the positional reads and writes of every descriptor (they move the file pointer).
static std::mutex& positionalLock() {
    static std::mutex m;
    return m;
}

std::ptrdiff_t readBytesAt(int fd, void* data, std::size_t bytes, std::uint64_t offset) {
    const HANDLE h = handleOf(fd);
    if (h == INVALID_HANDLE_VALUE)
        return -1;
    // The offset by moving the file pointer, not by an OVERLAPPED: on a synchronous handle
    // ReadFile and WriteFile given one also queue a completion notification when they succeed,
    // a round trip to Wine's server per call (1510 of them in a 1080p preview, about a tenth
    // of its time under Wine). The lock makes the move and the transfer one step, as pread's.
    const std::lock_guard<std::mutex> lock(positionalLock());
    LARGE_INTEGER at;
    at.QuadPart = static_cast<LONGLONG>(offset);
    if (!::SetFilePointerEx(h, at, nullptr, FILE_BEGIN))
        return failWithLastError();
    DWORD done = 0;
    if (!::ReadFile(h, data, static_cast<DWORD>(std::min<std::size_t>(bytes, DWORD(1) << 30)),
                    &done, nullptr)) {
        if (::GetLastError() == ERROR_HANDLE_EOF)
            return 0;
        return failWithLastError();
    }
    return static_cast<std::ptrdiff_t>(done);
}

std::ptrdiff_t writeBytesAt(int fd, const void* data, std::size_t bytes, std::uint64_t offset) {
    const HANDLE h = handleOf(fd);
    if (h == INVALID_HANDLE_VALUE)
        return -1;
    // As readBytesAt: the file pointer moved under the lock, no OVERLAPPED.
    const std::lock_guard<std::mutex> lock(positionalLock());
    LARGE_INTEGER at;
    at.QuadPart = static_cast<LONGLONG>(offset);
    if (!::SetFilePointerEx(h, at, nullptr, FILE_BEGIN))
        return failWithLastError();
    DWORD done = 0;
    if (!::WriteFile(h, data, static_cast<DWORD>(std::min<std::size_t>(bytes, DWORD(1) << 30)),
                     &done, nullptr))
        return failWithLastError();
    return static_cast<std::ptrdiff_t>(done);
}

int syncFile(int fd) {
    const HANDLE h = handleOf(fd);
    if (h == INVALID_HANDLE_VALUE)
        return -1;
    if (::FlushFileBuffers(h))
        return 0;
    if (::GetLastError() != ERROR_ACCESS_DENIED)
        return failWithLastError();
    // A descriptor opened for reading (POSIX's fsync takes any): the same file, opened for writing
    // by its final name, flushes the same cached bytes.
    wchar_t name[32768];
    const DWORD n = ::GetFinalPathNameByHandleW(h, name, 32768, FILE_NAME_NORMALIZED);
    if (n == 0 || n >= 32768)
        return failWithLastError();
    const HANDLE w = ::CreateFileW(name, GENERIC_WRITE, kShareAll, nullptr, OPEN_EXISTING,
                                   FILE_ATTRIBUTE_NORMAL, nullptr);
    if (w == INVALID_HANDLE_VALUE)
        return failWithLastError();
    const bool ok = ::FlushFileBuffers(w);
    const DWORD err = ::GetLastError();
    ::CloseHandle(w);
    if (ok)
        return 0;
    errno = errnoFrom(err);
    return -1;
}

int closeFile(int fd) {
    return ::_close(fd);
}

void startWriteback(int, std::uint64_t, std::uint64_t) {}

int removeFile(const char* path) noexcept {
    // No allocation: the console's interrupt handler calls this (lut/io/TempFiles.h).
    wchar_t wide[32768]; // 64 KiB of stack, the longest name Windows takes
    if (::MultiByteToWideChar(CP_UTF8, 0, path, -1, wide, 32768) == 0)
        return failWithLastError();
    if (::DeleteFileW(wide))
        return 0;
    // POSIX removes a read-only file from a writable folder; Windows wants the attribute off.
    if (::GetLastError() == ERROR_ACCESS_DENIED && isReadOnly(wide) &&
        ::SetFileAttributesW(wide, FILE_ATTRIBUTE_NORMAL) && ::DeleteFileW(wide))
        return 0;
    return failWithLastError();
}

int removeFolder(const char* path) noexcept {
    wchar_t wide[32768]; // 64 KiB of stack, the longest name Windows takes
    if (::MultiByteToWideChar(CP_UTF8, 0, path, -1, wide, 32768) == 0)
        return failWithLastError();
    return ::RemoveDirectoryW(wide) ? 0 : failWithLastError();
}

int renameReplacing(const std::string& from, const std::string& to) {
    const std::wstring src = widen(from), dst = widen(to);
    constexpr DWORD kFlags = MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH;
    if (::MoveFileExW(src.c_str(), dst.c_str(), kFlags))
        return 0;
    // A read-only file is replaced as on POSIX (the new one keeps the attribute when it has it).
    const DWORD err = ::GetLastError();
    if (err == ERROR_ACCESS_DENIED && isReadOnly(dst.c_str())) {
        const DWORD attr = ::GetFileAttributesW(dst.c_str());
        if (::SetFileAttributesW(dst.c_str(), attr & ~DWORD(FILE_ATTRIBUTE_READONLY))) {
            if (::MoveFileExW(src.c_str(), dst.c_str(), kFlags))
                return 0;
            const DWORD again = ::GetLastError();
            ::SetFileAttributesW(dst.c_str(), attr);
            errno = errnoFrom(again);
            return -1;
        }
    }
    errno = errnoFrom(err);
    return -1;
}

int renameNoReplace(const std::string& from, const std::string& to) {
    // Without MOVEFILE_REPLACE_EXISTING the move fails when `to` exists, atomically.
    return ::MoveFileExW(widen(from).c_str(), widen(to).c_str(), MOVEFILE_WRITE_THROUGH)
               ? 0
               : failWithLastError();
}

int syncFolder(const std::string&) {
    return 0; // NTFS journals the rename; MOVEFILE_WRITE_THROUGH waited for it
}

int setPermissions(const std::string& path, unsigned permissions) {
    const std::wstring w = widen(path);
    const DWORD attr = ::GetFileAttributesW(w.c_str());
    if (attr == INVALID_FILE_ATTRIBUTES)
        return failWithLastError();
    const DWORD want = (permissions & 0200) ? (attr & ~DWORD(FILE_ATTRIBUTE_READONLY))
                                            : (attr | FILE_ATTRIBUTE_READONLY);
    if (want == attr)
        return 0;
    return ::SetFileAttributesW(w.c_str(), want == 0 ? FILE_ATTRIBUTE_NORMAL : want)
               ? 0
               : failWithLastError();
}

std::size_t maxNameBytes(const std::string&) {
    // 255 UTF-16 units; a name of 255 bytes of UTF-8 never has more.
    return 255;
}

std::string realPath(const std::string& path) {
    const HANDLE h = ::CreateFileW(widen(path).c_str(), 0, kShareAll, nullptr, OPEN_EXISTING,
                                   FILE_FLAG_BACKUP_SEMANTICS, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return {};
    std::wstring buf(MAX_PATH, L'\0');
    DWORD n = ::GetFinalPathNameByHandleW(h, buf.data(), static_cast<DWORD>(buf.size()),
                                          FILE_NAME_NORMALIZED | VOLUME_NAME_DOS);
    if (n >= buf.size()) {
        buf.resize(n + 1);
        n = ::GetFinalPathNameByHandleW(h, buf.data(), static_cast<DWORD>(buf.size()),
                                        FILE_NAME_NORMALIZED | VOLUME_NAME_DOS);
    }
    ::CloseHandle(h);
    if (n == 0 || n >= buf.size())
        return {};
    buf.resize(n);
    // "\\?\C:\x" -> "C:\x", "\\?\UNC\server\share" -> "\\server\share".
    if (buf.rfind(L"\\\\?\\UNC\\", 0) == 0)
        buf = L"\\\\" + buf.substr(8);
    else if (buf.rfind(L"\\\\?\\", 0) == 0)
        buf = buf.substr(4);
    return windows::narrow(buf);
}

std::string linkTarget(const std::string&) {
    return {}; // lutkit asks only for the links POSIX names its own streams by (/dev/stdout)
}

} // namespace lut::os
