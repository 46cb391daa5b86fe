// SPDX-License-Identifier: Apache-2.0
#pragma once
// The operating system's files, in one place (docs/windows.md, "The platform layer"): every open,
// read, write, look, rename and removal lutkit's own code makes goes through here, on UTF-8 paths.
// Linux and the browser edition (Emscripten) have it from POSIX (src/os/posix/), Windows from its
// wide API (src/os/windows/: UTF-16 names, binary mode always, files shared for deletion so an
// interrupt can remove a temporary file still open, MoveFileExW for the atomic rename).
// Failures are reported the POSIX way, -1 (or an errno value) with errno set, so every message
// says the same std::strerror words on every system ("No such file or directory").
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace lut::os {

enum class FileType {
    Regular,
    Directory,
    SymbolicLink, // linkInfo only
    Fifo,         // Windows: a pipe
    Socket,
    CharacterDevice, // Windows: a console, NUL
    BlockDevice,
    Other
};

struct FileInfo {
    FileType type = FileType::Other;
    std::uint64_t size = 0;
    std::int64_t modifiedNs = 0; // last modification, in nanoseconds since 1970
    // Last change of the file or its entry (POSIX ctime, which no program can set back; Windows:
    // the last write, as modifiedNs), in nanoseconds since 1970.
    std::int64_t changedNs = 0;
    // The file whatever its names (hard links, symbolic links, any spelling): equal device and
    // inode = one file. Windows: the volume's serial number and the file's index on it.
    std::uint64_t device = 0;
    std::uint64_t inode = 0;
    unsigned permissions = 0; // POSIX permission bits (Windows: 0444 when read-only, else 0666)
};

// stat(), lstat(), fstat(): 0, or the errno value (ENOENT, EACCES, ENOTDIR ...).
int fileInfo(const std::string& path, FileInfo& info); // symbolic links followed
int linkInfo(const std::string& path, FileInfo& info); // a symbolic link itself
int openFileInfo(int fd, FileInfo& info);
bool exists(const std::string& path);      // anything, symbolic links followed
bool isDirectory(const std::string& path); // symbolic links followed

enum class OpenFor {
    Read,         // an existing file, read-only; never waits for a FIFO's writer, never becomes
                  // the controlling terminal
    WriteInPlace, // an existing file or device written where it is: not created, not truncated
    CreateNew,    // a new file (0666 less the umask), write-only; EEXIST if the name is taken
    Append,       // an existing file, appended to
};
// A file descriptor (close-on-exec, binary), or -1 with errno set.
int openFile(const std::string& path, OpenFor how);
// fopen() in binary mode ("rb", "wb"), or nullptr with errno set.
std::FILE* openStream(const std::string& path, const char* mode);

// read() and write(), and their positional forms pread() and pwrite(): bytes done, 0 at the end
// of a file, or -1 with errno set (EINTR: try again). Descriptors 0, 1 and 2 are the standard
// streams, in binary mode on every system (lut/os/Console.h).
std::ptrdiff_t readBytes(int fd, void* data, std::size_t bytes);
std::ptrdiff_t writeBytes(int fd, const void* data, std::size_t bytes);
std::ptrdiff_t readBytesAt(int fd, void* data, std::size_t bytes, std::uint64_t offset);
std::ptrdiff_t writeBytesAt(int fd, const void* data, std::size_t bytes, std::uint64_t offset);
int syncFile(int fd);  // fsync(): the file's bytes on the disk; 0 or -1 with errno
int closeFile(int fd); // 0 or -1 with errno
// Starts handing the bytes [from, from + bytes) to the disk without waiting (Linux's
// sync_file_range; elsewhere nothing). Advisory: errors show again at syncFile().
void startWriteback(int fd, std::uint64_t from, std::uint64_t bytes);

// unlink() and rmdir(): 0 or -1 with errno. Safe in a signal handler (POSIX: async-signal-safe;
// Windows, where the console's handler runs on a thread of its own: no allocation either). A file
// lutkit still has open is removed too (Windows: as soon as it is closed).
int removeFile(const char* path) noexcept;
int removeFolder(const char* path) noexcept;
// rename(): `to` replaced when it exists (atomically where the system can). 0 or -1 with errno.
int renameReplacing(const std::string& from, const std::string& to);
// The same, failing with EEXIST instead of replacing a file at `to`.
int renameNoReplace(const std::string& from, const std::string& to);
// Makes a rename in folder durable (fsync of the folder); 0 where the system needs none, else 0
// or -1 with errno.
int syncFolder(const std::string& folder);
// chmod(): 0 or -1 with errno (Windows: only the read-only attribute, from the 0200 bit).
int setPermissions(const std::string& path, unsigned permissions);
// The longest file name, in bytes of UTF-8, folder takes (NAME_MAX; 255 where it cannot be told).
std::size_t maxNameBytes(const std::string& folder);
// The absolute path with every symbolic link resolved (realpath()), "" when it cannot be told.
std::string realPath(const std::string& path);
// What the symbolic link at path names (readlink()), "" when path is no symbolic link.
std::string linkTarget(const std::string& path);

} // namespace lut::os
