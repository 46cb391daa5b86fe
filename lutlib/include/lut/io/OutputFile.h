// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where an output's bytes go, after checkOutput (lut/io/OutputPolicy.h) said they may: a regular
// file is written to a temporary sibling (lut::AtomicFile) and renamed into place by commit(),
// after the caller's check of the finished file; standard output and special files (devices,
// FIFOs, /dev/stdout) are written in place; an in-memory output (lut::memoryOutput) is a buffer
// handed to the caller's string by commit(). Every write is checked: a short or failed write
// throws lut::Error "OUT: cannot write: REASON" naming the path the user gave, with the system's
// reason ("No space left on device"), and the temporary file is removed by the destructor.
#include "lut/io/OutputPolicy.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace lut {

class AtomicFile;

class OutputFile {
public:
    explicit OutputFile(const OutputTarget& target);
    ~OutputFile(); // not committed: the temporary file is removed (in-place outputs: nothing)
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    const std::string& path() const { return m_target.path; }
    const OutputTarget& target() const { return m_target; }
    // The temporary file of a regular output ("" for in-place and in-memory outputs): readers may
    // open it to check the result before commit().
    const std::string& tempPath() const;
    // Regular and in-memory outputs can be written at any offset (writers that go back to fill in
    // a table).
    bool seekable() const { return !m_target.inPlace(); }

    void write(const void* data, std::size_t bytes);                        // appends
    void pwrite(const void* data, std::size_t bytes, std::uint64_t offset); // seekable() only
    std::uint64_t size() const { return m_size; } // bytes in the file so far

    // Regular outputs: verify(tempPath) (throws to refuse the file), then the rename. In-place
    // outputs: verify is not called (a device cannot be read back). In-memory outputs: verify is
    // not called either (there is no file to reopen; the caller has the bytes and reads them
    // itself if it must); the bytes must not be empty (as lut::AtomicFile requires of a file),
    // then they move to the target's string.
    void commit(const std::function<void(const std::string& tempPath)>& verify = {});
    // Gives up: throws lut::Error "OUT: cannot write: reason" (the temporary file is removed).
    [[noreturn]] void fail(const std::string& reason);

private:
    void checkedWrite(const void* data, std::size_t bytes, std::int64_t offset);
    void startWriteback();

    OutputTarget m_target;
    std::unique_ptr<AtomicFile> m_atomic;
    int m_fd = -1;
    bool m_ownFd = false;
    std::string m_memory; // OutputKind::Memory: the bytes until commit()
    std::uint64_t m_size = 0;
    [[maybe_unused]] std::uint64_t m_writebackFrom = 0; // handed to the disk early (Linux)
    bool m_done = false;
};

// Writes bytes to an output through OutputFile (checkOutput with ExistingOutput::Replace when
// given a path: callers that must refuse existing files check first).
void writeOutputBytes(const OutputTarget& target, std::string_view bytes);

} // namespace lut
