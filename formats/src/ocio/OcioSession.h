// SPDX-License-Identifier: Apache-2.0
#pragma once
// What every OpenColorIO bridge needs (OcioReader.cpp, OcioWriters.cpp): OCIO's multi-line
// messages made one line, an OcioSession that serialises OCIO use and turns its log into
// diagnostics (the library must not print), and the one way an OCIO failure becomes a lut::Error.
// OCIO is touched only inside read()/write(): nothing here runs at start-up (no static OCIO
// objects), which keeps `lutkit info small.cube` fast.
#include "lut/Error.h"

#include <OpenColorIO/OpenColorIO.h>

#include <mutex>
#include <string>
#include <vector>

namespace lut::formats {

namespace OCIO = OCIO_NAMESPACE;

// An exception's message from inside OpenColorIO as one line (OCIO's span several). A bare C++
// library message at its end (std::length_error's "vector::reserve" from a reader that believed
// a size in the file, std::bad_alloc) is explained instead of quoted alone.
std::string ocioMessage(const char* what);

// The one line for an exception thrown while OpenColorIO was `doing` something with path (e.g.
// "loading the file", "sampling the processor"): "PATH: OpenColorIO cannot read it: ..." while
// loading, "PATH: OpenColorIO failed while DOING: ..." later.
std::string ocioFailure(const std::string& path, const std::string& doing, const char* what);

// An OpenColorIO message about the file `path`, short: the reason alone (the format's own words,
// without the wrapper of its FileTransform: "The specified transform file '...' could not be
// loaded. All formats have been tried ..."), the path taken out (lutkit names it first), and the
// line (and column) where OpenColorIO gives one ("At line 7:", "error at line 8, column 1:") as
// numbers for "PATH:LINE:COL:". Messages of 482 characters naming the file three times became
// "bad.spi1d:7: OpenColorIO cannot read it: spi1d: Malformed LUT line (zz)".
struct OcioReason {
    std::string text;
    int line = 0;   // 0: not given
    int column = 0; // 0: not given
};
OcioReason shortOcioMessage(const std::string& path, std::string text);

// Routes OpenColorIO's log to the session in progress (idempotent; see LibraryMessages.h).
void installOcioLogSink();

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
