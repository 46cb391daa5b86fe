// SPDX-License-Identifier: Apache-2.0
// What a LUT is for, its names and its tag in files; see lut/LutPurpose.h.
#include "lut/LutPurpose.h"

#include "lut/Error.h"

#include <cctype>
#include <string>

namespace lut {

const char* toString(LutPurpose p) {
    return p == LutPurpose::Raw ? "raw" : "smash";
}

LutPurpose parseLutPurpose(std::string_view name) {
    if (name == "raw")
        return LutPurpose::Raw;
    if (name == "smash")
        return LutPurpose::Smash;
    throw Error("unknown target '" + std::string(name) + "' (expected raw or smash)");
}

const char* describe(LutPurpose p) {
    return p == LutPurpose::Raw ? "an edit (the look itself)"
                                : "the game's LUT (compensated for Smash Ultimate's brighten step)";
}

std::vector<std::string> lutPurposeNames() {
    return {toString(LutPurpose::Raw), toString(LutPurpose::Smash)};
}

std::string purposeTag(LutPurpose p) {
    return std::string(kPurposeKeyword) + " " + toString(p);
}

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// The tag on one line: the keyword first (after blanks), then blanks and a word.
std::optional<LutPurpose> tagOnLine(std::string_view line, const std::string& where) {
    std::size_t i = 0;
    while (i < line.size() && isSpace(line[i]))
        ++i;
    const std::string_view keyword(kPurposeKeyword);
    if (line.substr(i, keyword.size()) != keyword)
        return std::nullopt;
    i += keyword.size();
    if (i < line.size() && !isSpace(line[i]))
        return std::nullopt; // LUTKIT_PURPOSEFUL...: another word
    while (i < line.size() && isSpace(line[i]))
        ++i;
    std::size_t end = i;
    while (end < line.size() && !isSpace(line[end]))
        ++end;
    const std::string_view word = line.substr(i, end - i);
    if (word == "raw" || word == "smash")
        return parseLutPurpose(word);
    throw Error((where.empty() ? std::string() : where + ": ") + kPurposeKeyword + " '" +
                std::string(word) + "' is not a purpose (expected raw or smash)");
}

} // namespace

std::optional<LutPurpose> purposeInText(std::string_view text, const std::string& where) {
    std::optional<LutPurpose> found;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t nl = text.find('\n', start);
        const std::string_view line =
            text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
        if (const auto p = tagOnLine(line, where)) {
            if (found && *found != *p)
                throw Error((where.empty() ? std::string() : where + ": ") +
                            "two LUTKIT_PURPOSE tags that disagree (raw and smash)");
            found = p;
        }
        if (nl == std::string_view::npos)
            break;
        start = nl + 1;
    }
    return found;
}

std::optional<LutPurpose> takePurposeTag(std::vector<std::string>& comments,
                                         const std::string& where) {
    std::optional<LutPurpose> found;
    for (auto it = comments.begin(); it != comments.end();) {
        const auto p = purposeInText(*it, where);
        if (!p) {
            ++it;
            continue;
        }
        if (found && *found != *p)
            throw Error((where.empty() ? std::string() : where + ": ") +
                        "two LUTKIT_PURPOSE tags that disagree (raw and smash)");
        found = p;
        it = comments.erase(it);
    }
    return found;
}

std::string PurposeDecision::text(const std::string& how) const {
    const std::string name = toString(purpose);
    switch (source) {
    case PurposeSource::Given:
        return name + " (" + how +
               (said && *said != purpose ? std::string("; the file says ") + toString(*said)
                                         : std::string()) +
               ")";
    case PurposeSource::File:
        return name + " (the file says so: " + purposeTag(purpose) + ")";
    case PurposeSource::Format:
        return name + " (a .nutexb is the game's LUT)";
    case PurposeSource::Builtin:
        return name +
               (purpose == LutPurpose::Smash ? " (a built-in game LUT)" : " (a built-in edit)");
    case PurposeSource::Content:
        return name + " (the file does not say; its content does: " + evidence + "; " + how +
               " raw if it is an edit)";
    case PurposeSource::Assumed:
        break;
    }
    const LutPurpose other = purpose == LutPurpose::Raw ? LutPurpose::Smash : LutPurpose::Raw;
    return name + " (the file does not say; " + how + " " + toString(other) + " if it is " +
           (other == LutPurpose::Smash ? "the game's LUT" : "an edit") + ")";
}

PurposeDecision decidePurpose(std::optional<LutPurpose> said, bool byFormat,
                              std::optional<LutPurpose> given, LutPurpose assumed) {
    PurposeDecision d;
    d.said = said;
    if (given) {
        d.purpose = *given;
        d.source = PurposeSource::Given;
    } else if (said) {
        d.purpose = *said;
        d.source = byFormat ? PurposeSource::Format : PurposeSource::File;
    } else {
        d.purpose = assumed;
        d.source = PurposeSource::Assumed;
    }
    return d;
}

} // namespace lut
