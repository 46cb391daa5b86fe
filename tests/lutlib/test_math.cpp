// SPDX-License-Identifier: Apache-2.0
// lut/Math.h (musl's functions compiled by lutkit) against the C library's (glibc here): both
// are within about one unit in the last place of the true value (musl's float sin, cos, atan2 and
// hypot within 1.5), so they agree within four; and
// the overloads are <cmath>'s (float in, float out; mixed or integer arguments in double).
#include "lut/Math.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>

namespace {

template <class T> std::int64_t ulps(T a, T b) {
    if (std::isnan(a) && std::isnan(b))
        return 0;
    if (a == b)
        return 0;
    using I = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;
    I ia, ib;
    std::memcpy(&ia, &a, sizeof a);
    std::memcpy(&ib, &b, sizeof b);
    if ((ia < 0) != (ib < 0))
        return std::numeric_limits<std::int64_t>::max();
    return ia > ib ? static_cast<std::int64_t>(ia) - ib : static_cast<std::int64_t>(ib) - ia;
}

} // namespace

TEST(Math, EveryFunctionIsWithinFourUlpsOfTheCLibrary) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::int64_t worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = u(rng) * 4.0, y = u(rng) * 4.0 - 2.0, w = (u(rng) - 0.5) * 40.0;
        const float xf = static_cast<float>(x), yf = static_cast<float>(y),
                    wf = static_cast<float>(w);
        const std::int64_t d[] = {
            ulps(lut::math::pow(x, y * 1.3), std::pow(x, y * 1.3)),
            ulps(lut::math::exp(w), std::exp(w)),
            ulps(lut::math::exp2(w), std::exp2(w)),
            ulps(lut::math::log(x), std::log(x)),
            ulps(lut::math::log2(x), std::log2(x)),
            ulps(lut::math::log10(x), std::log10(x)),
            ulps(lut::math::cbrt(y), std::cbrt(y)),
            ulps(lut::math::sin(w), std::sin(w)),
            ulps(lut::math::cos(w), std::cos(w)),
            ulps(lut::math::atan(w), std::atan(w)),
            ulps(lut::math::atan2(y, x - 2.0), std::atan2(y, x - 2.0)),
            ulps(lut::math::hypot(x, y), std::hypot(x, y)),
            ulps(lut::math::pow(xf, yf), std::pow(xf, yf)),
            ulps(lut::math::exp(wf), std::exp(wf)),
            ulps(lut::math::exp2(wf), std::exp2(wf)),
            ulps(lut::math::log(xf), std::log(xf)),
            ulps(lut::math::log2(xf), std::log2(xf)),
            ulps(lut::math::cbrt(yf), std::cbrt(yf)),
            ulps(lut::math::sin(wf), std::sin(wf)),
            ulps(lut::math::cos(wf), std::cos(wf)),
            ulps(lut::math::atan2(yf, xf - 2.0f), std::atan2(yf, xf - 2.0f)),
            ulps(lut::math::hypot(xf, yf), std::hypot(xf, yf)),
        };
        for (const auto v : d)
            worst = std::max(worst, v);
    }
    EXPECT_LE(worst, 4);
    // Special values as the C library gives them.
    EXPECT_TRUE(std::isnan(lut::math::log(-1.0)));
    EXPECT_EQ(lut::math::log(0.0), -HUGE_VAL);
    EXPECT_EQ(lut::math::pow(0.0, 0.0), 1.0);
    EXPECT_EQ(lut::math::pow(-8.0, 1.0 / 3.0) == lut::math::pow(-8.0, 1.0 / 3.0), false); // NaN
    EXPECT_EQ(lut::math::pow(2.0f, 10.0f), 1024.0f);
    EXPECT_EQ(lut::math::exp(1000.0), HUGE_VAL);
    EXPECT_EQ(lut::math::cbrt(-27.0), -3.0);
}

TEST(Math, OverloadsFollowCmath) {
    static_assert(std::is_same_v<decltype(lut::math::pow(1.0f, 2.0f)), float>);
    static_assert(std::is_same_v<decltype(lut::math::pow(1.0f, 2)), double>);
    static_assert(std::is_same_v<decltype(lut::math::pow(1.0, 2.0f)), double>);
    static_assert(std::is_same_v<decltype(lut::math::exp(1)), double>);
    static_assert(std::is_same_v<decltype(lut::math::cbrt(1.0f)), float>);
    EXPECT_EQ(lut::math::pow(2, 3), 8.0);
}
