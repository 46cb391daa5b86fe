// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioSession.h"

#include <filesystem>
#include <regex>
#include <utility>
#include <vector>

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

namespace {

// The path as OpenColorIO spells it in its messages: the absolute one.
std::vector<std::string> spellings(const std::string& path) {
    std::vector<std::string> out{path};
    std::error_code ec;
    const std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
    if (!ec && abs != path)
        out.insert(out.begin(), abs);
    return out;
}

} // namespace

OcioReason shortOcioMessage(const std::string& path, std::string text) {
    // "The specified transform file 'P' could not be loaded. All formats have been tried.
    // (Enable debug log ...) The format for the file's extension gave the error: 'FMT' failed
    // with: REASON' in P." -> "FMT: REASON"
    if (const auto at = text.rfind("' failed with: "); at != std::string::npos) {
        const auto open = at == 0 ? std::string::npos : text.rfind('\'', at - 1);
        const std::string format =
            open == std::string::npos ? std::string() : text.substr(open + 1, at - open - 1);
        text = text.substr(at + 15);
        if (!format.empty())
            text = format + ": " + text;
    }
    // "Error: Loading the OCIO profile 'P' failed. yaml-cpp: error at line 8, column 1: ..."
    if (text.rfind("Error: Loading the OCIO profile", 0) == 0)
        if (const auto at = text.find(" failed. "); at != std::string::npos)
            text.erase(0, at + 9);
    // The file's name, said by OpenColorIO again and again: once, by lutkit, first.
    for (const std::string& p : spellings(path))
        for (const auto& [form, by] :
             std::vector<std::pair<std::string, std::string>>{{" in " + p + ".", ""},
                                                              {" (" + p + ")", ""},
                                                              {"'" + p + "'", "the file"},
                                                              {p, "the file"}})
            for (std::size_t at; (at = text.find(form)) != std::string::npos;)
                text.replace(at, form.size(), by);
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    OcioReason r;
    // "At line 7: ...", "error at line 8, column 1: ...", "(line 12)".
    static const std::regex kLine(
        R"((?:error )?(?:[Aa]t line|[Ll]ine) \(?(\d+)\)?(?:, column (\d+))?:? ?)");
    std::smatch m;
    if (std::regex_search(text, m, kLine)) {
        r.line = std::stoi(m[1].str());
        if (m[2].matched)
            r.column = std::stoi(m[2].str());
        text.erase(static_cast<std::size_t>(m.position(0)), static_cast<std::size_t>(m.length(0)));
    }
    r.text = text;
    return r;
}

std::string ocioFailure(const std::string& path, const std::string& doing, const char* what) {
    const OcioReason r = shortOcioMessage(path, ocioMessage(what));
    const std::string where =
        path + (r.line > 0 ? ":" + std::to_string(r.line) : std::string()) +
        (r.line > 0 && r.column > 0 ? ":" + std::to_string(r.column) : std::string());
    if (doing == "loading the file")
        return where + ": OpenColorIO cannot read it: " + r.text;
    return where + ": OpenColorIO failed while " + doing + ": " + r.text;
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
