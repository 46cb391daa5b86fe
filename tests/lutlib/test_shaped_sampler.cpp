// SPDX-License-Identifier: Apache-2.0
// A LUT file's 1D shaper then its 3D table, evaluated exactly (makeSampler(LutFile)): the shaper
// against a float64 linear interpolation written here from Lut1D's definition, the whole against
// OpenColorIO's processor for a Lut1DTransform then a Lut3DTransform holding the same entries,
// and the SIMD kernel against sample() bit for bit (NaN, +-Inf, HDR, 2 and 65536 entries).
#include "LutTestUtil.h"
#include "OcioTestUtil.h"
#include "lut/LutFile.h"
#include "lut/interp/PixelChain.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/InvertFile.h"
#include "lut/ops/Lattice.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

// A log2 shaper over [0, 64] (the case): (log2(x) + 8) / 14, clamped to [0, 1].
Lut1D log2Shaper(int n) {
    Lut1D s(n);
    s.setDomain(glm::vec3(0.0f), glm::vec3(64.0f));
    for (int i = 0; i < n; ++i) {
        const double x = 64.0 * i / (n - 1);
        const double y = x <= 0 ? 0.0 : std::clamp((std::log2(x) + 8.0) / 14.0, 0.0, 1.0);
        s[i] = glm::vec3(static_cast<float>(y));
    }
    return s;
}

LutFile shapedFile(int shaperSize, int cubeSize) {
    LutFile f;
    f.shaper = log2Shaper(shaperSize);
    f.cube = test::smoothLut(cubeSize);
    return f;
}

// Lut1D's definition in float64: t = (x - min) / (max - min) * (N - 1), clamped to [0, N - 1]
// (NaN as min), then linear between entries.
double shaperReference(const Lut1D& s, int c, double x) {
    const int n = s.size();
    if (std::isnan(x))
        x = s.domainMin()[c];
    double t = (x - s.domainMin()[c]) / (double(s.domainMax()[c]) - s.domainMin()[c]) * (n - 1);
    t = std::clamp(t, 0.0, double(n - 1));
    const int i = std::min(static_cast<int>(t), n - 2);
    const double f = t - i;
    return (1 - f) * s[i][c] + f * s[i + 1][c];
}

OCIO::ConstCPUProcessorRcPtr ocioShaped(const LutFile& file) {
    auto group = OCIO::GroupTransform::Create();
    const Lut1D& s = *file.shaper;
    // The shaper's domain onto [0, 1], then its entries.
    const glm::vec3 lo = s.domainMin(), hi = s.domainMax();
    auto range = OCIO::RangeTransform::Create();
    range->setStyle(OCIO::RANGE_CLAMP);
    range->setMinInValue(lo.x);
    range->setMaxInValue(hi.x);
    range->setMinOutValue(0.0);
    range->setMaxOutValue(1.0);
    group->appendTransform(range);
    auto l1 = OCIO::Lut1DTransform::Create(static_cast<unsigned long>(s.size()), false);
    for (int i = 0; i < s.size(); ++i)
        l1->setValue(static_cast<unsigned long>(i), s[i].r, s[i].g, s[i].b);
    l1->setInterpolation(OCIO::INTERP_LINEAR);
    group->appendTransform(l1);
    group->appendTransform(test::ocioLut3DTransform(*file.cube, OCIO::INTERP_TETRAHEDRAL));
    return test::ocioCpuProcessor(group);
}

glm::vec3 viaKernel(const Sampler& s, glm::vec3 in) {
    float px[4] = {in.x, in.y, in.z, 0.25f};
    s.applyPixels(px, 1);
    EXPECT_EQ(px[3], 0.25f);
    return glm::vec3(px[0], px[1], px[2]);
}

} // namespace

