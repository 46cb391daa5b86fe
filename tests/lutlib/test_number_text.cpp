// SPDX-License-Identifier: Apache-2.0
// lut/NumberText.h's browser-edition forms (fast_float with the out-of-range rule, Dragonbox in the
// standard's style) against GCC's std::from_chars and std::to_chars: the same values, the same
// texts, the same errors, on hostile texts and on random floats and doubles.
#include "lut/NumberText.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace {

template <class T> void sameRead(const std::string& text) {
    T a = T(-7), b = T(-7);
    const char* first = text.data();
    const char* last = text.data() + text.size();
    const auto r1 = std::from_chars(first, last, a);
    const auto r2 = lut::detail::fromCharsPortable(first, last, b);
    EXPECT_EQ(r1.ec, r2.ec) << text;
    EXPECT_EQ(r1.ptr - first, r2.ptr - first) << text;
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << text << ": " << a << " vs " << b;
}

template <class T> void sameText(T v) {
    char a[128], b[128];
    const auto r1 = std::to_chars(a, a + sizeof a, v);
    const auto r2 = lut::detail::toCharsPortable(b, b + sizeof b, v);
    ASSERT_EQ(r1.ec, std::errc());
    ASSERT_EQ(r2.ec, std::errc());
    EXPECT_EQ(std::string(a, r1.ptr), std::string(b, r2.ptr)) << v;
}

} // namespace

TEST(NumberText, PortableReadIsTheStandardRead) {
    for (const std::string t : {"0",
                                "-0",
                                "1",
                                "0.5",
                                "1e10",
                                "1E-5",
                                "3.4028235e38",
                                "3.4028236e38",
                                "1e39",
                                "-1e39",
                                "1e-45",
                                "1.4e-45",
                                "7e-46",
                                "1e-50",
                                "-1e-50",
                                "0e-999",
                                "0.000000",
                                "inf",
                                "-inf",
                                "infinity",
                                "INF",
                                "nan",
                                "-nan",
                                "nan(123)",
                                "1.7976931348623157e308",
                                "1.7976931348623159e308",
                                "2e308",
                                "4.9e-324",
                                "2e-324",
                                "1e-400",
                                "123abc",
                                ".5",
                                "5.",
                                "-.5",
                                "+1",
                                " 1",
                                "",
                                "-",
                                "e5",
                                "1e",
                                "1e+",
                                "0x1p3",
                                "00012",
                                "1_0",
                                "99999999999999999999999999",
                                "0.1234567890123456789012345678901234567890"}) {
        sameRead<float>(t);
        sameRead<double>(t);
    }
    std::mt19937_64 rng(11);
    for (int i = 0; i < 200000; ++i) {
        const double d = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng),
                                    std::uniform_int_distribution<int>(-160, 160)(rng));
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*g", 1 + i % 20, d);
        sameRead<float>(buf);
        sameRead<double>(buf);
    }
}

TEST(NumberText, PortableTextIsTheStandardText) {
    for (const float v : {0.0f,
                          -0.0f,
                          1.0f,
                          -1.0f,
                          0.1f,
                          1e6f,
                          1e7f,
                          123456789.0f,
                          16777216.0f,
                          1e-5f,
                          1e-4f,
                          1e-3f,
                          1e10f,
                          3.4028235e38f,
                          1.4e-45f,
                          1.1754944e-38f,
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          0.3f,
                          2.5f,
                          100.0f,
                          1e21f})
        sameText(v);
    for (const double v : {0.0, -0.0, 0.1, 1e22, 1e23, 5e-324, 1.7976931348623157e308, 123456.789,
                           1e-7, 1e15, 1e16, 1e17})
        sameText(v);
    std::mt19937 rng(3);
    for (int i = 0; i < 1000000; ++i) {
        std::uint32_t bits = rng();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (std::isnan(f))
            continue;
        sameText(f);
        if (i % 4 == 0)
            sameText(std::ldexp(static_cast<double>(f), static_cast<int>(rng() % 40) - 20) + 1e-9);
    }
    // The values a LUT holds, 8- and 16-bit codes, and their fixed-point texts.
    for (int i = 0; i <= 65535; ++i) {
        const float v = static_cast<float>(i) / 65535.0f;
        sameText(v);
        char a[64], b[64];
        for (const int prec : {0, 3, 6, 9}) {
            const auto r1 = std::to_chars(a, a + sizeof a, v, std::chars_format::fixed, prec);
            const auto r2 = lut::detail::toCharsFixedPortable(b, b + sizeof b, v, prec);
            EXPECT_EQ(std::string(a, r1.ptr), std::string(b, r2.ptr)) << v << " " << prec;
        }
    }
}
