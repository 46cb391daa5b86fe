// SPDX-License-Identifier: Apache-2.0
#pragma once
// Verified writes, in one place. Every output file is written to a hidden temporary sibling
// (tempPath(): same folder, so the rename is atomic; same extension, so OpenImageIO picks the same
// format), checked, made durable, and only then renamed over the output:
//  1. the writer's own status (the caller throws before commit() when its writer failed);
//  2. the file: it exists, is not empty, has the expected size when one is given, and passes the
//     caller's verifier (image writers read the file back; LUT writers compare the bytes);
//  3. fsync of the temporary file, rename, fsync of the folder. An output that did not exist
//     when the write began (or that lut::checkOutput found absent under a rule that never
//     replaces) is renamed into place only if it is still absent: a file another program
//     created meanwhile is kept, and commit() throws "PATH: already exists: ...".
// Any failure removes the temporary file, keeps the old output as it was, and throws lut::Error
// "OUTPUT: cannot write: REASON" naming the path the caller gave (never the hidden temporary
// name), REASON being the system's own words when a write to that folder fails now ("No space left
// on device", "Disk quota exceeded"), else the writer's or verifier's message.
// Temporary files are registered for removal on SIGINT/SIGTERM (lut/io/TempFiles.h); once the
// program is interrupted, construction and commit() throw InterruptedError.
#include "lut/io/OutputPolicy.h"
#include "lut/io/ProtectInputs.h" // checkNotSameFile, declared here before
#include "lut/io/TempFiles.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace lut {

class AtomicFile {
public:
    // Creates the empty temporary file (exclusively, mode 0666 less the umask). Throws lut::Error
    // "PATH: cannot write: REASON" when it cannot be created (no such folder, permission, ...).
    explicit AtomicFile(std::string path);
    ~AtomicFile(); // removes the temporary file unless commit() succeeded
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& path() const { return m_path; }
    const std::string& tempPath() const { return m_tempPath; }
    // The temporary file, open for writing (O_WRONLY|O_CLOEXEC), for writers that write
    // themselves; -1 once committed or failed. Writers that open tempPath() by name (OpenImageIO)
    // may ignore it.
    int fd() const { return m_fd; }

    // Appends bytes through fd(); a failed write calls fail() with the system's reason.
    void write(std::string_view bytes);

    // Checks the file (tempPath) before it replaces the output; throws (any std::exception) with a
    // reason to refuse it. Messages may name tempPath: they are shown with the output's path.
    using Verifier = std::function<void(const std::string& tempPath)>;
    struct Checks {
        std::optional<std::uint64_t> size; // the exact size expected; unset = not empty
        Verifier verify;                   // optional
    };
    void commit(); // = commit(Checks{}): the file must exist and not be empty
    void commit(const Verifier& verify);
    void commit(const Checks& checks);

    // Gives up: removes the temporary file and throws lut::Error "PATH: cannot write: REASON".
    // REASON is what a write to the temporary file reports now, if it fails (a full disk that
    // the writer did not report), else writerMessage with tempPath() replaced by path(), else
    // "unknown error". For writers whose own status says they failed.
    [[noreturn]] void fail(const std::string& writerMessage);

private:
    void removeTemp() noexcept;
    std::string probeWriteError() const;
    std::string userFacing(std::string text) const;

    std::string m_path;
    std::string m_tempPath;
    bool m_existed = false; // the output existed when the write began: it may be replaced
    int m_fd = -1;
    bool m_done = false;
    TempPathRegistration m_registration;
};

// Writes bytes to path through AtomicFile, checking the file's size and reading it back to
// compare with bytes before the rename. Throws lut::Error naming path on failure.
void writeFileAtomically(const std::string& path, std::string_view bytes);

} // namespace lut
