// SPDX-License-Identifier: Apache-2.0
#pragma once
// The .cube keyword table and the table of departures from the Adobe 1.0 spec that strict reading
// reports (how many of each kind are shown before only counting, and the words of the "and N more"
// summary).
#include <cstddef>
#include <iterator>
#include <string_view>

namespace lut::formats::cube {

// clang-format off
enum class Key { Title, DomainMin, DomainMax, Size1D, Size3D, Range1D, Range3D, InVideo, OutVideo };
inline constexpr int kKeyCount = 9;
inline constexpr const char* kKeyNames[kKeyCount] = {
    "TITLE",
    "DOMAIN_MIN",
    "DOMAIN_MAX",
    "LUT_1D_SIZE",
    "LUT_3D_SIZE",
    "LUT_1D_INPUT_RANGE", // Resolve
    "LUT_3D_INPUT_RANGE", // Resolve
    "LUT_IN_VIDEO_RANGE", // Resolve
    "LUT_OUT_VIDEO_RANGE" // Resolve
};
// clang-format on

inline bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        char x = a[i];
        if (x >= 'a' && x <= 'z')
            x = static_cast<char>(x - 'a' + 'A');
        if (x != b[i])
            return false;
    }
    return true;
}

// The index of tok in kKeyNames (any case), or -1.
inline int lookupKey(std::string_view tok) {
    for (int k = 0; k < kKeyCount; ++k)
        if (equalsIgnoreCase(tok, kKeyNames[k]))
            return k;
    return -1;
}

enum class Departure {
    Bom,
    CrLf,
    CrOnly,
    LongLine,
    KeywordCase,
    KeywordRepeated,
    CommentIndent,
    TrailingComment,
    ResolveKeyword,
    ShaperAndCube,
    UnquotedTitle,
    UnknownKeyword,
    IgnoredKeyword,
    Count
};

struct DepartureInfo {
    int cap;          // reports of this kind before only counting
    const char* rest; // "and N more: <rest>"
};
// clang-format off
inline constexpr DepartureInfo kDepartureInfo[] = {
    {1, "byte order marks"},
    {1, "lines end with CR LF"},
    {1, "lines end with CR"},
    {3, "lines are longer than 250 bytes"},
    {3, "keywords are not upper case"},
    {3, "keywords are repeated"},
    {3, "comments do not start at column 1"},
    {3, "lines end with a comment"},
    {3, "Resolve keywords"},
    {1, "shaper and cube"},
    {3, "unquoted titles"},
    {3, "unknown keywords"},
    {3, "ignored keywords"},
};
// clang-format on
static_assert(std::size(kDepartureInfo) == static_cast<std::size_t>(Departure::Count));

// The Adobe spec's longest line.
inline constexpr std::size_t kAdobeMaxLineBytes = 250;

} // namespace lut::formats::cube
