#include "ocio/OcioInputChecks.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <cctype>
#include <string_view>

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

} // namespace

void checkOcioInput(const std::string& path) {
    // By content, not by extension: when the reader for the file's extension fails, OCIO tries
    // every other reader on it, Cinespace's included.
    const std::string text = readFile(path, limits::kMaxLutFileBytes);
    if (firstLineStartsWith(text, "csplutv100"))
        checkCspMetadata(path, text);
}

} // namespace lut::formats
