#pragma once
// Table-driven pow() for the pipeline's hot loops. pow() is most of the cost of the grading pass
// (nine per pixel in the naive form); these tables bring it to a few integer operations and one
// lerp with a relative error below 3e-7 (tested against std::pow in tests/pipeline).
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lut::detail {

// pow(x, p) for a fixed p: x = 2^e * m, m in [1,2): pow = 2^(e p) * m^p, with m^p from a table of
// 2^kBits + 1 entries, linearly interpolated. x <= 0, NaN and denormals give 0; +Inf gives the
// largest table value (finite). Callers clamp huge values beforehand where it matters.
class PowTable {
public:
    static constexpr int kBits = 12;
    explicit PowTable(double p) : m_p(p), m_mant((1u << kBits) + 1) {
        for (std::uint32_t i = 0; i <= (1u << kBits); ++i)
            m_mant[i] =
                static_cast<float>(std::pow(1.0 + static_cast<double>(i) / (1u << kBits), p));
        for (int e = 0; e < 256; ++e) {
            double v = e == 0 ? 0.0 : std::pow(2.0, (e - 127) * p);
            if (!(v < 3.0e38))
                v = 3.0e38;
            m_exp[e] = static_cast<float>(v);
        }
        const double top = static_cast<double>(m_exp[254]) * m_mant[1u << kBits];
        m_top = static_cast<float>(top < 3.0e38 ? top : 3.0e38);
    }
    double exponent() const { return m_p; }
    const float* mantissaTable() const { return m_mant.data(); }
    const float* exponentTable() const { return m_exp; }
    float top() const { return m_top; }
    float operator()(float x) const {
        if (!(x > 0.0f))
            return 0.0f;
        const std::uint32_t b = std::bit_cast<std::uint32_t>(x);
        const std::uint32_t e = b >> 23;
        if (e == 255)
            return m_top;
        const std::uint32_t m = b & 0x7FFFFFu;
        const std::uint32_t idx = m >> (23 - kBits);
        const float frac =
            static_cast<float>(m & ((1u << (23 - kBits)) - 1u)) * (1.0f / (1u << (23 - kBits)));
        const float a = m_mant[idx], c = m_mant[idx + 1];
        return m_exp[e] * (a + (c - a) * frac);
    }

private:
    double m_p;
    std::vector<float> m_mant;
    float m_exp[256];
    float m_top = 0.0f;
};

// f(r) on [0, hi] from a uniform table with linear interpolation; outside, the exact fallback.
class UniformTable {
public:
    template <class F> UniformTable(float hi, int intervals, F&& f) : m_hi(hi), m_n(intervals) {
        m_scale = static_cast<float>(intervals) / hi;
        m_v.resize(static_cast<std::size_t>(intervals) + 2);
        for (int i = 0; i <= intervals + 1; ++i)
            m_v[i] = static_cast<float>(f(static_cast<double>(i) * hi / intervals));
    }
    bool covers(float x) const { return x >= 0.0f && x < m_hi; }
    const float* values() const { return m_v.data(); }
    float scale() const { return m_scale; }
    int intervals() const { return m_n; }
    // x in [0, hi)
    float operator()(float x) const {
        const float t = x * m_scale;
        int i = static_cast<int>(t);
        if (i >= m_n)
            i = m_n - 1;
        const float f = t - static_cast<float>(i);
        return m_v[i] + (m_v[i + 1] - m_v[i]) * f;
    }

private:
    float m_hi;
    int m_n;
    float m_scale;
    std::vector<float> m_v;
};

// NaN -> 0; clamps to [-lim, lim].
inline float sanitizeValue(float v, float lim) {
    if (!(v == v))
        return 0.0f;
    return v > lim ? lim : (v < -lim ? -lim : v);
}

inline float clamp01(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
} // NaN -> 0

} // namespace lut::detail
