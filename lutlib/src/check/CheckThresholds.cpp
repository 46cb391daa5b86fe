// SPDX-License-Identifier: Apache-2.0
#include "lut/check/CheckThresholds.h"
#include "lut/NumberText.h"

#include "lut/Error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace lut {

namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// One number at text[pos...]; advances pos past it. Empty optional when there is none.
bool readNumber(std::string_view line, std::size_t& pos, double& value) {
    while (pos < line.size() && isSpace(line[pos]))
        ++pos;
    if (pos >= line.size())
        return false;
    const char* begin = line.data() + pos;
    const char* end = line.data() + line.size();
    if (*begin == '+')
        ++begin;
    const auto [ptr, ec] = fromChars(begin, end, value);
    if (ec != std::errc() || !std::isfinite(value))
        return false;
    pos = static_cast<std::size_t>(ptr - line.data());
    return true;
}

} // namespace

const std::vector<ThresholdKey>& thresholdKeys() {
    static const std::vector<ThresholdKey> keys = {
        {"fold-over", &CheckThresholds::foldOver, "8-bit steps",
         "how far an output channel falls back while its own input rises"},
        {"flat", &CheckThresholds::flat, "8-bit steps",
         "output change a flat run loses against the slope around it"},
        {"step", &CheckThresholds::step, "8-bit steps",
         "how far the output jumps in one lattice step beyond its neighbours"},
        {"steep", &CheckThresholds::steep, "steps per input step",
         "output 8-bit steps one input 8-bit step spreads over"},
        {"hue-shift", &CheckThresholds::hueShift, "degrees",
         "mean turn of a constant-hue ramp's hue (Oklab)"},
        {"skin-drift", &CheckThresholds::skinDrift, "degrees",
         "mean turn of the skin line's hue (Oklab)"},
        {"non-finite", &CheckThresholds::nonFinite, "entries", "NaN or infinite entries"},
        {"out-of-range", &CheckThresholds::outOfRange, "% of the cube",
         "entries outside [0, 1] by more than half an 8-bit step"},
        {"clip", &CheckThresholds::clip, "% of the cube",
         "where one output channel is held at 0 or 1 while its input moves"},
        {"rough", &CheckThresholds::rough, "8-bit steps",
         "second difference along a lattice line, at a 33-point lattice's spacing"},
        {"folded", &CheckThresholds::folded, "% of the cube",
         "cells turned inside out (no unique inverse)"},
    };
    return keys;
}

CheckThresholds parseCheckThresholds(std::string_view text, const std::string& path,
                                     const CheckThresholds& base) {
    CheckThresholds out = base;
    int lineNo = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t eol = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, eol - start);
        start = eol + 1;
        ++lineNo;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        std::size_t pos = 0;
        while (pos < line.size() && isSpace(line[pos]))
            ++pos;
        if (pos >= line.size()) {
            if (eol >= text.size())
                break;
            continue;
        }
        const std::size_t nameStart = pos;
        while (pos < line.size() && !isSpace(line[pos]) && line[pos] != '=')
            ++pos;
        std::string name(line.substr(nameStart, pos - nameStart));
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        const int column = static_cast<int>(nameStart) + 1;
        // NAME = WARN FAIL, NAME.warn = V or NAME.fail = V
        int which = 0; // 0 both, 1 warn, 2 fail
        std::string key = name;
        if (name.size() > 5 && name.compare(name.size() - 5, 5, ".warn") == 0) {
            which = 1;
            key = name.substr(0, name.size() - 5);
        } else if (name.size() > 5 && name.compare(name.size() - 5, 5, ".fail") == 0) {
            which = 2;
            key = name.substr(0, name.size() - 5);
        }
        const auto& keys = thresholdKeys();
        const auto it = std::find_if(keys.begin(), keys.end(),
                                     [&](const ThresholdKey& k) { return key == k.name; });
        if (it == keys.end()) {
            std::string msg = "unknown threshold '" + name + "'";
            const ThresholdKey* best = nullptr;
            std::size_t bestDistance = 3;
            for (const ThresholdKey& k : keys)
                if (const std::size_t d = editDistance(key, k.name); d < bestDistance) {
                    bestDistance = d;
                    best = &k;
                }
            if (best)
                msg += "; did you mean '" + std::string(best->name) + "'?";
            throw ParseError(path, lineNo, column, msg, name);
        }
        while (pos < line.size() && isSpace(line[pos]))
            ++pos;
        if (pos >= line.size() || line[pos] != '=')
            throw ParseError(path, lineNo, static_cast<int>(pos) + 1,
                             "expected '=' after '" + name + "'");
        ++pos;
        Threshold& t = out.*(it->member);
        const std::size_t numberColumn = pos + 1;
        double a = 0.0, b = 0.0;
        if (!readNumber(line, pos, a))
            throw ParseError(path, lineNo, static_cast<int>(numberColumn),
                             which == 0 ? "expected two numbers: the warn and the fail value"
                                        : "expected a number");
        if (which == 0) {
            const std::size_t second = pos + 1;
            if (!readNumber(line, pos, b))
                throw ParseError(path, lineNo, static_cast<int>(second),
                                 "expected a second number: the fail value");
            t = {a, b};
        } else if (which == 1) {
            t.warn = a;
        } else {
            t.fail = a;
        }
        while (pos < line.size() && isSpace(line[pos]))
            ++pos;
        if (pos < line.size())
            throw ParseError(path, lineNo, static_cast<int>(pos) + 1, "unexpected text",
                             std::string(line.substr(pos)));
        if (t.fail < t.warn)
            throw ParseError(path, lineNo, column,
                             "'" + key + "': the fail value is below the warn value");
        if (eol >= text.size())
            break;
    }
    return out;
}

} // namespace lut
