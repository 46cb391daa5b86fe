// SPDX-License-Identifier: Apache-2.0
#include "imageio/PixelConvert.h"

#include "lut/Quantize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace lut::formats {

namespace detail {
void halfToFloatF16c(const std::uint16_t* src, float* dst, std::size_t n);
void floatToHalfF16c(const float* src, std::uint16_t* dst, std::size_t n);
std::size_t halfRgbToRgbaF16c(const std::uint16_t* src, std::size_t n, float* rgba);
std::size_t rgbaToHalfRgbF16c(const float* rgba, std::size_t n, std::uint16_t* dst);
std::size_t rgbaToUnorm8Avx(const float* rgba, std::size_t n, std::uint8_t* dst, int nch);
std::size_t unorm8ToRgbaAvx(const std::uint8_t* src, std::size_t n, float* rgba, int nch);
std::size_t rgbaToUnorm16Avx(const float* rgba, std::size_t n, std::uint16_t* dst, int nch);
std::size_t rgbaToUnorm8Wasm(const float* rgba, std::size_t n, std::uint8_t* dst, int nch);
} // namespace detail

namespace {

bool hasF16c() {
#if defined(__x86_64__) || defined(__i386__)
    static const bool yes = [] {
        __builtin_cpu_init();
        // F16C from CPUID itself: clang 14's __builtin_cpu_supports does not know "f16c".
        unsigned a = 0, b = 0, c = 0, d = 0;
        return __builtin_cpu_supports("avx") && __get_cpuid(1, &a, &b, &c, &d) &&
               (c & bit_F16C) != 0;
    }();
    return yes;
#else
    return false;
#endif
}

bool hasAvx() {
#if defined(__x86_64__) || defined(__i386__)
    static const bool yes = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx") != 0;
    }();
    return yes;
#else
    return false;
#endif
}

