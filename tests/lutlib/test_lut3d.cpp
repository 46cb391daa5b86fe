// SPDX-License-Identifier: Apache-2.0
// Lut3D / Lut1D value types: identity exactness, storage order, domain checks, 1D apply.
#include "lut/Error.h"
#include "lut/Lut1D.h"
#include "lut/Lut3D.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace lut;

TEST(Lut3D, IdentityIsExactForEverySize) {
    for (int n : {2, 16, 17, 33, 256}) {
        const Lut3D l = Lut3D::identity(n);
        ASSERT_EQ(l.size(), n);
        ASSERT_EQ(l.entryCount(), static_cast<std::size_t>(n) * n * n);
        // Spot-check every lattice value along each axis and the corners, in float64.
        for (int i = 0; i < n; ++i) {
            const double want = static_cast<double>(i) / (n - 1);
            const float f = static_cast<float>(want);
            EXPECT_EQ(l.at(i, 0, 0).r, f) << n << " " << i;
            EXPECT_EQ(l.at(0, i, 0).g, f);
            EXPECT_EQ(l.at(0, 0, i).b, f);
            EXPECT_EQ(l.at(i, n - 1, 0).g, 1.0f);
            EXPECT_EQ(l.at(i, i, i), glm::vec3(f));
        }
        EXPECT_EQ(l.at(n - 1, n - 1, n - 1), glm::vec3(1.0f));
        EXPECT_EQ(l.at(0, 0, 0), glm::vec3(0.0f));
        EXPECT_TRUE(l.isIdentity(0.0f));
        EXPECT_EQ(l.maxDeviationFromIdentity(), 0.0f);
    }
}

TEST(Lut3D, StorageOrderIsRedFastest) {
    const int n = 5;
    Lut3D l(n);
    EXPECT_EQ(l.index(1, 0, 0), 1u);
    EXPECT_EQ(l.index(0, 1, 0), 5u);
    EXPECT_EQ(l.index(0, 0, 1), 25u);
    EXPECT_EQ(l.index(4, 4, 4), 124u);
    l.at(2, 3, 4) = glm::vec3(7, 8, 9);
    const std::size_t i = 2 + 5 * (3 + 5 * 4);
    EXPECT_EQ(l.data()[3 * i], 7.0f);
    EXPECT_EQ(l.data()[3 * i + 1], 8.0f);
    EXPECT_EQ(l.data()[3 * i + 2], 9.0f);
    // The identity's raw bytes follow the same order: the second float triple is (1/(n-1), 0, 0).
    const Lut3D id = Lut3D::identity(n);
    EXPECT_EQ(id.data()[3], 0.25f);
    EXPECT_EQ(id.data()[4], 0.0f);
    EXPECT_EQ(id.data()[3 * 5 + 1], 0.25f); // (0,1,0)
}

TEST(Lut3D, SizeLimits) {
    EXPECT_THROW(Lut3D(1), Error);
    EXPECT_THROW(Lut3D(257), Error);
    EXPECT_THROW(Lut3D(-3), Error);
    EXPECT_NO_THROW(Lut3D(2));
    EXPECT_TRUE(Lut3D().empty());
}

TEST(Lut3D, DomainValidation) {
    Lut3D l(2);
    EXPECT_TRUE(l.hasDefaultDomain());
    EXPECT_THROW(l.setDomain(glm::vec3(1), glm::vec3(0)), Error);
    EXPECT_THROW(l.setDomain(glm::vec3(0), glm::vec3(0)), Error);
    EXPECT_THROW(l.setDomain(glm::vec3(0), glm::vec3(std::numeric_limits<float>::infinity())),
                 Error);
    EXPECT_THROW(l.setDomain(glm::vec3(std::nanf("")), glm::vec3(1)), Error);
    l.setDomain(glm::vec3(-0.5f, 0, 0), glm::vec3(2, 1, 1e-30f));
    EXPECT_FALSE(l.hasDefaultDomain());
    EXPECT_EQ(l.latticeInput(1, 1, 1), glm::vec3(2, 1, 1e-30f));
    EXPECT_EQ(l.latticeInput(0, 0, 0), glm::vec3(-0.5f, 0, 0));
}

TEST(Lut3D, LatticeInputEndsExactly) {
    Lut3D l(33);
    l.setDomain(glm::vec3(-0.1f, 0.0f, 0.3f), glm::vec3(1.3f, 7.0f, 0.30001f));
    EXPECT_EQ(l.latticeInput(32, 32, 32), l.domainMax());
    EXPECT_EQ(l.latticeInput(0, 0, 0), l.domainMin());
    EXPECT_NEAR(l.latticeInput(16, 16, 16).y, 3.5f, 1e-6f);
}

TEST(Lut3D, ValueRangeIgnoresNaN) {
    Lut3D l = Lut3D::identity(2);
    l.at(1, 0, 0).r = std::nanf("");
    l.at(0, 1, 0).g = -2.0f;
    const auto [lo, hi] = l.valueRange();
    EXPECT_EQ(lo, -2.0f);
    EXPECT_EQ(hi, 1.0f);
    EXPECT_EQ(l.maxDeviationFromIdentity(), INFINITY);
}

TEST(Lut1D, IdentityAndInterpolation) {
    const Lut1D id = Lut1D::identity(1024);
    for (float x : {0.0f, 0.1f, 0.25f, 0.5f, 0.7771f, 1.0f})
        EXPECT_NEAR(id.apply(glm::vec3(x)).r, x, 1e-7f) << x;
    EXPECT_EQ(id.apply(glm::vec3(1.0f)).g, 1.0f);
    Lut1D l(3);
    l[0] = glm::vec3(0, 10, -1);
    l[1] = glm::vec3(1, 20, -1);
    l[2] = glm::vec3(4, 40, 3);
    const glm::vec3 a = l.apply(glm::vec3(0.25f, 0.75f, 0.5f));
    EXPECT_FLOAT_EQ(a.r, 0.5f);
    EXPECT_FLOAT_EQ(a.g, 30.0f);
    EXPECT_FLOAT_EQ(a.b, -1.0f);
    EXPECT_EQ(l.apply(glm::vec3(0.5f)), glm::vec3(1, 20, -1)); // on an entry: exact
}

TEST(Lut1D, ExtremeInputs) {
    Lut1D l(3);
    l[0] = glm::vec3(0.1f);
    l[1] = glm::vec3(0.2f);
    l[2] = glm::vec3(0.9f);
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(l.apply(glm::vec3(std::nanf(""))).r, 0.1f);
    EXPECT_EQ(l.apply(glm::vec3(-inf)).r, 0.1f);
    EXPECT_EQ(l.apply(glm::vec3(inf)).r, 0.9f);
    EXPECT_EQ(l.apply(glm::vec3(1e30f)).r, 0.9f);
    EXPECT_EQ(l.apply(glm::vec3(-1e30f)).r, 0.1f);
    EXPECT_EQ(l.apply(glm::vec3(-0.0f)).r, 0.1f);
    EXPECT_EQ(l.apply(glm::vec3(1.0f)).r, 0.9f);
    l.setDomain(glm::vec3(0.0f), glm::vec3(1e-30f));
    EXPECT_EQ(l.apply(glm::vec3(0.5e-30f)).r, 0.2f);
    EXPECT_EQ(l.apply(glm::vec3(1.0f)).r, 0.9f);
    EXPECT_THROW(l.setDomain(glm::vec3(1), glm::vec3(1)), Error);
    EXPECT_THROW(Lut1D(1), Error);
    EXPECT_THROW(Lut1D(65537), Error);
}