TEST(ShapedSampler, ShaperAloneIsLinearBetweenItsEntries) {
    for (int n : {2, 17, 4096, 65536}) {
        LutFile f;
        f.shaper = log2Shaper(n);
        if (n == 2) // a ramp with a domain off [0, 1], different per channel
            f.shaper->setDomain(glm::vec3(-0.5f, 0.0f, 1.0f), glm::vec3(2.0f, 1.0f, 3.0f));
        const auto s = makeSampler(f, Interpolation::Tetrahedral);
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> u(-1.0f, 70.0f);
        double worst = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 x(u(rng), u(rng) * 0.02f, u(rng) * 0.5f);
            const glm::vec3 got = s->sample(x);
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(got[c] - shaperReference(*f.shaper, c, x[c])));
        }
        EXPECT_LT(worst, 2e-6) << n << " entries";
        // Exactly the entry at an entry's input.
        for (int i = 0; i < n; i += std::max(1, n / 50)) {
            const float x = static_cast<float>(64.0 * i / (n - 1));
            if (n == 2)
                continue;
            EXPECT_EQ(s->sample(glm::vec3(x)).x, (*f.shaper)[i].x) << n << " entry " << i;
        }
    }
}

TEST(ShapedSampler, ShaperThenTableEqualsOcio) {
    const LutFile f = shapedFile(4096, 33);
    const auto ours = makeSampler(f, Interpolation::Tetrahedral);
    const auto ocio = ocioShaped(f);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), hdr(0.0f, 64.0f);
    double worst = 0;
    for (int i = 0; i < 40000; ++i) {
        glm::vec3 x = i % 4 == 0 ? glm::vec3(hdr(rng), hdr(rng), hdr(rng))
                                 : glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 got = viaKernel(*ours, x);
        ocio->applyRGB(&x.x);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(double(got[c]) - x[c]));
    }
    EXPECT_LT(worst, 1e-5) << "largest difference from OCIO (1e-5 = 0.0026 8-bit steps)";
}

TEST(ShapedSampler, KernelEqualsSampleBitForBit) {
    // The shaper's kernel is the scalar path bit for bit; the table after it agrees to float
    // rounding (the 3D kernels' contract, lut/interp/Sampler.h).
    for (int n : {2, 4096, 65536}) {
        LutFile f = shapedFile(n, n == 2 ? 2 : 17);
        const bool alone = n != 4096;
        if (alone)
            f.cube.reset();
        const auto s = makeSampler(f, Interpolation::Tetrahedral);
        std::vector<float> px;
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> u(-2.0f, 80.0f);
        const float specials[] = {kNaN, kInf, -kInf, 0.0f, -0.0f, 64.0f, 1e30f, -1e30f, 1.0f};
        for (float v : specials)
            px.insert(px.end(), {v, 0.5f, v, 0.75f});
        for (int i = 0; i < 1003; ++i) // not a multiple of 8: the tail too
            px.insert(px.end(), {u(rng), u(rng) * 0.01f, u(rng) * 0.2f, 0.5f});
        std::vector<float> k = px;
        s->applyPixels(k.data(), k.size() / 4);
        for (std::size_t i = 0; i < px.size() / 4; ++i) {
            const glm::vec3 want = s->sample(glm::vec3(px[4 * i], px[4 * i + 1], px[4 * i + 2]));
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(k[4 * i + c])) << "pixel " << i;
                if (alone)
                    EXPECT_EQ(k[4 * i + c], want[c]) << n << " entries, pixel " << i << " " << c;
                else
                    EXPECT_NEAR(k[4 * i + c], want[c], 2e-6f) << "pixel " << i << " " << c;
            }
            EXPECT_EQ(k[4 * i + 3], px[4 * i + 3]) << "alpha kept";
        }
    }
}

TEST(ShapedSampler, ScalarPathEqualsKernel) {
    const LutFile f = shapedFile(1024, 33);
    const auto simd = makeSampler(f, Interpolation::Trilinear);
    ::setenv("LUTKIT_SIMD", "scalar", 1);
    const auto scalar = makeSampler(f, Interpolation::Trilinear);
    ::unsetenv("LUTKIT_SIMD");
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 2.0f);
    std::vector<float> a;
    for (int i = 0; i < 4001; ++i)
        a.insert(a.end(), {u(rng), u(rng), u(rng), 1.0f});
    std::vector<float> b = a;
    simd->applyPixels(a.data(), a.size() / 4);
    scalar->applyPixels(b.data(), b.size() / 4);
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_NEAR(a[i], b[i], 2e-6f) << i; // the 3D kernels agree to float rounding
}

