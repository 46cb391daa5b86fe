// SPDX-License-Identifier: Apache-2.0
// The registry of formats: lookup by name and extension, and the one read and write of a LUT
// file that every front end goes through; see lut/io/FormatRegistry.h.
#include "lut/io/FormatRegistry.h"

#include "lut/Limits.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"
#include "lut/io/LutWriter.h"
#include "lut/io/OutputPolicy.h"
#include "lut/io/StdStreams.h"

#include <algorithm>
#include <cstdio>
#include <new>
#include <optional>

namespace lut {

namespace {

// Whether text is lines that are blank or start with '#' (after blanks), and nothing else.
bool onlyCommentLines(const std::string& text) {
    bool lineStart = true, comment = false;
    for (const char c : text) {
        if (c == '\n' || c == '\r') {
            lineStart = true;
            comment = false;
        } else if (comment) {
            continue;
        } else if (lineStart && (c == ' ' || c == '\t')) {
            continue;
        } else if (lineStart && c == '#') {
            comment = true;
            lineStart = false;
        } else {
            return false;
        }
    }
    return true;
}

} // namespace

FormatRegistry& FormatRegistry::instance() {
    static FormatRegistry registry;
    return registry;
}

void FormatRegistry::add(std::unique_ptr<Format> format) {
    if (byName(format->name()))
        return; // registering twice is harmless
    m_formats.push_back(std::move(format));
}

const Format* FormatRegistry::byName(const std::string& name) const {
    for (const auto& f : m_formats)
        if (f->name() == name)
            return f.get();
    for (const auto& f : m_formats)
        for (const auto& a : f->aliases())
            if (a.name == name)
                return f.get();
    return nullptr;
}

void FormatRegistry::applyAlias(const std::string& name, FormatOptions& options) const {
    for (const auto& f : m_formats) {
        if (f->name() == name)
            return;
        for (const auto& a : f->aliases())
            if (a.name == name) {
                if (!a.attribute.empty() && !options.attribute(a.attribute))
                    options.setAttribute(a.attribute, a.value);
                return;
            }
    }
}

std::vector<const Format*> FormatRegistry::forExtension(const std::string& path) const {
    const std::string ext = extensionOf(path);
    std::vector<const Format*> out;
    for (const auto& f : m_formats) {
        const auto exts = f->extensions();
        if (std::find(exts.begin(), exts.end(), ext) != exts.end())
            out.push_back(f.get());
    }
    return out;
}

const Format* FormatRegistry::writerForPath(const std::string& path) const {
    for (const Format* f : forExtension(path))
        if (f->canWrite())
            return f;
    return nullptr;
}

std::vector<const Format*> FormatRegistry::all() const {
    std::vector<const Format*> out;
    for (const auto& f : m_formats)
        out.push_back(f.get());
    return out;
}

static std::string knownExtensions(const std::vector<std::unique_ptr<Format>>& formats, bool read) {
    std::vector<std::string> exts;
    for (const auto& f : formats)
        if (read ? f->canRead() : f->canWrite())
            for (const auto& e : f->extensions())
                if (std::find(exts.begin(), exts.end(), e) == exts.end())
                    exts.push_back(e);
    std::string s;
    for (const auto& e : exts)
        s += (s.empty() ? "" : " ") + e;
    return s;
}

LutFile FormatRegistry::read(const std::string& path, const FormatOptions& options,
                             const std::string& formatName) const {
    if (isStdinName(path) && !isStdStream(path))
        return read("-", options, formatName); // /dev/stdin is standard input
    std::vector<const Format*> candidates;
    if (!formatName.empty()) {
        const Format* f = byName(formatName);
        if (!f)
            throw Error("unknown format '" + formatName + "'");
        candidates.push_back(f);
        if (f->name() != formatName) {
            FormatOptions aliased = options;
            applyAlias(formatName, aliased);
            return read(path, aliased, f->name());
        }
    } else {
        candidates = forExtension(path);
    }
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                    [](const Format* f) { return !f->canRead(); }),
                     candidates.end());
    if (isStdStream(path)) {
        // Standard input has no extension: the named format, else each readable one in turn.
        if (formatName.empty())
            for (const auto& f : m_formats)
                if (f->canRead())
                    candidates.push_back(f.get());
        // Bounded by what the candidates can be: binary data no format starts with stops after
        // its first MiB (`lutkit info - < /dev/zero` took 2 GB).
        const std::string bytes =
            readStandardInput(limits::kMaxLutFileBytes, [&](const std::string& head) {
                // A first MiB of comment lines alone (`yes '# c' | lutkit info -` took 4 GB
                // before the limit stopped it): no LUT file is so, refused at once.
                if (head.size() >= kStreamHeadBytes && onlyCommentLines(head))
                    throw Error("-: standard input is no LUT file lutkit reads (its first MiB "
                                "is comment and blank lines only)");
                std::uint64_t most = 0;
                for (const Format* f : candidates)
                    most = std::max(most, f->maxStreamBytes(head));
                if (most == 0)
                    throw Error("-: standard input is no LUT file lutkit reads (" +
                                std::string(head.find('\0') != std::string::npos
                                                ? "binary data that no LUT format starts with"
                                                : "no format takes it") +
                                "; name its format with --in-format)");
                return StreamBound{most, "a LUT file of the formats tried can take"};
            });
        std::string reasons;
        for (const Format* f : candidates) {
            try {
                return f->readMemory(bytes, path, options);
            } catch (const Error& e) {
                reasons += (reasons.empty() ? "" : "; ") + f->name() + ": " + e.what();
            }
        }
        throw Error("-: no format could read standard input (name it with --in-format): " +
                    reasons);
    }
    if (candidates.empty())
        throw Error(path + ": " +
                    (extensionOf(path).empty()
                         ? std::string("has no extension to tell its format: name it with "
                                       "--in-format")
                         : "no format reads '" + extensionOf(path) + "' files") +
                    " (readable: " + knownExtensions(m_formats, true) + ")");
    // Once for every candidate: a FIFO, a directory or a device is refused before any reader
    // opens it (each reader checks again when called directly).
    checkRegularInput(path);
    try {
        if (candidates.size() == 1)
            return candidates.front()->read(path, options);
        // Several formats claim the extension: the first that succeeds wins; otherwise report
        // all, unless one of them recognised the file and says where in it it failed (a
        // ParseError with a line): that reader's line alone, the same in every edition (the
        // portable ones lack OpenColorIO's reader).
        std::string reasons;
        std::optional<ParseError> placed;
        for (const Format* f : candidates) {
            try {
                return f->read(path, options);
            } catch (const ParseError& e) {
                if (!placed && e.line() > 0)
                    placed = e;
                reasons += (reasons.empty() ? "" : "; ") + f->name() + ": " + e.what();
            } catch (const Error& e) {
                reasons += (reasons.empty() ? "" : "; ") + f->name() + ": " + e.what();
            }
        }
        if (placed)
            throw *placed;
        throw Error(path + ": no format could read it (" + reasons + ")");
    } catch (const std::bad_alloc&) {
        // Readers name the size they asked for (lut::allocating); this is for any other
        // allocation, so the user still gets one line naming the file.
        throw Error(path + ": out of memory while reading it");
    }
}

Diagnostics FormatRegistry::write(const std::string& path, const LutFile& lut,
                                  const FormatOptions& options,
                                  const std::string& formatName) const {
    const Format* f = nullptr;
    if (!formatName.empty()) {
        f = byName(formatName);
        if (!f)
            throw Error("unknown format '" + formatName + "'");
    } else {
        f = writerForPath(path);
    }
    if (!f || !f->canWrite())
        throw Error(path + ": no format writes '" + extensionOf(path) +
                    "' files (writable: " + knownExtensions(m_formats, false) + ")");
    if (!formatName.empty() && f->name() != formatName) {
        FormatOptions aliased = options;
        applyAlias(formatName, aliased);
        return writeLutFile(*f, path, lut, aliased);
    }
    return writeLutFile(*f, path, lut, options);
}

} // namespace lut
