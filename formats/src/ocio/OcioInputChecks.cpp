// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioInputChecks.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string_view>
#include <vector>

namespace lut::formats {

namespace {

// Whether line, without leading blanks and ignoring case, starts with word (OCIO's startswithU).
bool startsWithWord(std::string_view line, std::string_view word) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front())))
        line.remove_prefix(1);
    if (line.size() < word.size())
        return false;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(line[i])) != word[i])
            return false;
    return true;
}

// Cinespace: OCIO reads a metadata block with
//   while (!startswithU(line, "END METADATA") || !istream) { nextline(istream, line); ... }
// so a BEGIN METADATA without END METADATA loops forever at the end of the file, appending to the
// metadata string until memory runs out.
void checkCspMetadata(const std::string& path, std::string_view text) {
    int line = 0, beginLine = 0;
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t nl = std::min(text.find('\n', at), text.size());
        const std::string_view l = text.substr(at, nl - at);
        ++line;
        if (beginLine == 0 && startsWithWord(l, "begin metadata"))
            beginLine = line;
        else if (beginLine != 0 && startsWithWord(l, "end metadata"))
            return;
        at = nl + 1;
    }
    if (beginLine != 0)
        throw ParseError(path, beginLine, 1,
                         "BEGIN METADATA without END METADATA (OpenColorIO would read past the "
                         "end of the file without stopping)");
}

// Whether text starts (after blank lines and leading blanks) with word, ignoring case.
bool firstLineStartsWith(std::string_view text, std::string_view word) {
    std::size_t at = 0;
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])))
        ++at;
    return startsWithWord(text.substr(at), word);
}

// The files a CTF/CLF text references: the path attribute of each <Reference> element.
std::vector<std::string> referencedPaths(std::string_view text) {
    std::vector<std::string> out;
    for (std::size_t at = 0; (at = text.find("<Reference", at)) != std::string_view::npos;) {
        const std::size_t end = std::min(text.find('>', at), text.size());
        const std::string_view element = text.substr(at, end - at);
        for (const char* attr : {"path=\"", "path='"}) {
            const std::size_t p = element.find(attr);
            if (p == std::string_view::npos)
                continue;
            const char quote = attr[5];
            const std::size_t b = p + 6;
            const std::size_t e = element.find(quote, b);
            if (e != std::string_view::npos)
                out.emplace_back(element.substr(b, e - b));
        }
        at = end;
    }
    return out;
}

void checkFileOnce(const std::string& path, std::vector<std::string>& chain);

void checkText(const std::string& path, std::vector<std::string>& chain) {
    // By content, not by extension: when the reader for the file's extension fails, OCIO tries
    // every other reader on it, Cinespace's included.
    const std::string text = readFile(path, limits::kMaxLutFileBytes);
    if (firstLineStartsWith(text, "csplutv100"))
        checkCspMetadata(path, text);
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    for (const std::string& ref : referencedPaths(text)) {
        const std::filesystem::path p(ref);
        // The refusal names the file that holds the reference too: the user gave that one.
        try {
            checkFileOnce((p.is_absolute() ? p : folder / p).lexically_normal().string(), chain);
        } catch (const LimitError& e) {
            throw LimitError(path + ": references " + ref + ": " + e.what());
        } catch (const ParseError&) {
            throw; // names its own file, line and column
        } catch (const Error& e) {
            throw Error(path + ": references " + ref + ": " + e.what());
        }
    }
}

void checkFileOnce(const std::string& path, std::vector<std::string>& chain) {
    std::error_code ec;
    const std::string key = std::filesystem::weakly_canonical(path, ec).string();
    for (const std::string& on : chain)
        if (on == key)
            throw Error(path + ": references itself through " + std::to_string(chain.size()) +
                        " file(s) (a cycle OpenColorIO would follow without end)");
    if (chain.size() >= 64)
        throw Error(path + ": more than 64 files deep in references");
    checkRegularInput(path);
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > limits::kMaxLutFileBytes)
        throw LimitError(path + ": file is " + std::to_string(size) + " bytes, over the limit of " +
                         std::to_string(limits::kMaxLutFileBytes));
    chain.push_back(key);
    checkText(path, chain);
    chain.pop_back();
}

} // namespace

void checkOcioInput(const std::string& path) {
    std::error_code ec;
    std::vector<std::string> chain{std::filesystem::weakly_canonical(path, ec).string()};
    checkText(path, chain);
}

void checkOcioFile(const std::string& path) {
    std::vector<std::string> chain;
    checkFileOnce(path, chain);
}

} // namespace lut::formats
