// SPDX-License-Identifier: Apache-2.0
#include "lut/io/AtomicFile.h"

#include "lut/Error.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <random>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace lut {

namespace {

std::string folderOf(const std::string& path) {
    const std::string dir = fs::path(path).parent_path().string();
    return dir.empty() ? "." : dir;
}

// The longest file name the output's folder takes (NAME_MAX, 255 on Linux file systems).
std::size_t nameMax(const std::string& dir) {
    const long n = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    return n > 0 ? static_cast<std::size_t>(n) : 255;
}

std::string randomTag() {
    static const char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    thread_local std::mt19937 rng{std::random_device{}() ^ static_cast<unsigned>(::getpid())};
    std::string tag(6, 'a');
    for (char& c : tag)
        c = kChars[rng() % (sizeof(kChars) - 1)];
    return tag;
}

// ".STEM.tmpTAG.EXT" beside the output: hidden, in the same folder (so the rename is atomic),
// ending in the output's extension (OpenImageIO picks its writer by it). The stem is shortened
// (at a UTF-8 character boundary) so the name fits the folder's NAME_MAX even when the output's
// own name is 255 bytes long.
std::string tempPathFor(const std::string& path, const std::string& tag) {
    const fs::path p(path);
    std::string ext = p.extension().string();
    if (ext.size() > 32)
        ext.clear(); // not a format's extension; the name must fit
    std::string stem = p.stem().string();
    const std::size_t fixed = 1 + 4 + tag.size() + ext.size(); // "." ".tmp" TAG EXT
    const std::size_t limit = nameMax(folderOf(path));
    if (stem.size() + fixed > limit) {
        std::size_t keep = limit > fixed ? limit - fixed : 0;
        while (keep > 0 && (static_cast<unsigned char>(stem[keep]) & 0xC0) == 0x80)
            --keep; // never cut a multi-byte character
        stem.resize(keep);
    }
    return (p.parent_path() / ("." + stem + ".tmp" + tag + ext)).string();
}

std::string errnoText(int err) {
    return std::strerror(err);
}

// rename(), failing with EEXIST instead of replacing a file at `to`.
int renameNoReplace(const char* from, const char* to) {
#ifdef RENAME_NOREPLACE
    if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_NOREPLACE) == 0)
        return 0;
    if (errno != EINVAL && errno != ENOSYS)
        return -1;
#endif
    // File systems without it: link() fails when the name exists.
    if (::link(from, to) == 0) {
        ::unlink(from);
        return 0;
    }
    if (errno == EEXIST)
        return -1;
    struct stat st {};
    if (::lstat(to, &st) == 0) {
        errno = EEXIST;
        return -1;
    }
    return ::rename(from, to); // no hard links either (FAT): the check above is the best left
}

} // namespace

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)) {
    throwIfInterrupted(m_path);
    struct stat st {};
    m_existed = ::lstat(m_path.c_str(), &st) == 0;
    for (int attempt = 0;; ++attempt) {
        m_tempPath = tempPathFor(m_path, randomTag());
        // Registered before it exists, so a signal between the two cannot leave it behind.
        m_registration = TempPathRegistration(m_tempPath);
        m_fd = ::open(m_tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (m_fd >= 0)
            break;
        const int err = errno;
        m_registration.release();
        if (err != EEXIST || attempt == 15) {
            m_done = true;
            throw Error(m_path + ": cannot write: " + errnoText(err));
        }
    }
    if (interrupted()) {
        removeTemp();
        throw InterruptedError(m_path + ": interrupted");
    }
}

AtomicFile::~AtomicFile() {
    if (!m_done)
        removeTemp();
}

void AtomicFile::removeTemp() noexcept {
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
    ::unlink(m_tempPath.c_str());
    m_registration.release();
    m_done = true;
}

std::string AtomicFile::userFacing(std::string text) const {
    // Messages name the output, never the hidden temporary file (full path, then bare name).
    const std::string tempName = fs::path(m_tempPath).filename().string();
    const std::string name = fs::path(m_path).filename().string();
    for (std::size_t at; (at = text.find(m_tempPath)) != std::string::npos;)
        text.replace(at, m_tempPath.size(), m_path);
    for (std::size_t at; (at = text.find(tempName)) != std::string::npos;)
        text.replace(at, tempName.size(), name);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    for (char& c : text)
        if (c == '\n')
            c = ' '; // one line
    return text;
}

// What writing to the temporary file reports now: a writer that lost ENOSPC or EDQUOT inside
// its own buffering shows it again here. At most 256 KiB are written, on failure paths only.
std::string AtomicFile::probeWriteError() const {
    const int fd = ::open(m_tempPath.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT ? std::string() : errnoText(errno);
    static const std::vector<char> zeros(std::size_t(64) << 10, '\0');
    int err = 0;
    for (int i = 0; i < 4 && err == 0; ++i) {
        const ssize_t n = ::write(fd, zeros.data(), zeros.size());
        if (n < 0 && errno != EINTR)
            err = errno;
    }
    if (err == 0 && ::fsync(fd) != 0)
        err = errno;
    ::close(fd);
    return err ? errnoText(err) : std::string();
}

void AtomicFile::fail(const std::string& writerMessage) {
    if (interrupted()) {
        removeTemp();
        throw InterruptedError(m_path + ": interrupted");
    }
    std::string reason = m_done ? std::string() : probeWriteError();
    if (reason.empty())
        reason = userFacing(writerMessage);
    if (reason.empty())
        reason = "unknown error";
    removeTemp();
    throw Error(m_path + ": cannot write: " + reason);
}

void AtomicFile::write(std::string_view bytes) {
    if (m_fd < 0)
        throw Error(m_path + ": cannot write: the file is already closed");
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            const int err = errno;
            removeTemp();
            if (interrupted())
                throw InterruptedError(m_path + ": interrupted");
            throw Error(m_path + ": cannot write: " + errnoText(err));
        }
        done += static_cast<std::size_t>(n);
    }
}

