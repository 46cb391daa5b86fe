// SPDX-License-Identifier: Apache-2.0
#include "lut/io/InputFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace lut {

namespace {

// "a FIFO", "a directory", ... for anything but a regular file.
const char* kindOf(mode_t mode) {
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISSOCK(mode))
        return "a socket";
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    return "not a regular file";
}

[[noreturn]] void refuse(const std::string& path, mode_t mode) {
    const char* kind = kindOf(mode);
    if (std::strcmp(kind, "not a regular file") == 0)
        throw Error(path + ": is not a regular file");
    throw Error(path + ": is " + kind + ", not a regular file");
}

class Fd {
public:
    explicit Fd(int fd) : m_fd(fd) {}
    ~Fd() {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return m_fd; }

private:
    int m_fd;
};

// Files from this size on are read into an anonymous mapping with huge pages.
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHugeThreshold = std::size_t(1) << 20;

bool sameTime(const struct stat& a, const struct stat& b) {
    return a.st_mtim.tv_sec == b.st_mtim.tv_sec && a.st_mtim.tv_nsec == b.st_mtim.tv_nsec;
}

} // namespace

void checkRegularInput(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw Error(path + ": cannot open: " + std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        refuse(path, st.st_mode);
}

FileBytes::~FileBytes() {
    if (m_mapped)
        ::munmap(m_data, m_capacity);
    else
        delete[] m_data;
}

FileBytes::FileBytes(FileBytes&& other) noexcept
    : m_data(std::exchange(other.m_data, nullptr)), m_size(std::exchange(other.m_size, 0)),
      m_capacity(std::exchange(other.m_capacity, 0)),
      m_mapped(std::exchange(other.m_mapped, false)) {}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
    if (this != &other) {
        FileBytes old(std::move(*this));
        m_data = std::exchange(other.m_data, nullptr);
        m_size = std::exchange(other.m_size, 0);
        m_capacity = std::exchange(other.m_capacity, 0);
        m_mapped = std::exchange(other.m_mapped, false);
    }
    return *this;
}

FileBytes readFileBytes(const std::string& path, std::size_t maxBytes, const char* limitName) {
    checkRegularInput(path);
    const Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
    if (fd.get() < 0)
        throw Error(path + ": cannot open: " + std::strerror(errno));
    struct stat before {};
    if (::fstat(fd.get(), &before) != 0)
        throw Error(path + ": cannot read: " + std::strerror(errno));
    if (!S_ISREG(before.st_mode))
        refuse(path, before.st_mode);
    // Regular files ignore O_NONBLOCK; cleared anyway so reads behave as documented.
    const int flags = ::fcntl(fd.get(), F_GETFL);
    if (flags >= 0)
        ::fcntl(fd.get(), F_SETFL, flags & ~O_NONBLOCK);
    const auto size = static_cast<std::uint64_t>(before.st_size);
    if (size > maxBytes)
        throw LimitError(path + ": file is " + std::to_string(size) + " bytes, over the limit of " +
                         std::to_string(maxBytes) + " bytes" +
                         (limitName ? std::string(" (") + limitName + ")" : std::string()));

    // One byte more than the size, so a file that grows while it is read is noticed.
    FileBytes out;
    const std::size_t want = static_cast<std::size_t>(size) + 1;
    if (want >= kHugeThreshold) {
        const std::size_t len = (want + kHugePage - 1) / kHugePage * kHugePage;
        void* p = ::mmap(nullptr, len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED)
            throw outOfMemory(path, "reading the file", want);
        ::madvise(p, len, MADV_HUGEPAGE);
        out.m_data = static_cast<char*>(p);
        out.m_capacity = len;
        out.m_mapped = true;
    } else {
        out.m_data = allocating(path, "reading the file", want, [&] { return new char[want]; });
        out.m_capacity = want;
    }
    std::size_t done = 0;
    while (done < want) {
        const ssize_t n = ::read(fd.get(), out.m_data + done, want - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            throw Error(path + ": cannot read: " + std::strerror(errno));
        if (n == 0)
            break;
        done += static_cast<std::size_t>(n);
    }
    struct stat after {};
    if (::fstat(fd.get(), &after) != 0)
        throw Error(path + ": cannot read: " + std::strerror(errno));
    if (done != size || after.st_size != before.st_size || !sameTime(before, after))
        throw Error(path + ": the file changed while being read (" +
                    (after.st_size != before.st_size
                         ? std::to_string(size) + " bytes when opened, " +
                               std::to_string(after.st_size) + " bytes now)"
                         : std::string("written to by another program)")));
    out.m_size = done;
    return out;
}

std::string readFile(const std::string& path, std::size_t maxBytes, const char* limitName) {
    const FileBytes bytes = readFileBytes(path, maxBytes, limitName);
    return allocating(path, "reading the file", bytes.size(),
                      [&] { return std::string(bytes.view()); });
}

Error outOfMemory(const std::string& path, const std::string& what, std::uint64_t bytes) {
    char mib[32];
    std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return Error(path + ": out of memory: " + what + " needs " + std::to_string(bytes) +
                 " bytes (" + mib + " MiB)");
}

} // namespace lut
