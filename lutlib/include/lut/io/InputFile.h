// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading input files safely, in one place: every LUT reader goes through here before it reads a
// byte (and readers that hand a path to a library, OpenColorIO or OpenImageIO, call
// checkRegularInput first).
//  - A FIFO, socket, directory or device is refused with one line before it is opened for
//    reading: opening a FIFO blocks until a writer comes, and a device may never end.
//  - Files are read into memory, never mapped (a mapped file that shrinks while it is read kills
//    the process with SIGBUS); the size and modification time are compared before and after.
//  - Sizes are checked before anything is allocated, and an allocation that fails names the file
//    and the size asked for instead of escaping as std::bad_alloc.
#include "lut/Error.h"
#include "lut/io/MemoryLimit.h"

#include <cstddef>
#include <cstdint>
#include <new>
#include <string>
#include <string_view>

namespace lut {

enum class LimitId; // lut/LimitError.h

// Throws lut::Error unless path names a regular file (symbolic links followed), without opening
// it: "PATH: is a FIFO, not a regular file" (or a socket, a directory, a character device, a
// block device), or "PATH: cannot open: <reason>" when it cannot be looked at.
void checkRegularInput(const std::string& path);

// A whole file's bytes in memory. Large files live in an anonymous mapping that asks for
// transparent huge pages, so filling it costs a few page faults instead of one per 4 KiB (on a
// virtual machine, first touches of fresh memory cost as much as the copy itself). Move-only.
class FileBytes {
public:
    FileBytes() = default;
    ~FileBytes();
    FileBytes(FileBytes&& other) noexcept;
    FileBytes& operator=(FileBytes&& other) noexcept;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;

    std::string_view view() const { return {m_data, m_size}; }
    std::size_t size() const { return m_size; }

private:
    template <class Refuse>
    friend FileBytes readWholeFile(const std::string&, std::size_t, const Refuse&);
    char* m_data = nullptr;
    std::size_t m_size = 0;
    std::size_t m_capacity = 0; // bytes allocated (mapped when m_mapped)
    bool m_mapped = false;
};

// Reads a whole regular file into memory. Refuses what checkRegularInput refuses, checked again
// on the opened file (opened with O_NONBLOCK, so a path swapped for a FIFO in between cannot
// block either); a file larger than maxBytes with lut::LimitError before reading it ("PATH: file
// is N bytes, over the limit of M bytes", followed by " (limitName)" when given); and a file that
// changes while it is read: "PATH: the file changed while being read (N bytes when opened, M
// bytes now)". A failed allocation is outOfMemory() naming the file's size.
FileBytes readFileBytes(const std::string& path, std::size_t maxBytes,
                        const char* limitName = nullptr);
// The same past a limit of lut/Limits.h: a FileLimitError naming it (lut/LimitError.h), so a
// front end can tell which limit without reading the message (the text is the same).
FileBytes readFileBytes(const std::string& path, std::size_t maxBytes, LimitId limit);
// The same as a std::string (for small files and callers that keep the bytes).
std::string readFile(const std::string& path, std::size_t maxBytes,
                     const char* limitName = nullptr);

// The error for an allocation that failed while reading path:
// "PATH: out of memory: WHAT needs N bytes (X MiB)".
Error outOfMemory(const std::string& path, const std::string& what, std::uint64_t bytes);

// Runs fn(), once bytes were checked against the memory limit (lut/io/MemoryLimit.h: a
// LimitError past it); a std::bad_alloc it throws becomes outOfMemory(path, what, bytes).
template <class Fn>
decltype(auto) allocating(const std::string& path, const std::string& what, std::uint64_t bytes,
                          Fn&& fn) {
    checkMemoryLimit(path, what, bytes);
    try {
        return fn();
    } catch (const std::bad_alloc&) {
        throw outOfMemory(path, what, bytes);
    }
}

} // namespace lut
