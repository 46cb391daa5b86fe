// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioSession.h"

#include <utility>

namespace lut::formats {

namespace {

// OCIO's messages span several lines; ours are one line each.
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

// OCIO reports warnings through a global logging callback; the library must not print, so we
// collect them and hand them back as diagnostics of the read/write that produced them.
std::mutex g_logMutex;
std::vector<std::string>* g_logSink = nullptr;

} // namespace

void installOcioLogSink() {
    static std::once_flag once;
    std::call_once(once, [] {
        // Outside a session (OCIO used directly, as lutkit bench does) messages are dropped.
        // Debug and info lines (OCIO_LOGGING_LEVEL=debug) are OCIO's own tracing, not news
        // about the file: only warnings and errors become diagnostics, without OCIO's prefix.
        OCIO::SetLoggingFunction([](const char* message) {
            if (!message)
                return;
            std::string line = oneLine(message);
            for (const char* quiet : {"[OpenColorIO Debug]", "[OpenColorIO Info]"})
                if (line.rfind(quiet, 0) == 0)
                    return;
            for (const char* prefix : {"[OpenColorIO Warning]: ", "[OpenColorIO Error]: "})
                if (line.rfind(prefix, 0) == 0)
                    line.erase(0, std::string(prefix).size());
            std::lock_guard lock(g_logMutex);
            if (g_logSink)
                g_logSink->push_back(std::move(line));
        });
    });
}

namespace {

// C++ library messages that mean "a size in the file was believed": a reader asked for more
// than can exist or be allocated.
// clang-format off
constexpr const char* kSizeMessages[] = {
    "vector::reserve",
    "vector::_M_default_append",
    "vector::_M_realloc_insert",
    "vector::_M_fill_insert",
    "cannot create std::vector larger than max_size()",
    "basic_string::_M_create",
    "basic_string::_M_replace_aux",
    "std::bad_array_new_length",
};
// clang-format on

// Replaces a bare library message at the end of text (after "failed with: " or alone) by what it
// means.
std::string explain(std::string text) {
    for (const char* m : kSizeMessages) {
        const std::string msg(m);
        if (text.size() >= msg.size() &&
            text.compare(text.size() - msg.size(), msg.size(), msg) == 0)
            return text.substr(0, text.size() - msg.size()) +
                   "a size declared in the file is too large to allocate (" + msg + ")";
    }
    const std::string badAlloc = "std::bad_alloc";
    if (text.size() >= badAlloc.size() &&
        text.compare(text.size() - badAlloc.size(), badAlloc.size(), badAlloc) == 0)
        return text.substr(0, text.size() - badAlloc.size()) + "out of memory (std::bad_alloc)";
    return text;
}

} // namespace

std::string ocioMessage(const char* what) {
    return explain(oneLine(what));
}

std::string ocioFailure(const std::string& path, const std::string& doing, const char* what) {
    const std::string text = ocioMessage(what);
    if (doing == "loading the file")
        return path + ": OpenColorIO cannot read it: " + text;
    return path + ": OpenColorIO failed while " + doing + ": " + text;
}

OcioSession::OcioSession(const std::string& path) : m_path(path) {
    installOcioLogSink();
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
