// SPDX-License-Identifier: Apache-2.0
// compose, mix, strength and smooth (lut/ops/Compose.h, Smooth.h) against float64 references
// written here, and the honesty of the errors they report.
#include "OpsTestUtil.h"

#include "lut/ops/Compose.h"
#include "lut/ops/Resize.h"
#include "lut/ops/Smooth.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lut;
using namespace lut::opstest;

namespace {

// Per-channel 1D linear interpolation of table[c] (n entries over [0, 1]) in float64: what
// tetrahedral interpolation gives for a LUT whose output channel c depends on input c only.
double interp1(const std::vector<double>& t, double x) {
    const int n = static_cast<int>(t.size());
    const double p = std::clamp(x, 0.0, 1.0) * (n - 1);
    const int i = std::min(static_cast<int>(p), n - 2);
    return t[static_cast<std::size_t>(i)] +
           (p - i) * (t[static_cast<std::size_t>(i) + 1] - t[static_cast<std::size_t>(i)]);
}

} // namespace

TEST(Compose, IdentityFirstGivesTheSecondLutExactly) {
    const Lut3D b = lutFrom(17, smoothGrade);
    const OpResult r = compose(Lut3D::identity(17), b);
    EXPECT_TRUE(sameBits(r.lut, b));
    EXPECT_EQ(r.error.maxAbs, 0.0);
    EXPECT_GT(r.error.count, 0u);
}

TEST(Compose, MatchesAFloat64Reference) {
    // A squares each channel, B takes the square root; both separable, so the composition at a
    // result lattice point is B's 1D interpolation at A's exact output.
    const int na = 17, nb = 9;
    const Lut3D a = lutFrom(na, [](glm::vec3 x) { return x * x; });
    const Lut3D b = lutFrom(nb, [](glm::vec3 x) { return glm::sqrt(x); });
    std::vector<double> tb(nb);
    for (int i = 0; i < nb; ++i)
        tb[static_cast<std::size_t>(i)] =
            std::sqrt(static_cast<double>(static_cast<float>(i) / (nb - 1)));
    ComposeOptions o;
    o.size = 33;
    const OpResult r = compose(a, b, o);
    ASSERT_EQ(r.lut.size(), 33);
    std::vector<double> ta(na);
    for (int i = 0; i < na; ++i) {
        const double v = static_cast<float>(i) / (na - 1);
        ta[static_cast<std::size_t>(i)] = static_cast<float>(v * v);
    }
    for (int k = 0; k < 33; ++k) {
        const double x = static_cast<float>(k) / 32.0f;
        const double want = interp1(tb, interp1(ta, x));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(r.lut.at(k, k, k)[c], want, 2e-6) << k;
        EXPECT_NEAR(r.lut.at(k, 0, 32).r, want, 2e-6);
    }
    // Affine LUTs compose exactly: (2x - 0.5) after (0.5x + 0.25) is the identity.
    const OpResult id = compose(lutFrom(5, [](glm::vec3 x) { return 0.5f * x + 0.25f; }),
                                lutFrom(9, [](glm::vec3 x) { return 2.0f * x - 0.5f; }));
    EXPECT_LT(id.lut.maxDeviationFromIdentity(), 1e-6f);
    EXPECT_LT(id.error.maxAbs, 1e-6);
}

TEST(Compose, ReportedErrorIsNeverBelowTheTruthAtCellCentres) {
    // The exact composition of x^2 then sqrt(x) (interpolated as LUTs) against a coarse result:
    // the error at each result cell centre on the neutral axis, computed here in float64, must
    // not exceed what compose reports (its probe grid includes those centres).
    const int na = 33, nb = 33;
    const Lut3D a = lutFrom(na, [](glm::vec3 x) { return x * x; });
    const Lut3D b = lutFrom(nb, [](glm::vec3 x) { return glm::sqrt(x); });
    std::vector<double> ta(na), tb(nb);
    for (int i = 0; i < na; ++i) {
        const double v = static_cast<float>(i) / (na - 1);
        ta[static_cast<std::size_t>(i)] = static_cast<float>(v * v);
        tb[static_cast<std::size_t>(i)] = static_cast<float>(std::sqrt(v));
    }
    double previous = INFINITY;
    for (int size : {5, 9, 17}) {
        ComposeOptions o;
        o.size = size;
        const OpResult r = compose(a, b, o);
        std::vector<double> tr(static_cast<std::size_t>(size));
        for (int i = 0; i < size; ++i)
            tr[static_cast<std::size_t>(i)] = r.lut.at(i, i, i).r;
        double truth = 0.0;
        for (int i = 0; i + 1 < size; ++i) {
            const double x = (i + 0.5) / (size - 1);
            truth = std::max(truth, std::fabs(interp1(tb, interp1(ta, x)) - interp1(tr, x)));
        }
        EXPECT_GT(truth, 1e-4) << size; // a real error to report
        EXPECT_GE(r.error.maxAbs, truth - 1e-6) << size;
        EXPECT_LT(r.error.maxAbs, previous) << "a larger lattice must be closer";
        previous = r.error.maxAbs;
        std::printf("[compose] x^2 then sqrt at size %d: %s\n", size, r.error.str().c_str());
    }
}