TEST(ShapedSampler, PixelChainWatchesTheShapersDomain) {
    PixelChain chain;
    chain.setLut(shapedFile(4096, 9));
    EXPECT_EQ(chain.domainMax(), glm::vec3(64.0f));
    EXPECT_FALSE(chain.isIdentityOnUnitRange());
    float px[8] = {10.0f, 20.0f, 30.0f, 1.0f, 70.0f, 0.5f, 0.5f, 1.0f};
    DomainStats st;
    chain.run(px, 2, &st);
    EXPECT_EQ(st.outside, 1u); // only 70 is outside [0, 64]
}

TEST(Lattice, HeldOutErrorBoundsTheTruthBetweenLatticePoints) {
    // The shaped file as one 16^3 lattice over [0,1] read trilinearly (the game's case): the
    // printed error, measured on the lattice's own held-out inputs, against the truth on other
    // inputs (a different random sequence), with OCIO evaluating the file.
    const LutFile f = shapedFile(4096, 33);
    LatticeRequest q;
    q.size = 16;
    q.domainMin = glm::vec3(0.0f);
    q.domainMax = glm::vec3(1.0f);
    q.readWith = Interpolation::Trilinear;
    const LatticeResult r = sampleOnLattice(f, q);
    ASSERT_GT(r.heldOut, 200000u);
    const auto ocio = ocioShaped(f);
    // At the lattice points: the file itself.
    for (int b = 0; b < 16; b += 5)
        for (int g = 0; g < 16; g += 3)
            for (int rr = 0; rr < 16; rr += 7) {
                glm::vec3 x = r.lut.latticeInput(rr, g, b);
                const glm::vec3 e = r.lut.at(rr, g, b);
                ocio->applyRGB(&x.x);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(e[c], x[c], 1e-5);
            }
    // Between them: trilinear interpolation of the lattice written plainly in float64.
    auto trilinear = [&](glm::vec3 x) {
        glm::dvec3 t = glm::dvec3(x) * 15.0;
        int i[3];
        double fr[3];
        for (int c = 0; c < 3; ++c) {
            i[c] = std::min(14, static_cast<int>(t[c]));
            fr[c] = t[c] - i[c];
        }
        glm::dvec3 acc(0.0);
        for (int k = 0; k < 8; ++k) {
            const int dr = k & 1, dg = (k >> 1) & 1, db = k >> 2;
            const double w =
                (dr ? fr[0] : 1 - fr[0]) * (dg ? fr[1] : 1 - fr[1]) * (db ? fr[2] : 1 - fr[2]);
            acc += w * glm::dvec3(r.lut.at(i[0] + dr, i[1] + dg, i[2] + db));
        }
        return acc;
    };
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double truth = 0;
    for (int k = 0; k < 60000; ++k) {
        glm::vec3 x(u(rng), u(rng), u(rng));
        const glm::dvec3 got = trilinear(x);
        ocio->applyRGB(&x.x);
        for (int c = 0; c < 3; ++c)
            truth = std::max(truth, std::fabs(got[c] - x[c]));
    }
    EXPECT_GE(r.error.maxAbs, truth) << "printed max below the truth";
    EXPECT_GT(truth, 0.5 * r.error.maxAbs) << "the estimate is not wildly pessimistic";
}

TEST(InvertFile, ShaperThenTableInvertedEntryByEntry) {
    // Each entry of the inverse, taken forward by OCIO's processor of the file, gives back its
    // lattice input where the grade reaches it (the middle of the cube).
    const LutFile f = shapedFile(4096, 17);
    InvertOptions o;
    o.size = 9;
    const FileInvertResult r = invert(f, o);
    ASSERT_EQ(r.table.lut.size(), 9);
    EXPECT_GT(r.heldOut, 100000u);
    EXPECT_TRUE(std::isfinite(r.heldOutResidual.maxAbs));
    const auto ocio = ocioShaped(f);
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int rr = 0; rr < 9; ++rr) {
                const glm::vec3 y = r.table.lut.latticeInput(rr, g, b);
                glm::vec3 x = r.table.lut.at(rr, g, b);
                EXPECT_TRUE(x.x >= 0.0f && x.x <= 64.0f) << "inside the shaper's range";
                if (std::min({rr, g, b}) < 3 || std::max({rr, g, b}) > 5)
                    continue; // the middle of the cube, inside the grade's gamut
                ocio->applyRGB(&x.x);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(x[c], y[c], 1e-4) << rr << " " << g << " " << b;
            }
}
