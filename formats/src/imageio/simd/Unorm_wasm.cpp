// SPDX-License-Identifier: Apache-2.0
// Float RGBA -> 8-bit RGB(A) in WebAssembly SIMD (the browser edition): the value
// lut::toUnorm8 gives (lut/Quantize.h), four pixels at a time, as Unorm_avx.cpp does natively.
// The scalar form is `v > 0 ? (v >= 1 ? 255 : int(double(v) * 255 + 0.5)) : 0`; here v is first
// clamped to [0, 1] in float (pmax(0, v) is 0 for NaN), which gives the same integer for every
// float: 0 * 255 + 0.5 and 1 * 255 + 0.5 truncate to 0 and 255, and in between the double
// arithmetic is the scalar's own (exact products: a float times 255 fits a double).
#include <wasm_simd128.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace lut::formats::detail {

namespace {

inline v128_t unorm4(const float* p) {
    const v128_t c = wasm_f32x4_pmin(wasm_f32x4_pmax(wasm_f32x4_splat(0.0f), wasm_v128_load(p)),
                                     wasm_f32x4_splat(1.0f));
    const v128_t scale = wasm_f64x2_splat(255.0), half = wasm_f64x2_splat(0.5);
    const v128_t lo = wasm_f64x2_add(wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(c), scale), half);
    const v128_t hi = wasm_f64x2_add(
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(wasm_i32x4_shuffle(c, c, 2, 3, 2, 3)), scale),
        half);
    return wasm_i32x4_shuffle(wasm_i32x4_trunc_sat_f64x2_zero(lo),
                              wasm_i32x4_trunc_sat_f64x2_zero(hi), 0, 1, 4, 5);
}

} // namespace

// n pixels of float RGBA to 8-bit RGB (nch 3) or RGBA (nch 4); returns how many were done (a
// multiple of 4; the caller converts the rest).
std::size_t rgbaToUnorm8Wasm(const float* rgba, std::size_t n, std::uint8_t* dst, int nch) {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const float* p = rgba + 4 * i;
        const v128_t w01 = wasm_u16x8_narrow_i32x4(unorm4(p), unorm4(p + 4));
        const v128_t w23 = wasm_u16x8_narrow_i32x4(unorm4(p + 8), unorm4(p + 12));
        const v128_t b = wasm_u8x16_narrow_i16x8(w01, w23); // 4 pixels, RGBA bytes
        if (nch == 4) {
            wasm_v128_store(dst + 4 * i, b);
        } else {
            alignas(16) std::uint8_t rgb[16];
            wasm_v128_store(
                rgb, wasm_i8x16_shuffle(b, b, 0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 0, 0, 0, 0));
            std::memcpy(dst + 3 * i, rgb, 12);
        }
    }
    return i;
}

} // namespace lut::formats::detail
