#pragma once
// What every OpenColorIO bridge needs (OcioReader.cpp, OcioBaker.cpp): OCIO's multi-line
// messages made one line, an OcioSession that serialises OCIO use and turns its log into
// diagnostics (the library must not print).
// OCIO is touched only inside read()/write(): nothing here runs at start-up (no static OCIO
// objects), which keeps `lutkit info small.cube` fast.
#include "lut/Error.h"

#include <OpenColorIO/OpenColorIO.h>

#include <mutex>
#include <string>
#include <vector>

namespace lut::formats {

namespace OCIO = OCIO_NAMESPACE;

// OCIO's messages span several lines; ours are one line each.
std::string oneLine(const char* message);

// Serialises OCIO use (its caches and our log sink are global) and gathers its log lines.
class OcioSession {
public:
    explicit OcioSession(const std::string& path);
    ~OcioSession();
    OcioSession(const OcioSession&) = delete;
    OcioSession& operator=(const OcioSession&) = delete;
    // Appends what OCIO logged since the session began (or the last call) as Info diagnostics.
    void appendDiagnostics(Diagnostics& out);

private:
    static inline std::mutex s_mutex;
    std::unique_lock<std::mutex> m_lock;
    std::string m_path;
    std::vector<std::string> m_log;
};

// A diagnostic for path (Info unless told otherwise).
Diagnostic ocioDiagnostic(const std::string& path, std::string message,
                          Diagnostic::Severity severity = Diagnostic::Severity::Info);

} // namespace lut::formats
