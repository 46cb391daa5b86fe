// SPDX-License-Identifier: Apache-2.0
#include "lut/io/AtomicFile.h"

#include "lut/Error.h"
#include "lut/os/Files.h"
#include "lut/os/Memory.h"
#include "lut/os/Paths.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <random>
#include <vector>

namespace lut {

namespace {

std::string folderOf(const std::string& path) {
    const std::string dir = os::fromPath(os::toPath(path).parent_path());
    return dir.empty() ? "." : dir;
}

std::string randomTag() {
    static const char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    thread_local std::mt19937 rng{std::random_device{}() ^ static_cast<unsigned>(os::processId())};
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
    const auto p = os::toPath(path);
    std::string ext = os::fromPath(p.extension());
    if (ext.size() > 32)
        ext.clear(); // not a format's extension; the name must fit
    std::string stem = os::fromPath(p.stem());
    const std::size_t fixed = 1 + 4 + tag.size() + ext.size(); // "." ".tmp" TAG EXT
    const std::size_t limit = os::maxNameBytes(folderOf(path));
    if (stem.size() + fixed > limit) {
        std::size_t keep = limit > fixed ? limit - fixed : 0;
        while (keep > 0 && (static_cast<unsigned char>(stem[keep]) & 0xC0) == 0x80)
            --keep; // never cut a multi-byte character
        stem.resize(keep);
    }
    return os::fromPath(p.parent_path() / os::toPath("." + stem + ".tmp" + tag + ext));
}

std::string errnoText(int err) {
    return std::strerror(err);
}

} // namespace

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)) {
    throwIfInterrupted(m_path);
    os::FileInfo st;
    m_existed = os::linkInfo(m_path, st) == 0;
    for (int attempt = 0;; ++attempt) {
        m_tempPath = tempPathFor(m_path, randomTag());
        // Registered before it exists, so a signal between the two cannot leave it behind.
        m_registration = TempPathRegistration(m_tempPath);
        m_fd = os::openFile(m_tempPath, os::OpenFor::CreateNew);
        if (m_fd >= 0)
            break;
        const int err = errno;
        m_registration.release();
        if (err != EEXIST || attempt == 15) {
            m_done = true;
            throw IoError(m_path + ": cannot write: " + errnoText(err));
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
        os::closeFile(m_fd);
    m_fd = -1;
    os::removeFile(m_tempPath.c_str());
    m_registration.release();
    m_done = true;
}

std::string AtomicFile::userFacing(std::string text) const {
    // Messages name the output, never the hidden temporary file (full path, then bare name).
    const std::string tempName = os::fromPath(os::toPath(m_tempPath).filename());
    const std::string name = os::fromPath(os::toPath(m_path).filename());
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
    const int fd = os::openFile(m_tempPath, os::OpenFor::Append);
    if (fd < 0)
        return errno == ENOENT ? std::string() : errnoText(errno);
    static const std::vector<char> zeros(std::size_t(64) << 10, '\0');
    int err = 0;
    for (int i = 0; i < 4 && err == 0; ++i) {
        const std::ptrdiff_t n = os::writeBytes(fd, zeros.data(), zeros.size());
        if (n < 0 && errno != EINTR)
            err = errno;
    }
    if (err == 0 && os::syncFile(fd) != 0)
        err = errno;
    os::closeFile(fd);
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
        const std::ptrdiff_t n = os::writeBytes(m_fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            const int err = errno;
            removeTemp();
            if (interrupted())
                throw InterruptedError(m_path + ": interrupted");
            throw IoError(m_path + ": cannot write: " + errnoText(err));
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
        throw IoError(m_path + ": cannot write: " + errnoText(err));
    };
    throwIfInterrupted(m_path);
    // 1. Our descriptor: a close error is a write error on some file systems (NFS).
    if (m_fd >= 0) {
        const int rc = os::closeFile(m_fd);
        m_fd = -1;
        if (rc != 0)
            failErrno(errno);
    }
    // 2. The file as written: regular, not empty, of the size promised, accepted by the verifier.
    const int fd = os::openFile(m_tempPath, os::OpenFor::Read);
    if (fd < 0)
        failErrno(errno);
    os::FileInfo st;
    if (const int err = os::openFileInfo(fd, st); err != 0) {
        os::closeFile(fd);
        failErrno(err);
    }
    const auto size = st.size;
    std::string problem;
    if (st.type != os::FileType::Regular)
        problem = "the written file is not a regular file";
    else if (checks.size && size != *checks.size)
        problem = "only " + std::to_string(size) + " of " + std::to_string(*checks.size) +
                  " bytes reached the file";
    else if (!checks.size && size == 0)
        problem = "the writer left an empty file";
    if (!problem.empty()) {
        os::closeFile(fd);
        fail(problem);
    }
    if (checks.verify) {
        try {
            checks.verify(m_tempPath);
        } catch (const std::exception& e) {
            os::closeFile(fd);
            fail(e.what());
        }
    }
    // 3. Durable before it replaces anything.
    if (os::syncFile(fd) != 0) {
        const int err = errno;
        os::closeFile(fd);
        failErrno(err);
    }
    os::closeFile(fd);
    // Keep the permissions of the file being replaced (a read-only or group-writable output).
    os::FileInfo old;
    if (os::fileInfo(m_path, old) == 0 && old.type == os::FileType::Regular)
        os::setPermissions(m_tempPath, old.permissions);
    throwIfInterrupted(m_path);
    // A new output is created exclusively: if another program made a file there meanwhile, it
    // stays, and this write fails naming it (lut::checkOutput's exclusive outputs).
    const bool exclusive = !m_existed || isExclusiveOutput(m_path);
    if ((exclusive ? os::renameNoReplace(m_tempPath, m_path)
                   : os::renameReplacing(m_tempPath, m_path)) != 0) {
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
    if (os::syncFolder(folderOf(m_path)) != 0)
        throw IoError(m_path +
                      ": written, but its folder could not be synced: " + errnoText(errno));
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    AtomicFile file(path);
    file.write(bytes);
    // Read back and compared: what is on the disk is what was handed over.
    file.commit({bytes.size(), [&](const std::string& temp) {
                     const int fd = os::openFile(temp, os::OpenFor::Read);
                     if (fd < 0)
                         throw IoError(errnoText(errno));
                     std::vector<char> buf(std::min<std::size_t>(bytes.size() + 1, 1 << 20));
                     std::size_t at = 0;
                     for (;;) {
                         const std::ptrdiff_t n = os::readBytes(fd, buf.data(), buf.size());
                         if (n < 0 && errno == EINTR)
                             continue;
                         if (n < 0) {
                             const int err = errno;
                             os::closeFile(fd);
                             throw IoError(errnoText(err));
                         }
                         if (n == 0)
                             break;
                         const auto got = static_cast<std::size_t>(n);
                         if (at + got > bytes.size() ||
                             std::memcmp(buf.data(), bytes.data() + at, got) != 0) {
                             os::closeFile(fd);
                             throw Error("the file read back differs from the bytes written");
                         }
                         at += got;
                     }
                     os::closeFile(fd);
                     if (at != bytes.size())
                         throw Error("the file read back is shorter than the bytes written");
                 }});
}

} // namespace lut
