// SPDX-License-Identifier: Apache-2.0
// The linear Monge-Kantorovich map against its defining property, checked in float64 here: the
// mapped source has the reference's mean and covariance, and the matrix is symmetric positive
// definite (no fold-over).
#include "lut/match/MongeKantorovich.h"

#include <gtest/gtest.h>

#include <glm/matrix.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace lut;

namespace {

std::vector<glm::dvec3> gaussian(const glm::dmat3& shape, const glm::dvec3& mean, int n,
                                 unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<glm::dvec3> out;
    for (int i = 0; i < n; ++i)
        out.push_back(mean + shape * glm::dvec3(g(rng), g(rng), g(rng)));
    return out;
}

void moments(const std::vector<glm::dvec3>& v, glm::dvec3& mean, glm::dmat3& cov) {
    mean = glm::dvec3(0.0);
    for (const auto& x : v)
        mean += x;
    mean /= static_cast<double>(v.size());
    cov = glm::dmat3(0.0);
    for (const auto& x : v)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                cov[i][j] += (x[i] - mean[i]) * (x[j] - mean[j]);
    cov /= static_cast<double>(v.size());
}

} // namespace

TEST(MongeKantorovich, MapsCovarianceOntoTheReference) {
    const auto src = gaussian(glm::dmat3(0.10, 0.02, 0.01, 0.0, 0.08, 0.02, 0.0, 0.0, 0.05),
                              glm::dvec3(0.4, 0.5, 0.45), 20000, 1);
    const auto ref = gaussian(glm::dmat3(0.12, 0.0, 0.03, 0.01, 0.06, 0.0, 0.02, 0.01, 0.09),
                              glm::dvec3(0.55, 0.45, 0.35), 20000, 2);
    ColourMoments ms, mr;
    for (const auto& x : src)
        ms.add(x);
    for (const auto& x : ref)
        mr.add(x);
    MklNotes notes;
    const AffineColourMap m = mongeKantorovich(ms, mr, 4.0, 1e-12, &notes);
    EXPECT_FALSE(notes.gainLimited);
    std::vector<glm::dvec3> mapped;
    for (const auto& x : src)
        mapped.push_back(m(x));
    glm::dvec3 mu, muRef;
    glm::dmat3 cov, covRef;
    moments(mapped, mu, cov);
    moments(ref, muRef, covRef);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(mu[i], muRef[i], 1e-9);
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(cov[i][j], covRef[i][j], 1e-9) << i << " " << j;
            EXPECT_NEAR(m.matrix[i][j], m.matrix[j][i], 1e-12); // symmetric
        }
    }
    glm::dvec3 values;
    glm::dmat3 vectors;
    symmetricEigen(m.matrix, values, vectors);
    EXPECT_GT(std::min({values.x, values.y, values.z}), 0.0);
}

TEST(MongeKantorovich, AGreySourceHasItsColourGainLimited) {
    // Almost all variance along grey: the chroma directions would need a gain of ~100.
    std::mt19937 rng(5);
    std::normal_distribution<double> g(0.0, 1.0);
    ColourMoments ms, mr;
    for (int i = 0; i < 5000; ++i) {
        const double t = 0.5 + 0.2 * g(rng);
        ms.add(glm::dvec3(t) + 0.001 * glm::dvec3(g(rng), g(rng), g(rng)));
        mr.add(glm::dvec3(0.5) + 0.15 * glm::dvec3(g(rng), g(rng), g(rng)));
    }
    MklNotes notes;
    const AffineColourMap m = mongeKantorovich(ms, mr, 4.0, 1e-12, &notes);
    EXPECT_TRUE(notes.gainLimited);
    EXPECT_GT(notes.largestGain, 50.0);
    EXPECT_LT(notes.sourceSpread, 0.002);
    glm::dvec3 values;
    glm::dmat3 vectors;
    symmetricEigen(m.matrix, values, vectors);
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(values[i], 4.0 + 1e-9);
        EXPECT_GE(values[i], 0.25 - 1e-9);
    }
}

TEST(MongeKantorovich, EigenDecompositionRebuildsTheMatrix) {
    const glm::dmat3 a(2.0, 0.3, -0.4, 0.3, 1.0, 0.2, -0.4, 0.2, 0.5);
    glm::dvec3 values;
    glm::dmat3 vectors;
    symmetricEigen(a, values, vectors);
    glm::dmat3 d(0.0);
    for (int i = 0; i < 3; ++i)
        d[i][i] = values[i];
    const glm::dmat3 back = vectors * d * glm::transpose(vectors);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(back[i][j], a[i][j], 1e-12);
}
