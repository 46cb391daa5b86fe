// SPDX-License-Identifier: Apache-2.0
// The SIMD kernels (applyPixels) against the scalar reference (sample()) on random and extreme
// inputs: same cells, same policy, agreement to float rounding; alpha untouched.
#include "LutTestUtil.h"
#include "lut/interp/Sampler.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace lut;
using lut::test::stressInputs;

namespace {

struct Case {
    Interpolation method;
    int size;
};

class SimdVsScalar : public ::testing::TestWithParam<Case> {};

void checkAgreement(const Lut3D& lut, Interpolation method, const std::vector<glm::vec3>& inputs) {
    const auto s = makeSampler(lut, method);
    std::vector<float> px(4 * inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        px[4 * i] = inputs[i].x;
        px[4 * i + 1] = inputs[i].y;
        px[4 * i + 2] = inputs[i].z;
        px[4 * i + 3] = static_cast<float>(i) * 0.25f - 3.0f; // distinct alpha per pixel
    }
    // Feed the kernel in uneven pieces so every tail length (1..7) goes through the padded path.
    std::size_t done = 0, piece = 1;
    while (done < inputs.size()) {
        const std::size_t n = std::min(piece, inputs.size() - done);
        s->applyPixels(px.data() + 4 * done, n);
        done += n;
        piece = piece % 23 + 1;
    }
    const float tol = method == Interpolation::Nearest ? 0.0f : 2e-6f;
    int bad = 0;
    for (std::size_t i = 0; i < inputs.size() && bad < 10; ++i) {
        const glm::vec3 ref = s->sample(inputs[i]);
        for (int c = 0; c < 3; ++c) {
            const float got = px[4 * i + c];
            if (!(std::fabs(got - ref[c]) <= tol)) {
                ++bad;
                ADD_FAILURE() << toString(method) << " N=" << lut.size() << " input ("
                              << inputs[i].x << ", " << inputs[i].y << ", " << inputs[i].z
                              << ") channel " << c << ": simd " << got << " scalar " << ref[c];
            }
        }
        EXPECT_EQ(px[4 * i + 3], static_cast<float>(i) * 0.25f - 3.0f);
    }
}

} // namespace

TEST_P(SimdVsScalar, RandomLutDefaultDomain) {
    checkAgreement(test::randomLut(GetParam().size), GetParam().method, stressInputs());
}

TEST_P(SimdVsScalar, SmoothLutOffsetDomain) {
    Lut3D lut = test::smoothLut(GetParam().size);
    lut.setDomain(glm::vec3(-0.25f, 0.0f, 0.1f), glm::vec3(1.75f, 4.0f, 0.9f));
    checkAgreement(lut, GetParam().method, stressInputs());
}

TEST_P(SimdVsScalar, DegenerateDomain) {
    Lut3D lut = test::randomLut(GetParam().size, 3);
    lut.setDomain(glm::vec3(0.0f), glm::vec3(1e-30f, 1e-38f, 1e-44f));
    auto in = stressInputs(500);
    in.emplace_back(0.5e-30f, 0.5e-38f, 1e-45f);
    checkAgreement(lut, GetParam().method, in);
}

