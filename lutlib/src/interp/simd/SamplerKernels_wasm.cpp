// SPDX-License-Identifier: Apache-2.0
// WebAssembly SIMD forms of the portable trilinear and tetrahedral kernels (the browser
// edition): the same bits as interp/PortableKernels.cpp, hence as the AVX2 kernels, one pixel per
// iteration with R, G, B in the lanes of one register.
//
// Each table entry is one 16-byte load (RGB + the padding 0), so a pixel's three channels are
// blended at once. The kernels' fused multiply-adds (one rounding) are computed exactly as
// fmaEmulated (core/FastMath.h) does, two lanes at a time in double: the product of two floats is
// exact in double and the sum rounds once; only a sum that lands exactly halfway between two
// floats can round to another float than the fused instruction's, so such a pixel (rare) is
// computed again by the portable kernel, whose scalar emulation settles it.
//
// The lattice mapping is interp/LatticeMapping.h's locateAxis with the lanes as the channels
// (WasmOps); the tetrahedron and its weights are interp/Tetrahedral.h's, per pixel in scalar.
#include "interp/ScalarLattice.h"
#include "interp/simd/SimdKernels.h"

#include <wasm_simd128.h>

namespace lut::detail {

namespace {

// The lanes of locateAxis: the R, G, B (and an unused 4th) channel of one pixel. Each operation
// gives the scalar ScalarOps' result per lane (pmin/pmax are the scalar comparisons; nearest
// breaks ties to even where ScalarOps rounds half up: locateAxis allows either).
struct WasmOps {
    using Float = v128_t;
    using Int = v128_t;
    using Mask = v128_t;
    static v128_t splat(float v) { return wasm_f32x4_splat(v); }
    static v128_t add(v128_t a, v128_t b) { return wasm_f32x4_add(a, b); }
    static v128_t sub(v128_t a, v128_t b) { return wasm_f32x4_sub(a, b); }
    static v128_t mul(v128_t a, v128_t b) { return wasm_f32x4_mul(a, b); }
    static v128_t abs(v128_t a) { return wasm_f32x4_abs(a); }
    static v128_t min(v128_t a, v128_t b) { return wasm_f32x4_pmin(a, b); } // b < a ? b : a
    static v128_t max(v128_t a, v128_t b) { return wasm_f32x4_pmax(b, a); } // b < a ? a : b
    // 0 < a ? a : 0: NaN and -Inf land on 0.
    static v128_t maxWithZero(v128_t a) { return wasm_f32x4_pmax(wasm_f32x4_splat(0.0f), a); }
    static v128_t roundNearest(v128_t t) { return wasm_f32x4_nearest(t); }
    static v128_t lessEqual(v128_t a, v128_t b) { return wasm_f32x4_le(a, b); }
    static v128_t greaterEqual(v128_t a, v128_t b) { return wasm_f32x4_ge(a, b); }
    static v128_t maskAnd(v128_t a, v128_t b) { return wasm_v128_and(a, b); }
    static v128_t maskAndNot(v128_t a, v128_t b) { return wasm_v128_andnot(b, a); }
    static v128_t select(v128_t m, v128_t a, v128_t b) { return wasm_v128_bitselect(a, b, m); }
    static v128_t truncate(v128_t t) { return wasm_i32x4_trunc_sat_f32x4(t); }
    static v128_t minInt(v128_t a, v128_t b) { return wasm_i32x4_min(a, b); }
    static v128_t toFloat(v128_t i) { return wasm_f32x4_convert_i32x4(i); }
};

struct Consts {
    v128_t offset, scale, snapBias, top, maxCell; // per channel; the 4th lane maps to cell 0
    std::size_t n;
    explicit Consts(const KernelTable& t) {
        const LatticeMapping& m = t.map;
        offset = wasm_f32x4_make(m.offset[0], m.offset[1], m.offset[2], 0.0f);
        scale = wasm_f32x4_make(m.scale[0], m.scale[1], m.scale[2], 0.0f);
        snapBias = wasm_f32x4_make(m.snapBias[0], m.snapBias[1], m.snapBias[2], 0.0f);
        top = wasm_f32x4_splat(static_cast<float>(m.size - 1));
        maxCell = wasm_i32x4_splat(m.size - 2);
        n = static_cast<std::size_t>(m.size);
    }
};

struct Located {
    std::size_t base; // float offset of the cell's origin entry
    float fr, fg, fb; // fractions
};

inline Located locate(const Consts& k, v128_t px) {
    v128_t cell, frac;
    locateAxis<WasmOps>(px, k.offset, k.scale, k.snapBias, k.top, k.maxCell, cell, frac);
    const std::size_t r = static_cast<std::size_t>(wasm_i32x4_extract_lane(cell, 0));
    const std::size_t g = static_cast<std::size_t>(wasm_i32x4_extract_lane(cell, 1));
    const std::size_t b = static_cast<std::size_t>(wasm_i32x4_extract_lane(cell, 2));
    Located l;
    l.base = 4 * (r + k.n * (g + k.n * b));
    l.fr = wasm_f32x4_extract_lane(frac, 0);
    l.fg = wasm_f32x4_extract_lane(frac, 1);
    l.fb = wasm_f32x4_extract_lane(frac, 2);
    return l;
}

// fma(a, b, c) in every lane, each rounded once when its double sum is not halfway between two
// floats; `halfway` collects the lanes where it is (their result must come from fmaEmulated).
inline v128_t fmaLanes(float a, v128_t b, v128_t c, v128_t& halfway) {
    const v128_t ad = wasm_f64x2_splat(static_cast<double>(a));
    const v128_t bHi = wasm_i32x4_shuffle(b, b, 2, 3, 2, 3);
    const v128_t cHi = wasm_i32x4_shuffle(c, c, 2, 3, 2, 3);
    const v128_t lo = wasm_f64x2_add(wasm_f64x2_mul(ad, wasm_f64x2_promote_low_f32x4(b)),
                                     wasm_f64x2_promote_low_f32x4(c));
    const v128_t hi = wasm_f64x2_add(wasm_f64x2_mul(ad, wasm_f64x2_promote_low_f32x4(bHi)),
                                     wasm_f64x2_promote_low_f32x4(cHi));
    const v128_t below = wasm_i64x2_splat(0x1FFFFFFF), half = wasm_i64x2_splat(0x10000000);
    halfway = wasm_v128_or(halfway, wasm_i64x2_eq(wasm_v128_and(lo, below), half));
    halfway = wasm_v128_or(halfway, wasm_i64x2_eq(wasm_v128_and(hi, below), half));
    return wasm_i32x4_shuffle(wasm_f32x4_demote_f64x2_zero(lo), wasm_f32x4_demote_f64x2_zero(hi), 0,
                              1, 4, 5);
}

// The blended R, G, B with the input's alpha.
inline void store(float* p, v128_t rgb, v128_t px) {
    wasm_v128_store(p, wasm_i32x4_shuffle(rgb, px, 0, 1, 2, 7));
}

} // namespace

void trilinearWasm(const KernelTable& table, float* rgba, std::size_t count) {
    const Consts k(table);
    const std::size_t dr = 4, dg = 4 * k.n, db = 4 * k.n * k.n;
    for (std::size_t i = 0; i < count; ++i) {
        float* p = rgba + 4 * i;
        const v128_t px = wasm_v128_load(p);
        const Located c = locate(k, px);
        const float gr = 1.0f - c.fr, gg = 1.0f - c.fg, gb = 1.0f - c.fb;
        const float w00 = gg * gb, w10 = c.fg * gb, w01 = gg * c.fb, w11 = c.fg * c.fb;
        const float* e = table.rgb + c.base;
        v128_t halfway = wasm_i64x2_splat(0);
        v128_t edge[2];
        for (int h = 0; h < 2; ++h) {
            const float* q = e + h * dr;
            v128_t acc = wasm_f32x4_mul(wasm_f32x4_splat(w00), wasm_v128_load(q));
            acc = fmaLanes(w10, wasm_v128_load(q + dg), acc, halfway);
            acc = fmaLanes(w01, wasm_v128_load(q + db), acc, halfway);
            acc = fmaLanes(w11, wasm_v128_load(q + db + dg), acc, halfway);
            edge[h] = acc;
        }
        const v128_t out =
            fmaLanes(c.fr, edge[1], wasm_f32x4_mul(wasm_f32x4_splat(gr), edge[0]), halfway);
        if (wasm_v128_any_true(halfway))
            trilinearPortable(table, p, 1);
        else
            store(p, out, px);
    }
}

void tetrahedralWasm(const KernelTable& table, float* rgba, std::size_t count) {
    const Consts k(table);
    const std::size_t dr = 4, dg = 4 * k.n, db = 4 * k.n * k.n, dAll = dr + dg + db;
    for (std::size_t i = 0; i < count; ++i) {
        float* p = rgba + 4 * i;
        const v128_t px = wasm_v128_load(p);
        const Located c = locate(k, px);
        const Tetrahedron<ScalarOps> t = tetrahedron<ScalarOps>(c.fr, c.fg, c.fb);
        const std::size_t offMax = t.rIsMax ? dr : t.gIsMax ? dg : db;
        const std::size_t offMin = t.bIsMin ? db : t.gIsMin ? dg : dr;
        const float* c000 = table.rgb + c.base;
        v128_t halfway = wasm_i64x2_splat(0);
        v128_t o = wasm_f32x4_mul(wasm_f32x4_splat(t.w0), wasm_v128_load(c000));
        o = fmaLanes(t.w1, wasm_v128_load(c000 + offMax), o, halfway);
        o = fmaLanes(t.w2, wasm_v128_load(c000 + dAll - offMin), o, halfway);
        o = fmaLanes(t.w3, wasm_v128_load(c000 + dAll), o, halfway);
        if (wasm_v128_any_true(halfway))
            tetrahedralPortable(table, p, 1);
        else
            store(p, o, px);
    }
}

} // namespace lut::detail
