// SPDX-License-Identifier: Apache-2.0
// The extreme-input policy of Sampler.h, for every sampler, through both sample() (scalar) and
// applyPixels() (the run-time chosen SIMD kernel).
#include "LutTestUtil.h"
#include "lut/Error.h"
#include "lut/interp/Sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace lut;

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

glm::vec3 viaKernel(const Sampler& s, glm::vec3 in) {
    float px[4] = {in.x, in.y, in.z, 0.25f};
    s.applyPixels(px, 1);
    EXPECT_EQ(px[3], 0.25f);
    return glm::vec3(px[0], px[1], px[2]);
}

// Same bits (so -0 vs 0 and NaN would show).
void expectSame(glm::vec3 a, glm::vec3 b, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(a[c], b[c]) << what << " channel " << c;
}

class Policy : public ::testing::TestWithParam<Interpolation> {};

} // namespace

TEST_P(Policy, SpecialValuesMapToDomainEnds) {
    for (int n : {2, 17, 33}) {
        Lut3D lut = test::randomLut(n, 21);
        lut.setDomain(glm::vec3(-0.25f, 0.0f, 0.5f), glm::vec3(1.5f, 1.0f, 2.0f));
        const auto s = makeSampler(lut, GetParam());
        const glm::vec3 lo = lut.domainMin(), hi = lut.domainMax();
        const glm::vec3 mid(0.3f, 0.6f, 0.9f);
        for (int c = 0; c < 3; ++c) {
            auto with = [&](float v) {
                glm::vec3 x = mid;
                x[c] = v;
                return x;
            };
            for (auto eval : {+[](const Sampler&s, glm::vec3 x) { return s.sample(x); },
                              +[](const Sampler&s, glm::vec3 x) { return viaKernel(s, x); }}) {
                const glm::vec3 atMin = eval(*s, with(lo[c])), atMax = eval(*s, with(hi[c]));
                expectSame(eval(*s, with(kNaN)), atMin, "NaN");
                expectSame(eval(*s, with(-kNaN)), atMin, "-NaN");
                expectSame(eval(*s, with(-kInf)), atMin, "-Inf");
                expectSame(eval(*s, with(-1e30f)), atMin, "-1e30");
                expectSame(eval(*s, with(kInf)), atMax, "+Inf");
                expectSame(eval(*s, with(1e30f)), atMax, "1e30");
                expectSame(eval(*s, with(std::numeric_limits<float>::max())), atMax, "FLT_MAX");
                expectSame(eval(*s, with(hi[c] + 1.0f)), atMax, "above");
                expectSame(eval(*s, with(lo[c] - 1.0f)), atMin, "below");
            }
        }
        // -0 is 0, and a denormal in a [0,1] domain is (almost) 0.
        Lut3D unit = test::randomLut(n, 22);
        const auto u = makeSampler(unit, GetParam());
        expectSame(u->sample(glm::vec3(-0.0f, 0.5f, -0.0f)), u->sample(glm::vec3(0.0f, 0.5f, 0.0f)),
                   "-0");
        expectSame(viaKernel(*u, glm::vec3(-0.0f, 0.5f, -0.0f)),
                   viaKernel(*u, glm::vec3(0.0f, 0.5f, 0.0f)), "-0 simd");
        const glm::vec3 den = u->sample(glm::vec3(1e-40f, 1e-45f, -1e-40f)),
                        zero = u->sample(glm::vec3(0.0f));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(den[c], zero[c], 1e-30f);
    }
}