void AtomicFile::commit() {
    commit(Checks{});
}

void AtomicFile::commit(const Verifier& verify) {
    commit(Checks{std::nullopt, verify});
}

void AtomicFile::commit(const Checks& checks) {
    if (m_done)
        throw Error(m_path + ": cannot write: the file was already committed or abandoned");
    auto failErrno = [&](int err) {
        removeTemp();
        if (interrupted())
            throw InterruptedError(m_path + ": interrupted");
        throw Error(m_path + ": cannot write: " + errnoText(err));
    };
    throwIfInterrupted(m_path);
    // 1. Our descriptor: a close error is a write error on some file systems (NFS).
    if (m_fd >= 0) {
        const int rc = ::close(m_fd);
        m_fd = -1;
        if (rc != 0)
            failErrno(errno);
    }
    // 2. The file as written: regular, not empty, of the size promised, accepted by the verifier.
    const int fd = ::open(m_tempPath.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        failErrno(errno);
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd);
        failErrno(err);
    }
    const auto size = static_cast<std::uint64_t>(st.st_size);
    std::string problem;
    if (!S_ISREG(st.st_mode))
        problem = "the written file is not a regular file";
    else if (checks.size && size != *checks.size)
        problem = "only " + std::to_string(size) + " of " + std::to_string(*checks.size) +
                  " bytes reached the file";
    else if (!checks.size && size == 0)
        problem = "the writer left an empty file";
    if (!problem.empty()) {
        ::close(fd);
        fail(problem);
    }
    if (checks.verify) {
        try {
            checks.verify(m_tempPath);
        } catch (const std::exception& e) {
            ::close(fd);
            fail(e.what());
        }
    }
    // 3. Durable before it replaces anything.
    if (::fsync(fd) != 0) {
        const int err = errno;
        ::close(fd);
        failErrno(err);
    }
    ::close(fd);
    // Keep the permissions of the file being replaced (a read-only or group-writable output).
    struct stat old {};
    if (::stat(m_path.c_str(), &old) == 0 && S_ISREG(old.st_mode))
        ::chmod(m_tempPath.c_str(), old.st_mode & 07777);
    throwIfInterrupted(m_path);
    // A new output is created exclusively: if another program made a file there meanwhile, it
    // stays, and this write fails naming it (lut::checkOutput's exclusive outputs).
    const bool exclusive = !m_existed || isExclusiveOutput(m_path);
    if ((exclusive ? renameNoReplace(m_tempPath.c_str(), m_path.c_str())
                   : ::rename(m_tempPath.c_str(), m_path.c_str())) != 0) {
        const int err = errno;
        if (exclusive && err == EEXIST) {
            removeTemp();
            throw Error(m_path + ": already exists: another program created it while lutkit was "
                                 "writing it; not replaced");
        }
        failErrno(err);
    }
    forgetExclusiveOutput(m_path);
    m_registration.release();
    m_done = true;
    // The rename itself durable: sync the folder (file systems that cannot are fine).
    const int dir = ::open(folderOf(m_path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        const int rc = ::fsync(dir);
        const int err = errno;
        ::close(dir);
        if (rc != 0 && err != EINVAL && err != EROFS && err != ENOTSUP)
            throw Error(m_path +
                        ": written, but its folder could not be synced: " + errnoText(err));
    }
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    AtomicFile file(path);
    file.write(bytes);
    // Read back and compared: what is on the disk is what was handed over.
    file.commit({bytes.size(), [&](const std::string& temp) {
                     const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
                     if (fd < 0)
                         throw Error(errnoText(errno));
                     std::vector<char> buf(std::min<std::size_t>(bytes.size() + 1, 1 << 20));
                     std::size_t at = 0;
                     for (;;) {
                         const ssize_t n = ::read(fd, buf.data(), buf.size());
                         if (n < 0 && errno == EINTR)
                             continue;
                         if (n < 0) {
                             const int err = errno;
                             ::close(fd);
                             throw Error(errnoText(err));
                         }
                         if (n == 0)
                             break;
                         const auto got = static_cast<std::size_t>(n);
                         if (at + got > bytes.size() ||
                             std::memcmp(buf.data(), bytes.data() + at, got) != 0) {
                             ::close(fd);
                             throw Error("the file read back differs from the bytes written");
                         }
                         at += got;
                     }
                     ::close(fd);
                     if (at != bytes.size())
                         throw Error("the file read back is shorter than the bytes written");
                 }});
}

} // namespace lut
