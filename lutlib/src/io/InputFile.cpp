// SPDX-License-Identifier: Apache-2.0
#include "lut/io/InputFile.h"

#include "lut/LimitError.h"

#include "lut/os/Files.h"
#include "lut/os/Memory.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace lut {

namespace {

// "a FIFO", "a directory", ... for anything but a regular file.
const char* kindOf(os::FileType type) {
    switch (type) {
    case os::FileType::Fifo:
        return "a FIFO";
    case os::FileType::Socket:
        return "a socket";
    case os::FileType::Directory:
        return "a directory";
    case os::FileType::CharacterDevice:
        return "a character device";
    case os::FileType::BlockDevice:
        return "a block device";
    default:
        return "not a regular file";
    }
}

[[noreturn]] void refuse(const std::string& path, os::FileType type) {
    const char* kind = kindOf(type);
    if (std::strcmp(kind, "not a regular file") == 0)
        throw Error(path + ": is not a regular file");
    throw Error(path + ": is " + kind + ", not a regular file");
}

class Fd {
public:
    explicit Fd(int fd) : m_fd(fd) {}
    ~Fd() {
        if (m_fd >= 0)
            os::closeFile(m_fd);
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

} // namespace

void checkRegularInput(const std::string& path) {
    os::FileInfo st;
    if (const int err = os::fileInfo(path, st); err != 0)
        throw IoError(path + ": cannot open: " + std::strerror(err));
    if (st.type != os::FileType::Regular)
        refuse(path, st.type);
}

FileBytes::~FileBytes() {
    if (m_mapped)
        os::freePages(m_data, m_capacity);
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

// readFileBytes with `tooLarge(size)` throwing for a file over maxBytes.
template <class Refuse>
FileBytes readWholeFile(const std::string& path, std::size_t maxBytes, const Refuse& tooLarge) {
    checkRegularInput(path);
    // Opened without waiting for a writer: a path swapped for a FIFO in between cannot block.
    const Fd fd(os::openFile(path, os::OpenFor::Read));
    if (fd.get() < 0)
        throw IoError(path + ": cannot open: " + std::strerror(errno));
    os::FileInfo before;
    if (const int err = os::openFileInfo(fd.get(), before); err != 0)
        throw IoError(path + ": cannot read: " + std::strerror(err));
    if (before.type != os::FileType::Regular)
        refuse(path, before.type);
    const std::uint64_t size = before.size;
    if (size > maxBytes)
        tooLarge(size);

    // One byte more than the size, so a file that grows while it is read is noticed.
    FileBytes out;
    const std::size_t want = static_cast<std::size_t>(size) + 1;
    if (want >= kHugeThreshold) {
        const std::size_t len = (want + kHugePage - 1) / kHugePage * kHugePage;
        void* p = os::allocatePages(len);
        if (!p)
            throw outOfMemory(path, "reading the file", want);
        out.m_data = static_cast<char*>(p);
        out.m_capacity = len;
        out.m_mapped = true;
    } else {
        out.m_data = allocating(path, "reading the file", want, [&] { return new char[want]; });
        out.m_capacity = want;
    }
    std::size_t done = 0;
    while (done < want) {
        const std::ptrdiff_t n = os::readBytes(fd.get(), out.m_data + done, want - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            throw IoError(path + ": cannot read: " + std::strerror(errno));
        if (n == 0)
            break;
        done += static_cast<std::size_t>(n);
    }
    os::FileInfo after;
    if (const int err = os::openFileInfo(fd.get(), after); err != 0)
        throw IoError(path + ": cannot read: " + std::strerror(err));
    if (done != size || after.size != before.size || after.modifiedNs != before.modifiedNs)
        throw Error(path + ": the file changed while being read (" +
                    (after.size != before.size ? std::to_string(size) + " bytes when opened, " +
                                                     std::to_string(after.size) + " bytes now)"
                                               : std::string("written to by another program)")));
    out.m_size = done;
    return out;
}

namespace {

std::string sizeRefusal(const std::string& path, std::uint64_t size, std::size_t maxBytes) {
    return path + ": file is " + std::to_string(size) + " bytes, over the limit of " +
           std::to_string(maxBytes) + " bytes";
}

} // namespace

FileBytes readFileBytes(const std::string& path, std::size_t maxBytes, const char* limitName) {
    return readWholeFile(path, maxBytes, [&](std::uint64_t size) {
        throw LimitError(sizeRefusal(path, size, maxBytes) +
                         (limitName ? std::string(" (") + limitName + ")" : std::string()));
    });
}

FileBytes readFileBytes(const std::string& path, std::size_t maxBytes, LimitId limit) {
    return readWholeFile(path, maxBytes, [&](std::uint64_t size) {
        throw FileLimitError(limit, sizeRefusal(path, size, maxBytes) + " (", ")");
    });
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
