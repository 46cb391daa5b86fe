// SPDX-License-Identifier: Apache-2.0
// lut/os/Files.h on POSIX (Linux, the browser edition's Emscripten): the system calls themselves.
#include "lut/os/Files.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lut::os {

namespace {

FileType typeOf(mode_t mode) {
    if (S_ISREG(mode))
        return FileType::Regular;
    if (S_ISDIR(mode))
        return FileType::Directory;
    if (S_ISLNK(mode))
        return FileType::SymbolicLink;
    if (S_ISFIFO(mode))
        return FileType::Fifo;
    if (S_ISSOCK(mode))
        return FileType::Socket;
    if (S_ISCHR(mode))
        return FileType::CharacterDevice;
    if (S_ISBLK(mode))
        return FileType::BlockDevice;
    return FileType::Other;
}

void fill(const struct stat& st, FileInfo& info) {
    info.type = typeOf(st.st_mode);
    info.size = static_cast<std::uint64_t>(st.st_size);
    info.modifiedNs =
        static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
    info.changedNs = static_cast<std::int64_t>(st.st_ctim.tv_sec) * 1000000000 + st.st_ctim.tv_nsec;
    info.device = static_cast<std::uint64_t>(st.st_dev);
    info.inode = static_cast<std::uint64_t>(st.st_ino);
    info.permissions = static_cast<unsigned>(st.st_mode & 07777);
}

} // namespace

int fileInfo(const std::string& path, FileInfo& info) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        return errno;
    fill(st, info);
    return 0;
}

int linkInfo(const std::string& path, FileInfo& info) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0)
        return errno;
    fill(st, info);
    return 0;
}

int openFileInfo(int fd, FileInfo& info) {
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        return errno;
    fill(st, info);
    return 0;
}

bool exists(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}

bool isDirectory(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

int openFile(const std::string& path, OpenFor how) {
    switch (how) {
    case OpenFor::Read: {
        // O_NONBLOCK: a FIFO put in a regular file's place does not block the open; cleared at
        // once (regular files ignore it, and reads then behave as documented).
        const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd >= 0) {
            const int flags = ::fcntl(fd, F_GETFL);
            if (flags >= 0)
                ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
        }
        return fd;
    }
    case OpenFor::WriteInPlace:
        return ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    case OpenFor::CreateNew:
        return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    case OpenFor::Append:
        return ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    }
    errno = EINVAL;
    return -1;
}

std::FILE* openStream(const std::string& path, const char* mode) {
    return std::fopen(path.c_str(), mode);
}

std::ptrdiff_t readBytes(int fd, void* data, std::size_t bytes) {
    return ::read(fd, data, bytes);
}

std::ptrdiff_t writeBytes(int fd, const void* data, std::size_t bytes) {
    return ::write(fd, data, bytes);
}

std::ptrdiff_t readBytesAt(int fd, void* data, std::size_t bytes, std::uint64_t offset) {
    return ::pread(fd, data, bytes, static_cast<off_t>(offset));
}

std::ptrdiff_t writeBytesAt(int fd, const void* data, std::size_t bytes, std::uint64_t offset) {
    return ::pwrite(fd, data, bytes, static_cast<off_t>(offset));
}

int syncFile(int fd) {
    return ::fsync(fd);
}

int closeFile(int fd) {
    return ::close(fd);
}

void startWriteback(int fd, std::uint64_t from, std::uint64_t bytes) {
#if defined(__linux__)
    ::sync_file_range(fd, static_cast<off_t>(from), static_cast<off_t>(bytes),
                      SYNC_FILE_RANGE_WRITE);
#else
    (void)fd;
    (void)from;
    (void)bytes;
#endif
}

int removeFile(const char* path) noexcept {
    return ::unlink(path);
}

int removeFolder(const char* path) noexcept {
    return ::rmdir(path);
}

int renameReplacing(const std::string& from, const std::string& to) {
    return ::rename(from.c_str(), to.c_str());
}

int renameNoReplace(const std::string& from, const std::string& to) {
#ifdef RENAME_NOREPLACE
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
        return 0;
    if (errno != EINVAL && errno != ENOSYS)
        return -1;
#endif
    // File systems without it: link() fails when the name exists.
    if (::link(from.c_str(), to.c_str()) == 0) {
        ::unlink(from.c_str());
        return 0;
    }
    if (errno == EEXIST)
        return -1;
    struct stat st {};
    if (::lstat(to.c_str(), &st) == 0) {
        errno = EEXIST;
        return -1;
    }
    return ::rename(from.c_str(), to.c_str()); // no hard links either (FAT): the check above is
                                               // the best left
}

int syncFolder(const std::string& folder) {
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0)
        return 0; // a folder that cannot be opened cannot be synced either: nothing to wait for
    const int rc = ::fsync(dir);
    const int err = errno;
    ::close(dir);
    if (rc != 0 && err != EINVAL && err != EROFS && err != ENOTSUP) {
        errno = err;
        return -1;
    }
    return 0;
}

int setPermissions(const std::string& path, unsigned permissions) {
    return ::chmod(path.c_str(), static_cast<mode_t>(permissions & 07777));
}

std::size_t maxNameBytes(const std::string& folder) {
    const long n = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    return n > 0 ? static_cast<std::size_t>(n) : 255;
}

std::string realPath(const std::string& path) {
    char buf[PATH_MAX];
    return ::realpath(path.c_str(), buf) ? std::string(buf) : std::string();
}

std::string linkTarget(const std::string& path) {
    std::vector<char> buf(PATH_MAX);
    const ssize_t n = ::readlink(path.c_str(), buf.data(), buf.size() - 1);
    return n > 0 ? std::string(buf.data(), static_cast<std::size_t>(n)) : std::string();
}

} // namespace lut::os
