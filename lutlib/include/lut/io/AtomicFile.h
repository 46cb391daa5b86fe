#pragma once
#include <string>
#include <string_view>

namespace lut {

// Writing that never leaves a partial file or destroys an existing one: write to tempPath()
// (same folder, same extension, so OpenImageIO picks the same format), then commit() renames it
// into place. The destructor removes the temporary file if commit() was not reached.
class AtomicFile {
public:
    explicit AtomicFile(std::string path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& path() const { return m_path; }
    const std::string& tempPath() const { return m_tempPath; }
    void commit(); // throws lut::Error naming the file if the rename fails

private:
    std::string m_path;
    std::string m_tempPath;
    bool m_committed = false;
};

// Writes bytes to path atomically. Throws lut::Error naming the file on failure.
void writeFileAtomically(const std::string& path, std::string_view bytes);

// Throws lut::Error if output names the same file as input (same path, symlink or hard link).
void checkNotSameFile(const std::string& input, const std::string& output);

} // namespace lut