TEST(Compose, MixAndStrength) {
    const Lut3D a = lutFrom(9, smoothGrade);
    const Lut3D b = randomLut(9);
    EXPECT_TRUE(sameBits(mix(a, b, 0.0).lut, a));
    EXPECT_TRUE(sameBits(mix(a, b, 1.0).lut, b));
    const OpResult q = mix(a, b, 0.25);
    EXPECT_EQ(q.error.maxAbs, 0.0);
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(q.lut.entries()[i][c], static_cast<float>(0.75 * a.entries()[i][c] +
                                                                      0.25 * b.entries()[i][c]));
    // Another size: B is resampled onto A's lattice and the error says by how much.
    const OpResult other = mix(Lut3D::identity(3), lutFrom(33, smoothGrade), 0.5);
    EXPECT_EQ(other.lut.size(), 3);
    EXPECT_GT(other.error.maxAbs, 1e-3);
    EXPECT_LT(other.error.maxAbs, 0.5);
    // Strength 0 is the identity, 1 the LUT itself.
    EXPECT_TRUE(sameBits(withStrength(a, 0.0), Lut3D::identity(9)));
    EXPECT_TRUE(sameBits(withStrength(a, 1.0), a));
    // NaN/Inf entries: finite results, counted.
    const OpResult bad = mix(withNonFinite(a), b, 0.5);
    EXPECT_TRUE(allFinite(bad.lut));
    EXPECT_EQ(bad.sanitizedEntries, 3u);
    EXPECT_TRUE(allFinite(withStrength(withNonFinite(a), 2.0)));
}

