// SPDX-License-Identifier: Apache-2.0
// What a LUT file is for (decidePurpose) and whether its table says it is the game's LUT
// (gameLutEvidence), declared in lut/LutFile.h; made here in smash/ because the evidence is the
// game's brighten pass (lut/smash/SmashConstants.h).
#include "lut/LutFile.h"
#include "lut/smash/SmashConstants.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut {

PurposeDecision decidePurpose(const LutFile& file, std::optional<LutPurpose> given,
                              LutPurpose assumed) {
    PurposeDecision d = decidePurpose(file.purpose, file.format == "nutexb", given, assumed);
    if (d.source == PurposeSource::File && file.format == "builtin")
        d.source = PurposeSource::Builtin; // builtin:smash-default says so by its name
    if (d.source == PurposeSource::Assumed && assumed == LutPurpose::Raw && file.cube &&
        !file.shaper)
        if (auto evidence = gameLutEvidence(*file.cube)) {
            d.purpose = LutPurpose::Smash;
            d.source = PurposeSource::Content;
            d.evidence = std::move(*evidence);
        }
    return d;
}

std::optional<std::string> gameLutEvidence(const Lut3D& t) {
    const int n = t.size();
    if (n < 8 || !t.hasDefaultDomain())
        return std::nullopt;
    // The brighten step's white point: the LUT input (and entry) from which the game shows white.
    constexpr double kWhitePoint = 1.0 / static_cast<double>(kSmashBrightenScale);
    constexpr double kCeiling = 187.0 / 255.0;
    constexpr double kFlat = 2.0 / 255.0;
    float top = 0.0f;
    for (const glm::vec3& e : t.entries())
        for (int c = 0; c < 3; ++c) {
            if (!(e[c] <= kCeiling) || e[c] < -kFlat)
                return std::nullopt; // NaN too
            top = std::max(top, e[c]);
        }
    int first = n; // the first lattice index the game shows white
    for (int i = 0; i < n; ++i)
        if (i / static_cast<double>(n - 1) > kWhitePoint + 1e-3) {
            first = i;
            break;
        }
    if (n - first < 2)
        return std::nullopt;
    double spread = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                glm::vec3 lo(2.0f), hi(-2.0f);
                for (int i = first; i < n; ++i) {
                    const glm::vec3 v = axis == 0   ? t.at(i, j, k)
                                        : axis == 1 ? t.at(j, i, k)
                                                    : t.at(j, k, i);
                    lo = glm::min(lo, v);
                    hi = glm::max(hi, v);
                }
                for (int c = 0; c < 3; ++c)
                    spread = std::max(spread, static_cast<double>(hi[c] - lo[c]));
                if (spread > kFlat)
                    return std::nullopt;
            }
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "no value above %.0f/255 (the entry that shows white is 186: 1/1.3703) and "
                  "flat, within %.1f codes, over every input the game shows white (%d..%d of "
                  "%d^3 on every axis): a game LUT made for the brighten pass, as Smush-LUT "
                  "writes it",
                  std::ceil(top * 255.0 - 1e-6), spread * 255.0, first, n - 1, n);
    return std::string(buf);
}

} // namespace lut
