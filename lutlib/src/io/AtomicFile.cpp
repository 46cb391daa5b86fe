#include "lut/io/AtomicFile.h"

#include "lut/Error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lut {

static std::string makeTempPath(const std::string& path) {
    const fs::path p(path);
    std::random_device rd;
    const unsigned long tag =
        (static_cast<unsigned long>(rd()) << 16) ^ static_cast<unsigned long>(::getpid());
    // Hidden, in the same folder (so rename is atomic), ending in the same extension.
    return (p.parent_path() /
            ("." + p.stem().string() + ".tmp" + std::to_string(tag) + p.extension().string()))
        .string();
}

AtomicFile::AtomicFile(std::string path)
    : m_path(std::move(path)), m_tempPath(makeTempPath(m_path)) {}

AtomicFile::~AtomicFile() {
    if (!m_committed)
        std::remove(m_tempPath.c_str());
}

void AtomicFile::commit() {
    if (std::rename(m_tempPath.c_str(), m_path.c_str()) != 0) {
        const int err = errno;
        std::remove(m_tempPath.c_str());
        m_committed = true;
        throw Error(m_path + ": cannot write: " + std::strerror(err));
    }
    m_committed = true;
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    AtomicFile file(path);
    const int fd = ::open(file.tempPath().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        throw Error(path + ": cannot write: " + std::strerror(errno));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            const int err = errno;
            ::close(fd);
            throw Error(path + ": cannot write: " + std::strerror(err));
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0)
        throw Error(path + ": cannot write: " + std::strerror(errno));
    file.commit();
}

void checkNotSameFile(const std::string& input, const std::string& output) {
    std::error_code ec;
    if (!fs::exists(output, ec)) {
        // Not existing yet: only the same path spelled differently can match.
        if (fs::weakly_canonical(input, ec) == fs::weakly_canonical(output, ec))
            throw Error(output + ": output is the same file as input " + input +
                        "; refusing to overwrite it");
        return;
    }
    if (fs::equivalent(input, output, ec) && !ec)
        throw Error(output + ": output is the same file as input " + input +
                    " (same path or a link to it); refusing to overwrite it");
}

} // namespace lut