TEST_P(SimdVsScalar, LatticeInputsAreExact) {
    const Lut3D lut = test::randomLut(GetParam().size, 5);
    const auto s = makeSampler(lut, GetParam().method);
    const int n = lut.size();
    const int step = n > 20 ? 3 : 1;
    std::vector<float> px;
    std::vector<glm::vec3> want;
    for (int b = 0; b < n; b += step)
        for (int g = 0; g < n; g += step)
            for (int r = 0; r < n; r += step) {
                const glm::vec3 in = lut.latticeInput(r, g, b);
                px.insert(px.end(), {in.x, in.y, in.z, 1.0f});
                want.push_back(lut.at(r, g, b));
            }
    s->applyPixels(px.data(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(px[4 * i + c], want[i][c]) << "lattice point " << i;
}

INSTANTIATE_TEST_SUITE_P(
    AllMethods, SimdVsScalar,
    ::testing::Values(Case{Interpolation::Nearest, 2}, Case{Interpolation::Nearest, 17},
                      Case{Interpolation::Nearest, 33}, Case{Interpolation::Trilinear, 2},
                      Case{Interpolation::Trilinear, 3}, Case{Interpolation::Trilinear, 16},
                      Case{Interpolation::Trilinear, 33}, Case{Interpolation::Trilinear, 65},
                      Case{Interpolation::Tetrahedral, 2}, Case{Interpolation::Tetrahedral, 3},
                      Case{Interpolation::Tetrahedral, 16}, Case{Interpolation::Tetrahedral, 17},
                      Case{Interpolation::Tetrahedral, 33}, Case{Interpolation::Tetrahedral, 65}),
    [](const ::testing::TestParamInfo<Case>& i) {
        return std::string(toString(i.param.method)) + "_" + std::to_string(i.param.size);
    });

namespace {
bool cpuHasAvx512() {
#if defined(__x86_64__)
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
           __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
#else
    return false;
#endif
}
} // namespace

TEST(SamplerIsa, ReportsAKnownPath) {
    const std::string isa = samplerIsa();
    EXPECT_TRUE(isa == "avx512" || isa == "avx2" || isa == "scalar") << isa;
#if defined(__x86_64__)
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
        !std::getenv("LUTKIT_SIMD")) {
        EXPECT_EQ(isa, cpuHasAvx512() ? "avx512" : "avx2");
    }
#endif
}

// The AVX-512 tetrahedral kernel promises the AVX2 kernel's bits (same operations in the same
// order, 16 lanes instead of 8): no output changes on CPUs that have it. Every tail length, NaN,
// Inf, HDR and lattice inputs, sizes 2 to 65; the agreement of both with the scalar reference
// and OpenColorIO is checked by SimdVsScalar and test_sampler_ocio.
TEST(SamplerIsa, Avx512TetrahedralIsBitIdenticalToAvx2) {
    if (!cpuHasAvx512() || std::getenv("LUTKIT_SIMD"))
        GTEST_SKIP() << "this CPU has no AVX-512 F + DQ (or LUTKIT_SIMD is set)";
    for (int size : {2, 3, 17, 33, 65}) {
        Lut3D lut = test::randomLut(size, 11);
        if (size == 17)
            lut.setDomain(glm::vec3(-0.25f, 0.0f, 0.1f), glm::vec3(1.75f, 4.0f, 0.9f));
        auto inputs = stressInputs(3000);
        for (int b = 0; b < size; b += std::max(1, size / 5))
            for (int g = 0; g < size; g += std::max(1, size / 5))
                for (int r = 0; r < size; ++r)
                    inputs.push_back(lut.latticeInput(r, g, b));
        std::vector<float> wide, narrow;
        for (std::size_t i = 0; i < inputs.size(); ++i)
            wide.insert(wide.end(), {inputs[i].x, inputs[i].y, inputs[i].z, float(i)});
        narrow = wide;
        const auto fast = makeSampler(lut, Interpolation::Tetrahedral);
        ASSERT_STREQ(samplerIsa(), "avx512");
        ::setenv("LUTKIT_SIMD", "avx2", 1);
        const auto twin = makeSampler(lut, Interpolation::Tetrahedral);
        EXPECT_STREQ(samplerIsa(), "avx2");
        ::unsetenv("LUTKIT_SIMD");
        std::size_t done = 0, piece = 1;
        while (done < inputs.size()) { // uneven pieces: every tail length 1..15 and full blocks
            const std::size_t n = std::min(piece, inputs.size() - done);
            fast->applyPixels(wide.data() + 4 * done, n);
            twin->applyPixels(narrow.data() + 4 * done, n);
            done += n;
            piece = piece % 37 + 1;
        }
        ASSERT_EQ(std::memcmp(wide.data(), narrow.data(), wide.size() * sizeof(float)), 0)
            << "N=" << size;
    }
}

TEST(SamplerIsa, ScalarCanBeForcedAndAgrees) {
    const Lut3D lut = test::smoothLut(17);
    const auto inputs = stressInputs(1000);
    std::vector<float> a, b;
    for (const auto& v : inputs)
        a.insert(a.end(), {v.x, v.y, v.z, 0.5f});
    b = a;
    const auto fast = makeSampler(lut, Interpolation::Tetrahedral);
    ::setenv("LUTKIT_SIMD", "scalar", 1);
    const auto slow = makeSampler(lut, Interpolation::Tetrahedral);
    EXPECT_STREQ(samplerIsa(), "scalar");
    ::unsetenv("LUTKIT_SIMD");
    fast->applyPixels(a.data(), inputs.size());
    slow->applyPixels(b.data(), inputs.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        ASSERT_NEAR(a[i], b[i], 2e-6f) << i;
}

// The portable forms of the kernels (what the browser edition and CPUs without AVX2 run) give the
// AVX2 kernels' bits, on every input the stress set has (NaN, infinities, the domain's edges,
// lattice points and between them) and on random LUTs: the editions write the same files.
TEST(SamplerIsa, PortableKernelsAreBitIdenticalToAvx2) {
    if (std::strcmp(samplerIsa(), "scalar") == 0)
        GTEST_SKIP() << "this CPU has no AVX2 + FMA (or LUTKIT_SIMD=scalar is set)";
    for (const Interpolation method : {Interpolation::Trilinear, Interpolation::Tetrahedral})
        for (const int size : {2, 5, 17, 33, 65}) {
            const Lut3D lut = test::randomLut(size);
            const auto inputs = stressInputs();
            std::vector<float> a;
            for (std::size_t i = 0; i < inputs.size(); ++i)
                a.insert(a.end(), {inputs[i].x, inputs[i].y, inputs[i].z, 0.25f * i});
            std::vector<float> b = a;
            const auto simd = makeSampler(lut, method);
            ::setenv("LUTKIT_SIMD", "scalar", 1);
            const auto portable = makeSampler(lut, method);
            ::unsetenv("LUTKIT_SIMD");
            simd->applyPixels(a.data(), inputs.size());
            portable->applyPixels(b.data(), inputs.size());
            for (std::size_t i = 0; i < a.size(); ++i)
                ASSERT_EQ(std::memcmp(&a[i], &b[i], sizeof(float)), 0)
                    << toString(method) << " N=" << size << " value " << i << ": " << a[i] << " vs "
                    << b[i];
        }
}