TEST_P(Policy, FiniteTablesNeverGiveNaNOrInfAndStayInTheirRange) {
    for (int n : {2, 3, 16, 33}) {
        Lut3D lut = test::randomLut(n, 31);
        lut.at(0, 0, 0) = glm::vec3(-3e38f, 3e38f, 0.0f); // huge but finite entries
        lut.at(n - 1, n - 1, n - 1) = glm::vec3(3e38f, -3e38f, 1e-45f);
        const auto [lo, hi] = lut.valueRange();
        for (const auto& dom : {std::pair{glm::vec3(0.0f), glm::vec3(1.0f)},
                                std::pair{glm::vec3(0.0f), glm::vec3(1e-30f)},
                                std::pair{glm::vec3(-1e30f), glm::vec3(1e30f)},
                                std::pair{glm::vec3(1000.0f), glm::vec3(1000.001f)}}) {
            lut.setDomain(dom.first, dom.second);
            const auto s = makeSampler(lut, GetParam());
            const auto inputs = test::stressInputs(1000);
            std::vector<float> px;
            for (const auto& in : inputs)
                px.insert(px.end(), {in.x, in.y, in.z, kNaN});
            s->applyPixels(px.data(), inputs.size());
            for (std::size_t i = 0; i < inputs.size(); ++i) {
                const glm::vec3 a = s->sample(inputs[i]);
                ASSERT_TRUE(test::finite3(a)) << i;
                for (int c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(px[4 * i + c])) << "simd " << i;
                    ASSERT_GE(px[4 * i + c], lo);
                    ASSERT_LE(px[4 * i + c], hi);
                    ASSERT_GE(a[c], lo);
                    ASSERT_LE(a[c], hi);
                }
                ASSERT_TRUE(std::isnan(px[4 * i + 3])) << "alpha must pass through untouched";
            }
        }
    }
}

