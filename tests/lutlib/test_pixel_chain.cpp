// SPDX-License-Identifier: Apache-2.0
// lut::PixelChain: steps run in order around the LUT, the LUT is the sampler's, values outside
// the domain are counted (not silently clamped), and a neutral LUT is recognised.
#include "lut/interp/PixelChain.h"
#include "lut/interp/Sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace lut;

namespace {

Lut3D warmLut(int n) {
    Lut3D l(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 in = l.latticeInput(r, g, b);
                l.at(r, g, b) = glm::vec3(std::sqrt(in.r), in.g * in.g, 0.5f * in.b + 0.25f);
            }
    return l;
}

} // namespace

TEST(PixelChain, StepsRunInOrderAroundTheLut) {
    const Lut3D lut = warmLut(9);
    PixelChain chain;
    chain.addBefore("half", [](float* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                p[4 * i + c] *= 0.5f;
    });
    chain.setLut(lut, Interpolation::Tetrahedral);
    chain.addAfter("plus-alpha", [](float* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i)
            p[4 * i + 3] += 1.0f;
    });
    EXPECT_EQ(chain.stepNames(), (std::vector<std::string>{"half", "lut", "plus-alpha"}));
    std::vector<float> px = {0.8f, 0.4f, 0.2f, 0.25f, 1.0f, 1.0f, 1.0f, 0.0f};
    chain.run(px.data(), 2);
    const auto sampler = makeSampler(lut, Interpolation::Tetrahedral);
    const glm::vec3 a = sampler->sample({0.4f, 0.2f, 0.1f});
    const glm::vec3 b = sampler->sample({0.5f, 0.5f, 0.5f});
    EXPECT_FLOAT_EQ(px[0], a.r);
    EXPECT_FLOAT_EQ(px[1], a.g);
    EXPECT_FLOAT_EQ(px[2], a.b);
    EXPECT_FLOAT_EQ(px[3], 1.25f);
    EXPECT_FLOAT_EQ(px[4], b.r);
    EXPECT_FLOAT_EQ(px[7], 1.0f);
    EXPECT_FALSE(chain.isIdentityOnUnitRange());
}

TEST(PixelChain, CountsValuesOutsideTheDomain) {
    PixelChain chain;
    chain.setLut(warmLut(5));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> px = {
        0.5f, 0.5f,  0.5f, 1.0f, // inside
        1.0f, 0.0f,  1.0f, 1.0f, // on the edges: inside
        1.5f, 0.5f,  0.5f, 1.0f, // above by 0.5
        0.5f, -3.0f, 0.5f, 1.0f, // below by 3: the worst
        nan,  0.5f,  2.0f, 1.0f, // NaN and above by 1
    };
    DomainStats st;
    chain.run(px.data(), 5, &st);
    EXPECT_EQ(st.pixels, 5u);
    EXPECT_EQ(st.outside, 3u);
    EXPECT_EQ(st.nan, 1u);
    EXPECT_EQ(st.worst, -3.0f);
    EXPECT_DOUBLE_EQ(st.worstDistance, 3.0);
    EXPECT_EQ(st.str(chain.domainMin(), chain.domainMax()),
              "3 of 5 pixels (60%) outside the LUT's domain [0, 1] (worst -3), 1 with NaN");
    DomainStats none;
    std::vector<float> in = {0.1f, 0.2f, 0.3f, 1.0f};
    chain.run(in.data(), 1, &none);
    EXPECT_EQ(none.outside, 0u);
    EXPECT_EQ(none.str(chain.domainMin(), chain.domainMax()), "");
    st.merge(none);
    EXPECT_EQ(st.pixels, 6u);
    EXPECT_EQ(st.outside, 3u);
}

// The first pass that decides whether a run has anything outside is vectorized (AVX2, 4 pixels
// per step and a scalar tail): one value outside at every pixel position of runs of every
// length up to 19, in each channel, must be found; a NaN or huge alpha alone never counts; the
// domain's edges themselves are inside. The count is checked against the definition written
// here in float64.
TEST(PixelChain, FindsOneValueOutsideAtEveryPositionAndChannel) {
    Lut3D lut = warmLut(5);
    lut.setDomain(glm::vec3(-0.5f, 0.0f, 0.25f), glm::vec3(1.0f, 2.0f, 0.75f));
    PixelChain chain;
    chain.setLut(lut);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double lo[3] = {-0.5, 0.0, 0.25}, hi[3] = {1.0, 2.0, 0.75};
    const float bad[] = {nan,
                         1.0000001f,
                         -0.5000001f,
                         2.0000002f,
                         -1e30f,
                         1e30f,
                         std::numeric_limits<float>::infinity()};
    for (std::size_t n = 1; n <= 19; ++n)
        for (std::size_t at = 0; at < n; ++at)
            for (int c = 0; c < 3; ++c)
                for (const float v : bad) {
                    std::vector<float> px;
                    for (std::size_t i = 0; i < n; ++i) // on the edges and inside; odd alphas
                        px.insert(px.end(), {i % 2 ? -0.5f : 1.0f, i % 3 ? 2.0f : 0.0f, 0.25f,
                                             i % 2 ? nan : 1e30f});
                    px[4 * at + static_cast<std::size_t>(c)] = v;
                    const bool outside = std::isnan(v) || v < lo[c] || v > hi[c];
                    DomainStats st;
                    chain.run(px.data(), n, &st);
                    ASSERT_EQ(st.outside, outside ? 1u : 0u)
                        << "run of " << n << ", pixel " << at << ", channel " << c << ", " << v;
                    ASSERT_EQ(st.pixels, n);
                }
}

TEST(PixelChain, NeutralLutOverTheUnitRangeIsRecognised) {
    PixelChain chain;
    EXPECT_TRUE(chain.isIdentityOnUnitRange());
    Lut3D neutral = Lut3D::identity(17);
    // As a .cube with 6 decimals stores it.
    for (auto& e : neutral.entries())
        for (int c = 0; c < 3; ++c)
            e[c] = std::round(e[c] * 1e6f) / 1e6f;
    chain.setLut(neutral);
    EXPECT_TRUE(chain.isIdentityOnUnitRange());
    Lut3D narrow = Lut3D::identity(5);
    narrow.setDomain(glm::vec3(0.0f), glm::vec3(0.5f));
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r)
                narrow.at(r, g, b) = narrow.latticeInput(r, g, b);
    chain.setLut(narrow); // identity, but clamps [0.5, 1]: not neutral on integer pixels
    EXPECT_FALSE(chain.isIdentityOnUnitRange());
    chain.setLut(warmLut(5));
    EXPECT_FALSE(chain.isIdentityOnUnitRange());
}
