// SPDX-License-Identifier: Apache-2.0
// Oklab (lut/ops/Oklab.h) against the values Björn Ottosson and CSS Color 4 publish.
#include "lut/ops/Oklab.h"

#include <gtest/gtest.h>

using namespace lut;

TEST(CheckOklab, PublishedValues) {
    // sRGB red, green, blue and white in Oklab, as CSS Color 4 and Ottosson list them.
    const struct {
        glm::dvec3 srgb, lab;
    } cases[] = {{{1, 0, 0}, {0.627955, 0.224863, 0.125846}},
                 {{0, 1, 0}, {0.866440, -0.233888, 0.179498}},
                 {{0, 0, 1}, {0.452014, -0.032457, -0.311528}},
                 {{1, 1, 1}, {1.0, 0.0, 0.0}}};
    for (const auto& c : cases) {
        const glm::dvec3 lab = srgbToOklab(c.srgb);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(lab[k], c.lab[k], 2e-4) << k;
        const glm::dvec3 back = oklabToSrgb(lab);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(back[k], c.srgb[k], 1e-5);
    }
    EXPECT_NEAR(hueDifference(350.0, 10.0), 20.0, 1e-12);
    EXPECT_NEAR(hueDifference(10.0, 350.0), -20.0, 1e-12);
}
