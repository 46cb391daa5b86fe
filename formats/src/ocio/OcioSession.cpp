#include "ocio/OcioSession.h"

#include <utility>

namespace lut::formats {

std::string oneLine(const char* message) {
    std::string out;
    bool space = false;
    for (const char* p = message; p && *p; ++p) {
        const bool ws = *p == '\n' || *p == '\r' || *p == '\t' || *p == ' ';
        if (ws) {
            space = !out.empty();
            continue;
        }
        if (space)
            out += ' ';
        space = false;
        out += *p;
    }
    return out;
}

namespace {

// OCIO reports warnings through a global logging callback; the library must not print, so we
// collect them and hand them back as diagnostics of the read/write that produced them.
std::mutex g_logMutex;
std::vector<std::string>* g_logSink = nullptr;

void initOcio() {
    static std::once_flag once;
    std::call_once(once, [] {
        OCIO::SetLoggingFunction([](const char* message) {
            std::lock_guard lock(g_logMutex);
            if (g_logSink && message) {
                g_logSink->push_back(oneLine(message));
            }
        });
    });
}

} // namespace

OcioSession::OcioSession(const std::string& path) : m_path(path) {
    initOcio();
    m_lock = std::unique_lock(s_mutex);
    std::lock_guard lock(g_logMutex);
    g_logSink = &m_log;
}

OcioSession::~OcioSession() {
    std::lock_guard lock(g_logMutex);
    g_logSink = nullptr;
}

void OcioSession::appendDiagnostics(Diagnostics& out) {
    std::lock_guard lock(g_logMutex);
    for (const auto& m : m_log)
        out.push_back(ocioDiagnostic(m_path, "OpenColorIO: " + m));
    m_log.clear();
}

Diagnostic ocioDiagnostic(const std::string& path, std::string message,
                          Diagnostic::Severity severity) {
    Diagnostic d;
    d.severity = severity;
    d.path = path;
    d.message = std::move(message);
    return d;
}

} // namespace lut::formats