TEST(Smooth, KeepsIdentityAndAffineLutsAndZeroSigma) {
    const Lut3D id = Lut3D::identity(17);
    EXPECT_TRUE(sameBits(smooth(id, 2.0).lut, id));
    const Lut3D affine = lutFrom(17, [](glm::vec3 x) {
        return glm::vec3(0.8f * x.r + 0.1f, 0.5f * x.g + 0.2f * x.b, 1.0f - x.b);
    });
    const OpResult s = smooth(affine, 1.5);
    for (std::size_t i = 0; i < affine.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(s.lut.entries()[i][c], affine.entries()[i][c], 1e-6);
    // A kernel wider than the lattice (3 sigma = 24 steps on a 3^3 LUT): the reflection past
    // the edge repeats, so the affine LUT still stays itself (it moved by 0.12 when the far edge
    // entry was repeated instead).
    for (const int n : {2, 3, 5}) {
        const Lut3D small = lutFrom(n, [](glm::vec3 x) {
            return glm::vec3(0.8f * x.r + 0.1f, 0.5f * x.g + 0.2f * x.b, 1.0f - 0.7f * x.b);
        });
        const OpResult w = smooth(small, 8.0);
        for (std::size_t i = 0; i < small.entryCount(); ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(w.lut.entries()[i][c], small.entries()[i][c], 1e-6) << n;
    }
    const Lut3D noisy = randomLut(9);
    const OpResult none = smooth(noisy, 0.0);
    EXPECT_TRUE(sameBits(none.lut, noisy));
    EXPECT_EQ(none.error.maxAbs, 0.0);
}

TEST(Smooth, SpikeSpreadsAsTheGaussianKernel) {
    // One entry of the identity raised by 1 in the middle of a 33 lattice: the result's deviation
    // is the product of three normalized 1D Gaussians, far from any edge.
    const int n = 33, c0 = 16;
    const double sigma = 1.2;
    Lut3D lut = Lut3D::identity(n);
    lut.at(c0, c0, c0) += glm::vec3(1.0f, 0.0f, 0.0f);
    const OpResult res = smooth(lut, sigma);
    const int radius = static_cast<int>(std::ceil(3 * sigma));
    std::vector<double> k(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i)
        sum += k[static_cast<std::size_t>(i + radius)] = std::exp(-0.5 * i * i / (sigma * sigma));
    for (double& v : k)
        v /= sum;
    const Lut3D id = Lut3D::identity(n);
    for (int db = -radius - 1; db <= radius + 1; ++db)
        for (int dg = -radius - 1; dg <= radius + 1; ++dg)
            for (int dr = -radius - 1; dr <= radius + 1; ++dr) {
                auto w = [&](int d) {
                    return std::abs(d) > radius ? 0.0 : k[static_cast<std::size_t>(d + radius)];
                };
                const double want = w(dr) * w(dg) * w(db);
                const int r = c0 + dr, g = c0 + dg, b = c0 + db;
                EXPECT_NEAR(res.lut.at(r, g, b).r - id.at(r, g, b).r, want, 2e-7);
                EXPECT_NEAR(res.lut.at(r, g, b).g - id.at(r, g, b).g, 0.0, 1e-7);
            }
    // Its error is how much the LUT changed: at least the spike's own drop.
    EXPECT_GE(res.error.maxAbs, 1.0 -
                                    k[static_cast<std::size_t>(radius)] *
                                        k[static_cast<std::size_t>(radius)] *
                                        k[static_cast<std::size_t>(radius)] -
                                    1e-6);
}

TEST(Smooth, StableOnExtremeLuts) {
    const Lut3D step =
        lutFrom(17, [](glm::vec3 x) { return x.g < 0.5f ? glm::vec3(0.0f) : glm::vec3(1.0f); });
    for (const Lut3D& l : {withNonFinite(randomLut(9)), step, Lut3D::identity(2), randomLut(2)}) {
        for (double s : {0.5, 8.0, 1e9, double(NAN)}) {
            const OpResult r = smooth(l, s);
            EXPECT_TRUE(allFinite(r.lut)) << l.size() << " sigma " << s;
            EXPECT_TRUE(std::isfinite(r.error.maxAbs));
        }
    }
    // A smoothed step keeps its range (a Gaussian of a monotone step is monotone).
    const OpResult r = smooth(step, 2.0);
    for (int g = 1; g < 17; ++g)
        EXPECT_GE(r.lut.at(3, g, 3).r, r.lut.at(3, g - 1, 3).r - 1e-6);
}

TEST(Compose, SizeTwoAndLargeLattices) {
    const OpResult two = compose(randomLut(2), randomLut(2, 9));
    EXPECT_EQ(two.lut.size(), 2);
    EXPECT_TRUE(allFinite(two.lut));
    ComposeOptions o;
    o.size = 129;
    const OpResult big = compose(lutFrom(33, smoothGrade), withNonFinite(randomLut(2)), o);
    EXPECT_EQ(big.lut.size(), 129);
    EXPECT_TRUE(allFinite(big.lut));
    EXPECT_EQ(big.sanitizedEntries, 3u);
    // 129 lattice points per axis: the probes must not all sit on the lattice (error 0 there).
    EXPECT_GT(big.error.maxAbs, 0.0);
    std::printf("[compose] 33 then 2 at size 129: %s\n", big.error.str().c_str());
}

TEST(Resize, ReportsTheErrorAndStaysFiniteOnNaN) {
    // Affine LUTs resize exactly; a curved one reports what the smaller lattice loses.
    const OpResult affine = resize(lutFrom(9, [](glm::vec3 x) { return 0.5f * x + 0.25f; }), 33);
    EXPECT_EQ(affine.lut.size(), 33);
    EXPECT_LT(affine.error.maxAbs, 1e-6);
    const OpResult curved = resize(lutFrom(33, [](glm::vec3 x) { return x * x; }), 5);
    // x^2 on a 5 lattice: the chord error at a cell centre is h^2 / 4 = 1/64 at most, reached
    // there; the reported maximum bounds it, a little above (lut/ops/ErrorBound.h).
    EXPECT_GE(curved.error.maxAbs, 1.0 / 64.0 - 1e-6);
    EXPECT_LE(curved.error.maxAbs, 1.03 / 64.0);
    const OpResult bad = resize(withNonFinite(randomLut(9)), 17);
    EXPECT_EQ(bad.sanitizedEntries, 3u);
    EXPECT_TRUE(allFinite(bad.lut));
    EXPECT_TRUE(std::isfinite(bad.error.maxAbs));
}
