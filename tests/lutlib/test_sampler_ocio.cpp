// SPDX-License-Identifier: Apache-2.0
// OpenColorIO as the oracle: our trilinear and tetrahedral samplers (scalar and SIMD) against
// OCIO's CPU processor for a Lut3DTransform holding the same entries.
#include "LutTestUtil.h"
#include "OcioTestUtil.h"
#include "lut/interp/Sampler.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;

namespace {

OCIO::ConstCPUProcessorRcPtr ocioProcessor(const Lut3D& lut, Interpolation method) {
    return test::ocioCpuProcessor(test::ocioLut3DTransform(lut, method == Interpolation::Tetrahedral
                                                                    ? OCIO::INTERP_TETRAHEDRAL
                                                                    : OCIO::INTERP_LINEAR));
}

std::vector<glm::vec3> oracleInputs(int n) {
    std::vector<glm::vec3> v;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> u(0.0f, 1.0f), wide(-0.5f, 1.5f);
    for (int i = 0; i < 30000; ++i)
        v.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < 3000; ++i)
        v.emplace_back(wide(rng), wide(rng), wide(rng)); // clamped by both
    // Edges: lattice points, midpoints, 0, 1, and their neighbours in float, in every combination.
    std::vector<float> e = {
        0.0f,  1.0f,   0.5f, std::nextafter(1.0f, 0.0f), std::nextafter(0.0f, 1.0f), 1e-7f,
        1e30f, -1e30f, -0.0f};
    for (int i = 0; i < n; i += std::max(1, n / 5)) {
        const float x = static_cast<float>(i) / static_cast<float>(n - 1);
        e.push_back(x);
        e.push_back(std::nextafter(x, 2.0f));
        e.push_back(std::nextafter(x, -1.0f));
        e.push_back((static_cast<float>(i) + 0.5f) / static_cast<float>(n - 1));
    }
    for (float r : e)
        for (float g : e)
            for (float b : e)
                v.emplace_back(r, g, b);
    // Exact greys and near-greys (tetrahedral tie-breaking).
    for (int i = 0; i < 1000; ++i) {
        const float x = u(rng);
        v.emplace_back(x, x, x);
        v.emplace_back(x, x, std::nextafter(x, 2.0f));
    }
    return v;
}

struct Case {
    Interpolation method;
    int size;
    bool random;
};

class AgainstOcio : public ::testing::TestWithParam<Case> {};

} // namespace

TEST_P(AgainstOcio, AgreesWithin1e5) {
    const Case c = GetParam();
    const Lut3D lut = c.random ? test::randomLut(c.size, 99) : test::smoothLut(c.size);
    const auto ours = makeSampler(lut, c.method);
    const auto oracle = ocioProcessor(lut, c.method);
    const auto in = oracleInputs(c.size);

    std::vector<float> theirs, simd;
    for (const auto& v : in)
        theirs.insert(theirs.end(), {v.x, v.y, v.z, 0.75f});
    simd = theirs;
    OCIO::PackedImageDesc desc(theirs.data(), static_cast<long>(in.size()), 1, 4);
    oracle->apply(desc);
    ours->applyPixels(simd.data(), in.size());

    double worst = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const glm::vec3 s = ours->sample(in[i]);
        for (int ch = 0; ch < 3; ++ch) {
            const float o = theirs[4 * i + ch];
            ASSERT_NEAR(s[ch], o, 1e-5) << "scalar vs OCIO at (" << in[i].x << ", " << in[i].y
                                        << ", " << in[i].z << ") channel " << ch;
            ASSERT_NEAR(simd[4 * i + ch], o, 1e-5)
                << "SIMD vs OCIO at (" << in[i].x << ", " << in[i].y << ", " << in[i].z
                << ") channel " << ch;
            worst = std::max(worst, static_cast<double>(std::fabs(simd[4 * i + ch] - o)));
        }
        ASSERT_EQ(simd[4 * i + 3], 0.75f);
    }
    RecordProperty("max_abs_diff", std::to_string(worst));
}

INSTANTIATE_TEST_SUITE_P(
    Luts, AgainstOcio,
    ::testing::Values(
        Case{Interpolation::Trilinear, 2, false}, Case{Interpolation::Trilinear, 17, false},
        Case{Interpolation::Trilinear, 33, false}, Case{Interpolation::Trilinear, 2, true},
        Case{Interpolation::Trilinear, 17, true}, Case{Interpolation::Trilinear, 33, true},
        Case{Interpolation::Tetrahedral, 2, false}, Case{Interpolation::Tetrahedral, 17, false},
        Case{Interpolation::Tetrahedral, 33, false}, Case{Interpolation::Tetrahedral, 2, true},
        Case{Interpolation::Tetrahedral, 17, true}, Case{Interpolation::Tetrahedral, 33, true}),
    [](const ::testing::TestParamInfo<Case>& i) {
        return std::string(toString(i.param.method)) + "_" + std::to_string(i.param.size) +
               (i.param.random ? "_random" : "_smooth");
    });

// NaN and infinities: OCIO's CPU renderer clamps them the same way (NaN -> domain min).
TEST(AgainstOcio, SpecialValues) {
    const Lut3D lut = test::randomLut(17, 5);
    const float inf = std::numeric_limits<float>::infinity(),
                nan = std::numeric_limits<float>::quiet_NaN();
    for (auto method : {Interpolation::Trilinear, Interpolation::Tetrahedral}) {
        const auto ours = makeSampler(lut, method);
        const auto oracle = ocioProcessor(lut, method);
        const std::vector<glm::vec3> in = {
            {inf, 0.5f, 0.2f}, {-inf, 0.5f, 0.2f}, {0.3f, inf, -inf}, {inf, inf, inf}};
        std::vector<float> theirs;
        for (const auto& v : in)
            theirs.insert(theirs.end(), {v.x, v.y, v.z, 1.0f});
        OCIO::PackedImageDesc desc(theirs.data(), static_cast<long>(in.size()), 1, 4);
        oracle->apply(desc);
        for (std::size_t i = 0; i < in.size(); ++i) {
            const glm::vec3 s = ours->sample(in[i]);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(s[ch], theirs[4 * i + ch], 1e-5) << i;
        }
        // NaN: ours is defined as domain min; OCIO's result is only required to be finite here.
        float p[4] = {nan, 0.5f, 0.5f, 1.0f};
        OCIO::PackedImageDesc d1(p, 1, 1, 4);
        oracle->apply(d1);
        const glm::vec3 s = ours->sample(glm::vec3(nan, 0.5f, 0.5f));
        EXPECT_TRUE(test::finite3(s));
        EXPECT_EQ(s, ours->sample(glm::vec3(0.0f, 0.5f, 0.5f)));
        if (std::isfinite(p[0])) {
            EXPECT_NEAR(s.r, p[0], 1e-5);
        }
    }
}