std::uint32_t bitsOf(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}
float floatOf(std::uint32_t u) {
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

// Scratch floats for half runs, per thread.
float* scratch(std::size_t n) {
    thread_local std::vector<float> buf;
    if (buf.size() < n)
        buf.resize(n);
    return buf.data();
}

template <class T> float load(T v);
// 8-bit samples by table: the same division, done once per value.
const float* unorm8Table() {
    static const auto table = [] {
        std::array<float, 256> t{};
        for (int v = 0; v < 256; ++v)
            t[static_cast<std::size_t>(v)] = static_cast<float>(v) / 255.0f;
        return t;
    }();
    return table.data();
}
template <> float load(std::uint8_t v) {
    return static_cast<float>(v) / 255.0f;
}
template <> float load(std::uint16_t v) {
    return static_cast<float>(v) / 65535.0f;
}
template <> float load(float v) {
    return v;
}

template <class T> T store(float v);
template <> std::uint8_t store(float v) {
    return toUnorm8(v);
}
template <> std::uint16_t store(float v) {
    return toUnorm16(v);
}
template <> float store(float v) {
    return v;
}

template <class T>
void gather(const T* s, int nch, const RgbaMap& m, std::size_t n, float* __restrict o) {
    if constexpr (std::is_same_v<T, std::uint8_t>) {
        const float* t = unorm8Table();
        if (nch == 3 && m.r == 0 && m.g == 1 && m.b == 2 && m.a < 0) {
            const std::size_t done = hasAvx() ? detail::unorm8ToRgbaAvx(s, n, o, 3) : 0;
            for (std::size_t i = done; i < n; ++i) {
                o[4 * i + 0] = t[s[3 * i + 0]];
                o[4 * i + 1] = t[s[3 * i + 1]];
                o[4 * i + 2] = t[s[3 * i + 2]];
                o[4 * i + 3] = 1.0f;
            }
            return;
        }
        if (nch == 4 && m.r == 0 && m.g == 1 && m.b == 2 && m.a == 3) {
            const std::size_t done = hasAvx() ? detail::unorm8ToRgbaAvx(s, n, o, 4) : 0;
            for (std::size_t i = 4 * done; i < 4 * n; ++i)
                o[i] = t[s[i]];
            return;
        }
    }
    if (nch == 3 && m.r == 0 && m.g == 1 && m.b == 2 && m.a < 0) {
        for (std::size_t i = 0; i < n; ++i) {
            o[4 * i + 0] = load(s[3 * i + 0]);
            o[4 * i + 1] = load(s[3 * i + 1]);
            o[4 * i + 2] = load(s[3 * i + 2]);
            o[4 * i + 3] = 1.0f;
        }
        return;
    }
    if (nch == 4 && m.r == 0 && m.g == 1 && m.b == 2 && m.a == 3) {
        for (std::size_t i = 0; i < 4 * n; ++i)
            o[i] = load(s[i]);
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const T* p = s + static_cast<std::size_t>(nch) * i;
        o[4 * i + 0] = load(p[m.r]);
        o[4 * i + 1] = load(p[m.g]);
        o[4 * i + 2] = load(p[m.b]);
        o[4 * i + 3] = m.a >= 0 ? load(p[m.a]) : 1.0f;
    }
}

// 4x4 Bayer matrix, thresholds in (-0.5, 0.5) of one quantisation step.
float bayer(int x, int y) {
    static const int mtx[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    return (static_cast<float>(mtx[y & 3][x & 3]) + 0.5f) / 16.0f - 0.5f;
}

template <class T>
void scatter(const float* __restrict v, std::size_t n, T* d, int nch, const RgbaMap& m,
             const DitherPos& dp, float step) {
    const bool grey = m.r == m.g && m.g == m.b;
    const bool plainRgb =
        !dp.on && !grey && nch == 3 && m.r == 0 && m.g == 1 && m.b == 2 && m.a < 0;
    const bool plainRgba = !dp.on && nch == 4 && m.r == 0 && m.g == 1 && m.b == 2 && m.a == 3;
    if constexpr (!std::is_same_v<T, float>) {
#if defined(__wasm_simd128__)
        constexpr bool wasm = std::is_same_v<T, std::uint8_t>; // the browser edition's 8 bits
#else
        constexpr bool wasm = false;
#endif
        if ((plainRgb || plainRgba) && (wasm || hasAvx())) {
            std::size_t done = 0;
#if defined(__wasm_simd128__)
            if constexpr (wasm)
                done = detail::rgbaToUnorm8Wasm(v, n, d, nch);
#else
            if constexpr (std::is_same_v<T, std::uint8_t>)
                done = detail::rgbaToUnorm8Avx(v, n, d, nch);
            else
                done = detail::rgbaToUnorm16Avx(v, n, d, nch);
#endif
            for (std::size_t i = done; i < n; ++i)
                for (int c = 0; c < nch; ++c)
                    d[static_cast<std::size_t>(nch) * i + static_cast<std::size_t>(c)] =
                        store<T>(v[4 * i + static_cast<std::size_t>(c)]);
            return;
        }
    }
    if (plainRgb) {
        for (std::size_t i = 0; i < n; ++i) {
            d[3 * i + 0] = store<T>(v[4 * i + 0]);
            d[3 * i + 1] = store<T>(v[4 * i + 1]);
            d[3 * i + 2] = store<T>(v[4 * i + 2]);
        }
        return;
    }
    if (plainRgba) {
        for (std::size_t i = 0; i < 4 * n; ++i)
            d[i] = store<T>(v[i]);
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        T* p = d + static_cast<std::size_t>(nch) * i;
        float off = 0.0f;
        if (dp.on) {
            const std::size_t k = dp.start + i;
            off = bayer(static_cast<int>(k % static_cast<std::size_t>(dp.width)),
                        static_cast<int>(k / static_cast<std::size_t>(dp.width))) *
                  step;
        }
        p[m.r] = store<T>(v[4 * i + 0] + off);
        if (!grey) {
            p[m.g] = store<T>(v[4 * i + 1] + off);
            p[m.b] = store<T>(v[4 * i + 2] + off);
        }
        if (m.a >= 0)
            p[m.a] = store<T>(v[4 * i + 3]);
    }
}

} // namespace

const char* toString(PixelType t) {
    switch (t) {
    case PixelType::UInt8:
        return "uint8";
    case PixelType::UInt16:
        return "uint16";
    case PixelType::Half:
        return "half";
    case PixelType::Float:
        return "float";
    }
    return "float";
}

RgbaMap rgbaMapOf(const ImageInfo& info) {
    RgbaMap m;
    const auto& names = info.channelNames;
    // Only channels the pixels have: a reader may name more channels than it stores, or an
    // alpha index past the last channel (OpenImageIO's GIF reader said alpha = 4 of 4 channels
    // for a fuzzed file; the conversion read past every row). Alpha then goes by its name.
    const std::size_t stored = static_cast<std::size_t>(std::max(0, info.channels));
    auto find = [&](const char* n) {
        for (std::size_t i = 0; i < std::min(names.size(), stored); ++i)
            if (names[i] == n)
                return static_cast<int>(i);
        return -1;
    };
    m.a = info.alphaChannel >= 0 && info.alphaChannel < info.channels ? info.alphaChannel
          : info.alphaChannel >= 0                                    ? find("A")
                                                                      : -1;
    const int r = find("R"), g = find("G"), b = find("B"), y = find("Y");
    if (r >= 0 && g >= 0 && b >= 0) {
        m.r = r;
        m.g = g;
        m.b = b;
    } else if ((y >= 0 && info.channels - (m.a >= 0 ? 1 : 0) <= 1) || info.channels <= 2) {
        // Grey: one channel besides alpha (a "Y" among three or more is a name, not grey:
        // OpenImageIO calls a FITS file's RGB channels "Y", "unknown", "unknown").
        const int grey = y >= 0 ? y : 0;
        m.r = m.g = m.b = grey;
        if (m.a < 0 && info.channels == 2)
            m.a = grey == 0 ? 1 : 0;
    } else {
        // Unnamed channels: the first three, alpha as the file says (or the 4th of 4).
        m.r = 0;
        m.g = 1;
        m.b = 2;
        if (m.a < 0 && info.channels == 4 && names.empty())
            m.a = 3;
    }
    return m;
}

float halfToFloat(std::uint16_t h) {
    const std::uint32_t s = static_cast<std::uint32_t>(h & 0x8000u) << 16;
    const std::uint32_t e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
    if (e == 0) {
        const float v = static_cast<float>(m) * (1.0f / 16777216.0f); // m * 2^-24, exact
        return s ? -v : v;
    }
    if (e == 31)
        return floatOf(s | 0x7f800000u | (m << 13));
    return floatOf(s | ((e + 112u) << 23) | (m << 13));
}

std::uint16_t floatToHalf(float f) {
    std::uint32_t x = bitsOf(f);
    const std::uint16_t sign = static_cast<std::uint16_t>((x >> 16) & 0x8000u);
    x &= 0x7fffffffu;
    if (x > 0x7f800000u) // NaN: quiet, the payload's top bits kept (as F16C does)
        return static_cast<std::uint16_t>(sign | 0x7e00u | ((x >> 13) & 0x3ffu));
    if (x >= 0x477ff000u) // rounds to infinity (65520 and up), Inf
        return static_cast<std::uint16_t>(sign | 0x7c00u);
    if (x < 0x38800000u) { // below 2^-14: a half denormal (or zero), round to nearest even
        const float scaled = floatOf(x) * 16777216.0f; // exact: a power of two
        return static_cast<std::uint16_t>(sign |
                                          static_cast<std::uint16_t>(std::nearbyint(scaled)));
    }
    x += 0xc8000fffu + ((x >> 13) & 1u); // rebias the exponent, round to nearest even
    return static_cast<std::uint16_t>(sign | (x >> 13));
}

void halfToFloatN(const std::uint16_t* src, float* dst, std::size_t n) {
    if (hasF16c()) {
        detail::halfToFloatF16c(src, dst, n);
        return;
    }
    for (std::size_t i = 0; i < n; ++i)
        dst[i] = halfToFloat(src[i]);
}

void floatToHalfN(const float* src, std::uint16_t* dst, std::size_t n) {
    if (hasF16c()) {
        detail::floatToHalfF16c(src, dst, n);
        return;
    }
    for (std::size_t i = 0; i < n; ++i)
        dst[i] = floatToHalf(src[i]);
}

void toRgba(const void* src, PixelType type, int nch, const RgbaMap& map, std::size_t n,
            float* rgba) {
    switch (type) {
    case PixelType::UInt8:
        gather(static_cast<const std::uint8_t*>(src), nch, map, n, rgba);
        return;
    case PixelType::UInt16:
        gather(static_cast<const std::uint16_t*>(src), nch, map, n, rgba);
        return;
    case PixelType::Float:
        gather(static_cast<const float*>(src), nch, map, n, rgba);
        return;
    case PixelType::Half: {
        if (nch == 4 && map.r == 0 && map.g == 1 && map.b == 2 && map.a == 3) {
            halfToFloatN(static_cast<const std::uint16_t*>(src), rgba, 4 * n); // already RGBA
            return;
        }
        const auto* h = static_cast<const std::uint16_t*>(src);
        std::size_t done = 0;
        if (nch == 3 && map.r == 0 && map.g == 1 && map.b == 2 && map.a < 0 && hasF16c()) {
            done = detail::halfRgbToRgbaF16c(h, n, rgba); // one pass; the rest below
            if (done == n)
                return;
        }
        const std::size_t count = (n - done) * static_cast<std::size_t>(nch);
        float* f = scratch(count);
        halfToFloatN(h + done * static_cast<std::size_t>(nch), f, count);
        gather(static_cast<const float*>(f), nch, map, n - done, rgba + 4 * done);
        return;
    }
    }
}

void fromRgba(const float* rgba, std::size_t n, void* dst, PixelType type, int nch,
              const RgbaMap& map, const DitherPos& dither) {
    switch (type) {
    case PixelType::UInt8:
        scatter(rgba, n, static_cast<std::uint8_t*>(dst), nch, map, dither, 1.0f / 255.0f);
        return;
    case PixelType::UInt16:
        scatter(rgba, n, static_cast<std::uint16_t*>(dst), nch, map, dither, 1.0f / 65535.0f);
        return;
    case PixelType::Float:
        scatter(rgba, n, static_cast<float*>(dst), nch, map, DitherPos{}, 0.0f);
        return;
    case PixelType::Half: {
        const bool rgb = map.r == 0 && map.g == 1 && map.b == 2;
        if (nch == 4 && rgb && map.a == 3) { // every channel written: straight from RGBA
            floatToHalfN(rgba, static_cast<std::uint16_t*>(dst), 4 * n);
            return;
        }
        std::size_t done = 0;
        if (nch == 3 && rgb && map.a < 0 && hasF16c()) {
            done = detail::rgbaToHalfRgbF16c(rgba, n, static_cast<std::uint16_t*>(dst));
            if (done == n)
                return;
            rgba += 4 * done;
            dst = static_cast<std::uint16_t*>(dst) + 3 * done;
            n -= done;
        }
        // Through floats: the other channels are read, kept and written back unchanged (when
        // R, G, B are all there is, nothing needs reading).
        const std::size_t count = n * static_cast<std::size_t>(nch);
        float* f = scratch(count);
        if (!(nch == 3 && rgb && map.a < 0))
            halfToFloatN(static_cast<const std::uint16_t*>(dst), f, count);
        scatter(rgba, n, f, nch, map, DitherPos{}, 0.0f);
        floatToHalfN(f, static_cast<std::uint16_t*>(dst), count);
        return;
    }
    }
}

void copyChannel(const void* src, PixelType st, int sch, int sc, void* dst, PixelType dt, int dch,
                 int dc, std::size_t n) {
    const int sb = bytesPerSample(st), db = bytesPerSample(dt);
    const auto* s = static_cast<const unsigned char*>(src) + static_cast<std::size_t>(sc * sb);
    auto* d = static_cast<unsigned char*>(dst) + static_cast<std::size_t>(dc * db);
    const std::size_t ss = static_cast<std::size_t>(sch * sb),
                      ds = static_cast<std::size_t>(dch * db);
    for (std::size_t i = 0; i < n; ++i, s += ss, d += ds) {
        if (st == dt) {
            std::memcpy(d, s, static_cast<std::size_t>(sb));
            continue;
        }
        float v = 0.0f;
        switch (st) {
        case PixelType::UInt8:
            v = load(*s);
            break;
        case PixelType::UInt16: {
            std::uint16_t u;
            std::memcpy(&u, s, 2);
            v = load(u);
            break;
        }
        case PixelType::Half: {
            std::uint16_t u;
            std::memcpy(&u, s, 2);
            v = halfToFloat(u);
            break;
        }
        case PixelType::Float:
            std::memcpy(&v, s, 4);
            break;
        }
        switch (dt) {
        case PixelType::UInt8:
            *d = toUnorm8(v);
            break;
        case PixelType::UInt16: {
            const std::uint16_t u = toUnorm16(v);
            std::memcpy(d, &u, 2);
            break;
        }
        case PixelType::Half: {
            const std::uint16_t u = floatToHalf(v);
            std::memcpy(d, &u, 2);
            break;
        }
        case PixelType::Float:
            std::memcpy(d, &v, 4);
            break;
        }
    }
}

} // namespace lut::formats
