// SPDX-License-Identifier: Apache-2.0
#include "imageio/ByteIO.h"

#include "lut/Error.h"
#include "lut/io/InputFile.h"
#include "lut/os/Files.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace lut::formats {

ByteReader::ByteReader(const std::string& path, std::string memory) : m_path(path) {
    if (!memory.empty() || path == "-") {
        m_memory = std::move(memory);
        m_inMemory = true;
        m_size = m_memory.size();
        return;
    }
    checkRegularInput(path);
    m_fd = os::openFile(path, os::OpenFor::Read);
    if (m_fd < 0)
        throw IoError(path + ": cannot open: " + std::strerror(errno));
    os::FileInfo st;
    if (os::openFileInfo(m_fd, st) != 0 || st.type != os::FileType::Regular) {
        os::closeFile(m_fd);
        m_fd = -1;
        throw Error(path + ": is not a regular file");
    }
    m_size = st.size;
}

ByteReader::~ByteReader() {
    if (m_fd >= 0)
        os::closeFile(m_fd);
}

std::size_t ByteReader::pread(void* dst, std::size_t n, std::uint64_t offset) const {
    if (m_inMemory) {
        if (offset >= m_size)
            return 0;
        const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(n, m_size - offset));
        std::memcpy(dst, m_memory.data() + offset, k);
        return k;
    }
    std::size_t done = 0;
    while (done < n) {
        const std::ptrdiff_t r =
            os::readBytesAt(m_fd, static_cast<char*>(dst) + done, n - done, offset + done);
        if (r < 0) {
            if (errno == EINTR)
                continue;
            throw IoError(m_path + ": cannot read: " + std::strerror(errno));
        }
        if (r == 0)
            break;
        done += static_cast<std::size_t>(r);
    }
    return done;
}

std::size_t ByteReader::read(void* dst, std::size_t n) {
    const std::size_t k = pread(dst, n, m_pos);
    m_pos += k;
    return k;
}

std::string ByteReader::head(std::size_t n) const {
    std::string s(n, '\0');
    s.resize(pread(s.data(), n, 0));
    return s;
}

ByteWindow::ByteWindow(const ByteReader& in, std::size_t block) : m_in(in) {
    m_buf.resize(block);
}

void ByteWindow::refill() {
    m_start = m_pos;
    m_len = m_in.pread(m_buf.data(), m_buf.size(), m_pos);
}

ByteWriter::ByteWriter(const OutputTarget& target, bool needsSeek)
    : m_file(target), m_buffer(needsSeek && !m_file.seekable()) {}

void ByteWriter::write(const void* data, std::size_t n) {
    if (m_buffer)
        m_memory.append(static_cast<const char*>(data), n);
    else
        m_file.write(data, n);
    m_size += n;
}

void ByteWriter::pwrite(const void* data, std::size_t n, std::uint64_t offset) {
    if (m_buffer) {
        if (offset + n > m_memory.size())
            m_memory.resize(offset + n);
        std::memcpy(m_memory.data() + offset, data, n);
    } else {
        m_file.pwrite(data, n, offset);
    }
    m_size = std::max<std::uint64_t>(m_size, offset + n);
}

void ByteWriter::commit(const std::function<void(const std::string&)>& verify) {
    if (m_buffer) {
        m_file.write(m_memory.data(), m_memory.size());
        m_memory.clear();
    }
    m_file.commit(verify);
}

} // namespace lut::formats
