// SPDX-License-Identifier: Apache-2.0
#include "lut/smash/SmashShownEdit.h"

#include "lut/Error.h"
#include "lut/interp/Sampler.h"
#include "lut/smash/GameDisplay.h"
#include "lut/smash/SmashConstants.h"

#include <vector>

namespace lut {

Lut3D smashShownEdit(const Lut3D& gameLut, int size) {
    if (gameLut.empty())
        throw Error("smashShownEdit: the game LUT has no entries");
    // The neutral game's input for each display value, by bisection on its (rising) display;
    // the game interpolates its LUT trilinearly (as smashShownColour's stage model does).
    const double white = 1.0 / static_cast<double>(kSmashBrightenScale);
    std::vector<double> input(static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i) {
        const double d = static_cast<double>(i) / (size - 1);
        double lo = 0.0, hi = white;
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            (detail::gameShown(mid, mid) < d ? lo : hi) = mid;
        }
        input[static_cast<std::size_t>(i)] = i == size - 1 ? white : 0.5 * (lo + hi);
    }
    const auto game = makeSampler(gameLut, Interpolation::Trilinear);
    Lut3D edit(size);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r) {
                const glm::dvec3 s(input[static_cast<std::size_t>(r)],
                                   input[static_cast<std::size_t>(g)],
                                   input[static_cast<std::size_t>(b)]);
                const glm::vec3 l = game->sample(glm::vec3(s));
                glm::vec3 shown;
                for (int c = 0; c < 3; ++c)
                    shown[c] = static_cast<float>(detail::gameShown(l[c], s[c]));
                edit.at(r, g, b) = shown;
            }
    return edit;
}

} // namespace lut
