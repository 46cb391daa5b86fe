// SPDX-License-Identifier: Apache-2.0
#pragma once
// Bytes in and out for the native codecs: a file read with pread (never mapped: a file that
// shrinks while it is read must be an error, not SIGBUS) or bytes in memory (standard input); an
// output through lut::OutputFile, or kept in memory first when the codec must seek and the output
// cannot (an OpenEXR file to standard output).
#include "lut/io/OutputFile.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lut::formats {

// An allocator whose resize() leaves new bytes as they come (no zero-fill): for buffers a decoder
// or a read overwrites whole, where clearing megabytes first only costs time.
template <class T> struct UninitAllocator : std::allocator<T> {
    template <class U> struct rebind { using other = UninitAllocator<U>; };
    UninitAllocator() = default;
    template <class U> UninitAllocator(const UninitAllocator<U>&) noexcept {}
    template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
    template <class U, class... A> void construct(U* p, A&&... a) {
        ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
};
using UninitBytes = std::vector<unsigned char, UninitAllocator<unsigned char>>;

class ByteReader {
public:
    // path "-" is not accepted here: pass standard input's bytes as memory.
    ByteReader(const std::string& path, std::string memory);
    ~ByteReader();
    ByteReader(const ByteReader&) = delete;
    ByteReader& operator=(const ByteReader&) = delete;

    const std::string& path() const { return m_path; }
    std::uint64_t size() const { return m_size; }
    std::uint64_t tell() const { return m_pos; }
    void seek(std::uint64_t pos) { m_pos = pos; }
    // Up to n bytes at the current position; returns how many (fewer only at the end).
    std::size_t read(void* dst, std::size_t n);
    std::size_t pread(void* dst, std::size_t n, std::uint64_t offset) const;
    // The first n bytes (fewer if the file is shorter).
    std::string head(std::size_t n) const;

private:
    std::string m_path;
    std::string m_memory;
    bool m_inMemory = false;
    int m_fd = -1;
    std::uint64_t m_size = 0;
    std::uint64_t m_pos = 0;
};

// Sequential reads of a ByteReader through a window (one pread per window of `block` bytes): the
// input of the run-length decoders (BmpCodec.cpp, TgaCodec.cpp), which take a few bytes at a time
// and jump back to a row's first packet.
class ByteWindow {
public:
    explicit ByteWindow(const ByteReader& in, std::size_t block = std::size_t(1) << 16);
    std::uint64_t tell() const { return m_pos; }
    void seek(std::uint64_t pos) { m_pos = pos; }
    // n bytes (at most the block) at the current position, which moves past them; nullptr when
    // the file ends before them (the position then stays).
    const unsigned char* take(std::size_t n) {
        if (m_pos < m_start || m_pos + n > m_start + m_len)
            refill();
        if (m_pos + n > m_start + m_len)
            return nullptr;
        const unsigned char* p = m_buf.data() + (m_pos - m_start);
        m_pos += n;
        return p;
    }

private:
    void refill();
    const ByteReader& m_in;
    UninitBytes m_buf;
    std::uint64_t m_start = 0; // the file offset of m_buf[0]
    std::size_t m_len = 0;
    std::uint64_t m_pos = 0;
};

// Bytes to an output: straight to the OutputFile, or (seekable writes to a stream) kept in
// memory and written at finish().
class ByteWriter {
public:
    ByteWriter(const OutputTarget& target, bool needsSeek);
    void write(const void* data, std::size_t n);
    void pwrite(const void* data, std::size_t n, std::uint64_t offset);
    std::uint64_t size() const { return m_size; }
    const std::string& path() const { return m_file.path(); }
    const std::string& tempPath() const { return m_file.tempPath(); }
    void commit(const std::function<void(const std::string&)>& verify = {});
    [[noreturn]] void fail(const std::string& reason) { m_file.fail(reason); }

private:
    OutputFile m_file;
    bool m_buffer = false;
    std::string m_memory;
    std::uint64_t m_size = 0;
};

} // namespace lut::formats