TEST_P(Policy, LatticePointsReturnEntriesExactly) {
    for (int n : {2, 16, 17, 33, 256}) {
        const Lut3D base = test::randomLut(n, 41);
        for (const auto& dom :
             {std::pair{glm::vec3(0.0f), glm::vec3(1.0f)},
              std::pair{glm::vec3(-0.25f, 0.0f, 0.1f), glm::vec3(1.75f, 4.0f, 0.9f)},
              std::pair{glm::vec3(0.0f), glm::vec3(1e-30f)}}) {
            if (n == 256 && !(dom.first == glm::vec3(0.0f) && dom.second == glm::vec3(1.0f)))
                continue; // time
            Lut3D lut = base;
            lut.setDomain(dom.first, dom.second);
            const auto s = makeSampler(lut, GetParam());
            const int step = n > 40 ? 17 : 1;
            std::vector<int> idx;
            for (int i = 0; i < n; i += step)
                idx.push_back(i);
            if (idx.back() != n - 1)
                idx.push_back(n - 1);
            for (int b : idx)
                for (int g : idx)
                    for (int r : idx) {
                        const glm::vec3 in = lut.latticeInput(r, g, b);
                        expectSame(s->sample(in), lut.at(r, g, b),
                                   "N=" + std::to_string(n) + " lattice " + std::to_string(r) +
                                       "," + std::to_string(g) + "," + std::to_string(b));
                        expectSame(viaKernel(*s, in), lut.at(r, g, b), "simd lattice");
                    }
            // Exactly domainMax is the last entry.
            expectSame(s->sample(lut.domainMax()), lut.at(n - 1, n - 1, n - 1), "domainMax");
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, Policy,
                         ::testing::Values(Interpolation::Nearest, Interpolation::Trilinear,
                                           Interpolation::Tetrahedral),
                         [](const ::testing::TestParamInfo<Interpolation>& i) {
                             return std::string(toString(i.param));
                         });

class Smooth : public ::testing::TestWithParam<Interpolation> {};

TEST_P(Smooth, NeutralLutReturnsInputUnchanged) {
    for (int n : {2, 16, 17, 33, 65}) {
        const Lut3D id = Lut3D::identity(n);
        const auto s = makeSampler(id, GetParam());
        auto inputs = test::stressInputs(20000, 5);
        // Only in-domain inputs: the neutral LUT clamps the rest.
        std::vector<glm::vec3> in;
        for (const auto& v : inputs)
            if (v.x >= 0 && v.x <= 1 && v.y >= 0 && v.y <= 1 && v.z >= 0 && v.z <= 1)
                in.push_back(v);
        for (float t : {1e-6f, 1e-20f, 0.1f, 0.2f, 0.3f, 0.7f, 0.9f})
            in.emplace_back(t, 1.0f - t, t * 0.5f);
        std::vector<float> px;
        for (const auto& v : in)
            px.insert(px.end(), {v.x, v.y, v.z, 1.0f});
        s->applyPixels(px.data(), in.size());
        for (std::size_t i = 0; i < in.size(); ++i) {
            const glm::vec3 a = s->sample(in[i]);
            for (int c = 0; c < 3; ++c) {
                // A few float ulps of the value, plus the rounding of i/(N-1) entries near 1.
                const float tol =
                    4.0f * std::numeric_limits<float>::epsilon() * std::max(in[i][c], 1.0f / 64);
                ASSERT_NEAR(a[c], in[i][c], tol) << "N=" << n << " value " << in[i][c];
                ASSERT_NEAR(px[4 * i + c], in[i][c], tol)
                    << "simd N=" << n << " value " << in[i][c];
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Interpolating, Smooth,
                         ::testing::Values(Interpolation::Trilinear, Interpolation::Tetrahedral),
                         [](const ::testing::TestParamInfo<Interpolation>& i) {
                             return std::string(toString(i.param));
                         });

TEST(Tetrahedral, KeepsGreysGrey) {
    for (int n : {2, 17, 33}) {
        Lut3D lut = test::randomLut(n, 51);
        for (int i = 0; i < n; ++i)
            lut.at(i, i, i) =
                glm::vec3(static_cast<float>(i * i) / ((n - 1) * (n - 1)) * 0.8f + 0.1f);
        const auto s = makeSampler(lut, Interpolation::Tetrahedral);
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> u(-0.1f, 1.1f);
        std::vector<float> px;
        for (int k = 0; k < 5000; ++k) {
            const float v = u(rng);
            const glm::vec3 o = s->sample(glm::vec3(v));
            ASSERT_EQ(o.r, o.g) << v;
            ASSERT_EQ(o.g, o.b) << v;
            px.insert(px.end(), {v, v, v, 1.0f});
        }
        s->applyPixels(px.data(), 5000);
        for (int k = 0; k < 5000; ++k) {
            ASSERT_EQ(px[4 * k], px[4 * k + 1]);
            ASSERT_EQ(px[4 * k + 1], px[4 * k + 2]);
        }
    }
    // Trilinear does not have this property on the same LUT: the test above can fail.
    Lut3D lut = test::randomLut(5, 51);
    for (int i = 0; i < 5; ++i)
        lut.at(i, i, i) = glm::vec3(i / 4.0f);
    const glm::vec3 o = makeSampler(lut, Interpolation::Trilinear)->sample(glm::vec3(0.4f));
    EXPECT_FALSE(o.r == o.g && o.g == o.b);
}

TEST(Sampler, EmptyLutThrows) {
    EXPECT_THROW(makeSampler(Lut3D(), Interpolation::Trilinear), Error);
}

TEST(Sampler, ApplyUsesAnyThreadCountAndKeepsAlphaAndRowPadding) {
    const Lut3D lut = test::smoothLut(17);
    const auto s = makeSampler(lut, Interpolation::Tetrahedral);
    const int w = 37, h = 29, stride = 4 * w + 6; // padded rows: the padding must stay untouched
    std::vector<float> src(static_cast<std::size_t>(stride) * h);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-0.2f, 1.2f);
    for (auto& v : src)
        v = u(rng);
    std::vector<float> ref = src;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &ref[static_cast<std::size_t>(y) * stride + 4 * x];
            const glm::vec3 o = s->sample(glm::vec3(p[0], p[1], p[2]));
            p[0] = o.x, p[1] = o.y, p[2] = o.z;
        }
    for (int threads : {0, 1, 2, 3, 8, 100}) {
        std::vector<float> img = src;
        s->apply(ImageView{img.data(), w, h, stride}, threads);
        for (std::size_t i = 0; i < img.size(); ++i) {
            const std::size_t inRow = i % stride;
            if (inRow >= 4u * w || inRow % 4 == 3)
                ASSERT_EQ(img[i], src[i])
                    << "alpha/padding changed at " << i << " threads " << threads;
            else
                ASSERT_NEAR(img[i], ref[i], 2e-6f) << i << " threads " << threads;
        }
    }
    s->apply(ImageView{}, 0); // empty view: nothing to do, no crash
}
