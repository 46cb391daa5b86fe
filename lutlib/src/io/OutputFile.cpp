// SPDX-License-Identifier: Apache-2.0
#include "lut/io/OutputFile.h"

#include "lut/io/AtomicFile.h"
#include "lut/os/Files.h"

#include <cerrno>
#include <cstring>
#include <string_view>

namespace lut {

namespace {

constexpr int kStdout = 1;
constexpr int kStderr = 2;

// The descriptor a path names when it is one of the process's own streams (/dev/stdout,
// /dev/fd/1, /proc/self/fd/1): reopening those would start at offset 0 of whatever the stream is
// (a file the shell opened with >>, say), so they are written through the open descriptor.
int ownStreamFd(const std::string& path) {
    std::string p = os::linkTarget(path);
    if (p.empty())
        p = path;
    if (p == "/dev/stdout")
        return kStdout;
    if (p == "/dev/stderr")
        return kStderr;
    for (const char* prefix : {"/proc/self/fd/", "/dev/fd/"}) {
        const std::string_view pre(prefix);
        if (p.size() > pre.size() && p.compare(0, pre.size(), pre) == 0) {
            int fd = 0;
            for (std::size_t i = pre.size(); i < p.size(); ++i) {
                if (p[i] < '0' || p[i] > '9' || fd > 1000000)
                    return -1;
                fd = fd * 10 + (p[i] - '0');
            }
            return fd;
        }
    }
    return -1;
}

} // namespace

OutputFile::OutputFile(const OutputTarget& target) : m_target(target) {
    if (m_target.kind == OutputKind::Memory) {
        if (!m_target.memory)
            throw Error(m_target.path + ": cannot write: no memory to write to");
        return;
    }
    if (m_target.kind == OutputKind::Stdout) {
        m_fd = kStdout;
        return;
    }
    if (m_target.kind == OutputKind::Special) {
        if (const int own = ownStreamFd(m_target.writePath); own >= 0) {
            m_fd = own;
            return;
        }
        // No O_CREAT, no O_TRUNC: a device or FIFO is written as it is.
        m_fd = os::openFile(m_target.writePath, os::OpenFor::WriteInPlace);
        if (m_fd < 0)
            throw IoError(m_target.path + ": cannot write: " + std::strerror(errno));
        m_ownFd = true;
        return;
    }
    m_atomic = std::make_unique<AtomicFile>(m_target.writePath);
    m_fd = os::openFile(m_atomic->tempPath(), os::OpenFor::WriteInPlace); // created empty
    if (m_fd < 0)
        throw IoError(m_target.path + ": cannot write: " + std::strerror(errno));
    m_ownFd = true;
}

OutputFile::~OutputFile() {
    if (m_ownFd && m_fd >= 0)
        os::closeFile(m_fd);
    // m_atomic's destructor removes the temporary file unless it was committed.
}

const std::string& OutputFile::tempPath() const {
    static const std::string none;
    return m_atomic ? m_atomic->tempPath() : none;
}

void OutputFile::fail(const std::string& reason) {
    m_done = true;
    if (m_ownFd && m_fd >= 0) {
        os::closeFile(m_fd);
        m_fd = -1;
    }
    m_atomic.reset(); // removes the temporary file
    m_memory.clear();
    throw IoError(m_target.path + ": cannot write: " + reason);
}

void OutputFile::checkedWrite(const void* data, std::size_t bytes, std::int64_t offset) {
    if (m_target.kind == OutputKind::Memory) {
        if (m_done)
            throw Error(m_target.path + ": cannot write: the output is closed");
        const std::size_t at = static_cast<std::size_t>(offset);
        if (at + bytes > m_memory.size())
            m_memory.resize(at + bytes);
        if (bytes > 0)
            std::memcpy(m_memory.data() + at, data, bytes);
        return;
    }
    if (m_done || m_fd < 0)
        throw Error(m_target.path + ": cannot write: the output is closed");
    const char* p = static_cast<const char*>(data);
    std::size_t done = 0;
    while (done < bytes) {
        const std::ptrdiff_t n = offset < 0
                                     ? os::writeBytes(m_fd, p + done, bytes - done)
                                     : os::writeBytesAt(m_fd, p + done, bytes - done,
                                                        static_cast<std::uint64_t>(offset) + done);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            fail(std::strerror(errno));
        }
        if (n == 0)
            fail("the system wrote nothing (device full?)");
        done += static_cast<std::size_t>(n);
    }
}

// A regular output's bytes are handed to the disk as they come, every 8 MiB (Linux's
// sync_file_range, which starts the writeback and does not wait for it: os::startWriteback):
// commit()'s fsync then waits for the last few megabytes only instead of the whole file. A 50 MB
// frame's final fsync took 35-67 ms after plain writes, 2-10 ms after these (bench/RESULTS.md,
// issue 27). Advisory: an error here shows again at the fsync, which is what decides.
void OutputFile::startWriteback() {
    constexpr std::uint64_t kStep = std::uint64_t(8) << 20;
    if (!m_atomic || m_fd < 0 || m_size < m_writebackFrom + kStep)
        return;
    os::startWriteback(m_fd, m_writebackFrom, m_size - m_writebackFrom);
    m_writebackFrom = m_size;
}

void OutputFile::write(const void* data, std::size_t bytes) {
    if (seekable()) {
        checkedWrite(data, bytes, static_cast<std::int64_t>(m_size));
    } else {
        checkedWrite(data, bytes, -1);
    }
    m_size += bytes;
    startWriteback();
}

void OutputFile::pwrite(const void* data, std::size_t bytes, std::uint64_t offset) {
    if (!seekable())
        throw Error(m_target.path + ": cannot write: this output cannot seek");
    checkedWrite(data, bytes, static_cast<std::int64_t>(offset));
    if (offset + bytes > m_size)
        m_size = offset + bytes;
    startWriteback();
}

void OutputFile::commit(const std::function<void(const std::string&)>& verify) {
    if (m_done)
        throw Error(m_target.path + ": cannot write: the output is closed");
    if (m_target.kind == OutputKind::Memory) {
        if (m_memory.empty())
            fail("the writer produced no bytes");
        m_done = true;
        *m_target.memory = std::move(m_memory);
        m_memory.clear();
        return;
    }
    if (!m_atomic) {
        m_done = true;
        if (m_ownFd) {
            const int fd = m_fd;
            m_fd = -1;
            if (os::closeFile(fd) != 0 && errno != EINTR)
                throw IoError(m_target.path + ": cannot write: " + std::strerror(errno));
        }
        return;
    }
    if (os::syncFile(m_fd) != 0 && errno != EINVAL)
        fail(std::strerror(errno));
    const int fd = m_fd;
    m_fd = -1;
    if (os::closeFile(fd) != 0)
        fail(std::strerror(errno));
    if (verify) {
        try {
            verify(m_atomic->tempPath());
        } catch (const std::exception& e) {
            std::string why = e.what();
            // The verifier may name the hidden temporary file: show the user's path instead.
            const std::string& temp = m_atomic->tempPath();
            for (std::size_t at; (at = why.find(temp)) != std::string::npos;)
                why.replace(at, temp.size(), m_target.path);
            if (why.rfind(m_target.path + ": ", 0) == 0)
                why.erase(0, m_target.path.size() + 2);
            fail(why);
        }
    }
    m_done = true;
    m_atomic->commit();
}

void writeOutputBytes(const OutputTarget& target, std::string_view bytes) {
    OutputFile out(target);
    out.write(bytes.data(), bytes.size());
    out.commit();
}

} // namespace lut
