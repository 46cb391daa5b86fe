// SPDX-License-Identifier: Apache-2.0
#include "lut/io/FrameSequence.h"

#include "lut/Error.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fs = std::filesystem;

namespace lut {

namespace {

constexpr long kMaxFrames = 10'000'000;

// The placeholder starting at i, if any: its length and padding.
bool placeholderAt(const std::string& s, std::size_t i, std::size_t& len, int& padding) {
    if (s[i] == '%') {
        std::size_t j = i + 1;
        int width = 0;
        bool zero = false;
        if (j < s.size() && s[j] == '0') {
            zero = true;
            ++j;
        }
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])) && width < 100)
            width = width * 10 + (s[j++] - '0');
        if (j < s.size() && s[j] == 'd') {
            len = j + 1 - i;
            padding = zero ? width : 0;
            return true;
        }
        return false;
    }
    if (s[i] == '#' || s[i] == '@') {
        std::size_t j = i;
        int hashes = 0, ats = 0;
        while (j < s.size() && (s[j] == '#' || s[j] == '@'))
            (s[j++] == '#' ? hashes : ats)++;
        len = j - i;
        // oiiotool: # = 4 digits, @ = 1; a run of #'s is one digit each (frame.####.exr).
        padding = (hashes == 1 ? 4 : hashes) + ats;
        return true;
    }
    return false;
}

long parseNumber(const std::string& text, std::size_t& i, const std::string& whole) {
    std::size_t start = i;
    long v = 0;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
        v = v * 10 + (text[i++] - '0');
        if (v > 1'000'000'000)
            throw Error("frame range '" + whole + "': frame number too large");
    }
    if (i == start)
        throw Error("frame range '" + whole +
                    "': expected a frame number (ranges look like 1-100, 1-100x2 or 1,5,7-9)");
    return v;
}

} // namespace

std::string FramePattern::path(long frame) const {
    std::string n = std::to_string(frame);
    if (static_cast<int>(n.size()) < padding)
        n.insert(0, static_cast<std::size_t>(padding) - n.size(), '0');
    return prefix + n + suffix;
}

std::optional<long> FramePattern::frameOf(const std::string& p) const {
    if (p.size() <= prefix.size() + suffix.size() || p.compare(0, prefix.size(), prefix) != 0 ||
        p.compare(p.size() - suffix.size(), suffix.size(), suffix) != 0)
        return std::nullopt;
    const std::string digits = p.substr(prefix.size(), p.size() - prefix.size() - suffix.size());
    if (digits.size() > 10 || !std::all_of(digits.begin(), digits.end(), [](char c) {
            return std::isdigit(static_cast<unsigned char>(c));
        }))
        return std::nullopt;
    // Padded: exactly `padding` digits, or more without a leading zero (frame 12345 of %04d).
    if (padding > 0 && static_cast<int>(digits.size()) != padding &&
        (static_cast<int>(digits.size()) < padding || digits[0] == '0'))
        return std::nullopt;
    return std::stol(digits);
}

std::optional<FramePattern> parseFramePattern(const std::string& path) {
    if (os::exists(path))
        return std::nullopt;
    // Only the file name may hold the placeholder.
    const std::size_t nameStart =
        path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1;
    std::optional<FramePattern> found;
    for (std::size_t i = nameStart; i < path.size(); ++i) {
        std::size_t len = 0;
        int padding = 0;
        if (!placeholderAt(path, i, len, padding))
            continue;
        if (found)
            throw Error(path + ": two frame-number placeholders in one name");
        found = FramePattern{path.substr(0, i), path.substr(i + len), padding};
        i += len - 1;
    }
    return found;
}

std::vector<long> parseFrameRange(const std::string& text) {
    std::vector<long> frames;
    std::size_t i = 0;
    if (text.empty())
        throw Error("frame range is empty (ranges look like 1-100, 1-100x2 or 1,5,7-9)");
    while (i <= text.size()) {
        const long a = parseNumber(text, i, text);
        long b = a, step = 1;
        bool complement = false;
        if (i < text.size() && text[i] == '-') {
            ++i;
            b = parseNumber(text, i, text);
            if (i < text.size() && (text[i] == 'x' || text[i] == 'y')) {
                complement = text[i] == 'y';
                ++i;
                step = parseNumber(text, i, text);
                if (step < 1)
                    throw Error("frame range '" + text + "': the step must be 1 or more");
            }
        }
        const long dir = b >= a ? 1 : -1;
        if ((b - a) * dir + static_cast<long>(frames.size()) > kMaxFrames)
            throw Error("frame range '" + text + "': more than 10 million frames");
        for (long f = a, k = 0;; f += dir, ++k) {
            if ((k % step == 0) != complement)
                frames.push_back(f);
            if (f == b)
                break;
        }
        if (i == text.size())
            break;
        if (text[i] != ',')
            throw Error("frame range '" + text + "': unexpected '" + std::string(1, text[i]) +
                        "' (ranges look like 1-100, 1-100x2 or 1,5,7-9)");
        ++i;
    }
    return frames;
}

std::vector<long> findFrames(const FramePattern& pattern) {
    std::vector<long> frames;
    const fs::path folder = os::toPath(pattern.prefix).parent_path();
    // Compare as the pattern spells the folder (its separators too).
    const std::size_t cut = pattern.prefix.find_last_of(os::pathSeparators());
    const std::string spelled = cut == std::string::npos ? "" : pattern.prefix.substr(0, cut + 1);
    std::error_code ec;
    const fs::path dir = folder.empty() ? fs::path(".") : folder;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        if (!e.is_regular_file(ec))
            continue;
        const std::string name = spelled + os::fromPath(e.path().filename());
        if (const auto f = pattern.frameOf(name))
            frames.push_back(*f);
    }
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

std::string describeFrames(const std::vector<long>& f) {
    std::string s;
    for (std::size_t i = 0; i < f.size();) {
        std::size_t j = i;
        while (j + 1 < f.size() && f[j + 1] == f[j] + 1)
            ++j;
        s += (s.empty() ? "" : ", ") + std::to_string(f[i]);
        if (j > i)
            s += "-" + std::to_string(f[j]);
        i = j + 1;
    }
    return s;
}

std::string missingFrames(const std::vector<long>& f) {
    std::vector<long> missing;
    for (std::size_t i = 0; i + 1 < f.size(); ++i)
        for (long g = f[i] + 1; g < f[i + 1] && missing.size() < 100000; ++g)
            missing.push_back(g);
    return describeFrames(missing);
}

} // namespace lut
