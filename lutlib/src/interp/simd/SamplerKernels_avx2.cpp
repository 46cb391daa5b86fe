// SPDX-License-Identifier: Apache-2.0
// AVX2 + FMA kernels for the 3D LUT samplers, 8 pixels per iteration.
//
// Shape: load 8 RGBA pixels (4 registers of 2 pixels), transpose them in-lane to R, G, B planes,
// find lattice cells and fractions exactly as the scalar reference does (same float operations,
// same NaN/Inf clamping, same lattice snapping), then go back to pixels: tetrahedral and nearest
// work on one pixel per 128-bit half, each entry one aligned 16-byte load (RGB + padding) blended
// with weights shuffled out of a transposed register; trilinear works on one pixel per register,
// loading a whole red-axis edge (two adjacent entries) at once with weights as broadcast loads.
// Gathers are avoided on purpose: vgatherdps is slow on AMD cores, and the per-pixel loads need
// no transposition of the result. Alpha is restored from the input by a blend.
//
// The lattice mapping (interp/LatticeMapping.h) and the choice of tetrahedron and its weights
// (interp/Tetrahedral.h) are the scalar sampler's own templates, instantiated here with 8-lane
// AVX2 operations (Avx2Ops), so both paths pick the same cells, fractions and tetrahedra.
//
// Only <immintrin.h>, SimdKernels.h, Transpose.h and the two glm- and std-free templates above
// are included (see the note in SimdKernels.h about inline functions).
#include "SimdKernels.h"
#include "core/simd/Transpose.h"
#include "interp/LatticeMapping.h"
#include "interp/Tetrahedral.h"

#include <immintrin.h>

namespace lut::detail {
namespace {

// The lanes of locateAxis and tetrahedron: 8 floats, 8 ints, comparison masks as floats.
struct Avx2Ops {
    using Float = __m256;
    using Int = __m256i;
    using Mask = __m256;
    static __m256 splat(float v) { return _mm256_set1_ps(v); }
    static __m256 add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
    static __m256 sub(__m256 a, __m256 b) { return _mm256_sub_ps(a, b); }
    static __m256 mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
    static __m256 abs(__m256 a) {
        return _mm256_and_ps(a, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff)));
    }
    static __m256 min(__m256 a, __m256 b) { return _mm256_min_ps(a, b); }
    static __m256 max(__m256 a, __m256 b) { return _mm256_max_ps(a, b); }
    // maxps returns its second operand when either is NaN: NaN (and -Inf) land on 0.
    static __m256 maxWithZero(__m256 a) { return _mm256_max_ps(a, _mm256_setzero_ps()); }
    // Ties to even (the scalar form rounds half up; see locateAxis).
    static __m256 roundNearest(__m256 t) {
        return _mm256_round_ps(t, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    }
    static __m256 lessEqual(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
    static __m256 greaterEqual(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_GE_OQ); }
    static __m256 maskAnd(__m256 a, __m256 b) { return _mm256_and_ps(a, b); }
    static __m256 maskAndNot(__m256 a, __m256 b) { return _mm256_andnot_ps(a, b); }
    static __m256 select(__m256 m, __m256 a, __m256 b) { return _mm256_blendv_ps(b, a, m); }
    static __m256i truncate(__m256 t) { return _mm256_cvttps_epi32(t); }
    static __m256i minInt(__m256i a, __m256i b) { return _mm256_min_epi32(a, b); }
    static __m256 toFloat(__m256i i) { return _mm256_cvtepi32_ps(i); }
};

struct Consts {
    __m256 offset[3];
    __m256 scale[3];
    __m256 snapBias[3];
    __m256 top; // N - 1
    __m256 one;
    __m256i maxCell; // N - 2
    __m256i n;       // N
    int dr, dg, db;  // float offsets of the +1 neighbour along r, g, b
    explicit Consts(const KernelTable& t) {
        const LatticeMapping& m = t.map;
        for (int c = 0; c < 3; ++c) {
            offset[c] = _mm256_set1_ps(m.offset[c]);
            scale[c] = _mm256_set1_ps(m.scale[c]);
            snapBias[c] = _mm256_set1_ps(m.snapBias[c]);
        }
        top = _mm256_set1_ps(static_cast<float>(m.size - 1));
        one = _mm256_set1_ps(1.0f);
        maxCell = _mm256_set1_epi32(m.size - 2);
        n = _mm256_set1_epi32(m.size);
        dr = 4;
        dg = 4 * m.size;
        db = 4 * m.size * m.size;
    }
};

inline void locate(const Consts& k, int c, __m256 x, __m256i& cell, __m256& frac) {
    locateAxis<Avx2Ops>(x, k.offset[c], k.scale[c], k.snapBias[c], k.top, k.maxCell, cell, frac);
}

// Float offset of entry (r, g, b) in the padded table (4 floats per entry).
inline __m256i entryOffset(const Consts& k, __m256i r, __m256i g, __m256i b) {
    const __m256i idx = _mm256_add_epi32(
        r, _mm256_mullo_epi32(k.n, _mm256_add_epi32(g, _mm256_mullo_epi32(k.n, b))));
    return _mm256_slli_epi32(idx, 2);
}

// Two pixels' entries, one per 128-bit half (the 4th float is padding; alpha is restored later).
inline __m256 load2(const float* lo, const float* hi) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(lo)), _mm_loadu_ps(hi), 1);
}

struct Block {
    __m256 px[4]; // the input pixels, two per register
    __m256 f[3];  // fractions, lanes in transposed order
    __m256i base; // float offset of the cell's origin entry, same lanes
};

inline void loadBlock(const Consts& k, const float* p, Block& blk) {
    for (int i = 0; i < 4; ++i)
        blk.px[i] = _mm256_loadu_ps(p + 8 * i);
    __m256 r = blk.px[0], g = blk.px[1], b = blk.px[2], a = blk.px[3];
    transpose4(r, g, b, a);
    __m256i ir, ig, ib;
    locate(k, 0, r, ir, blk.f[0]);
    locate(k, 1, g, ig, blk.f[1]);
    locate(k, 2, b, ib, blk.f[2]);
    blk.base = entryOffset(k, ir, ig, ib);
}

// Runs `block` on every full group of 8 pixels and on the tail through a padded copy, so the
// tail gets the same arithmetic as the rest.
template <class BlockFn> inline void forEachBlock(float* rgba, std::size_t count, BlockFn&& block) {
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8)
        block(rgba + 4 * i);
    if (i < count) {
        alignas(32) float tmp[32] = {};
        const std::size_t rest = count - i;
        for (std::size_t j = 0; j < 4 * rest; ++j)
            tmp[j] = rgba[4 * i + j];
        block(tmp);
        for (std::size_t j = 0; j < 4 * rest; ++j)
            rgba[4 * i + j] = tmp[j];
    }
}

} // namespace

void nearestAvx2(const KernelTable& table, float* rgba, std::size_t count) {
    const Consts k(table);
    const float* t = table.rgb;
    const __m256 half = _mm256_set1_ps(0.5f);
    forEachBlock(rgba, count, [&](float* p) {
        Block blk;
        loadBlock(k, p, blk);
        // Round half up, as the scalar sampler: the next entry where frac >= 0.5.
        __m256i off = blk.base;
        off = _mm256_add_epi32(
            off, _mm256_and_si256(_mm256_castps_si256(_mm256_cmp_ps(blk.f[0], half, _CMP_GE_OQ)),
                                  _mm256_set1_epi32(k.dr)));
        off = _mm256_add_epi32(
            off, _mm256_and_si256(_mm256_castps_si256(_mm256_cmp_ps(blk.f[1], half, _CMP_GE_OQ)),
                                  _mm256_set1_epi32(k.dg)));
        off = _mm256_add_epi32(
            off, _mm256_and_si256(_mm256_castps_si256(_mm256_cmp_ps(blk.f[2], half, _CMP_GE_OQ)),
                                  _mm256_set1_epi32(k.db)));
        alignas(32) int idx[8];
        _mm256_store_si256(reinterpret_cast<__m256i*>(idx), off);
        for (int q = 0; q < 4; ++q) {
            const __m256 o = load2(t + idx[q], t + idx[q + 4]);
            _mm256_storeu_ps(p + 8 * q, _mm256_blend_ps(o, blk.px[q], 0x88));
        }
    });
}

void trilinearAvx2(const KernelTable& table, float* rgba, std::size_t count) {
    const Consts k(table);
    const float* t = table.rgb;
    const int dg = k.dg, db = k.db;
    forEachBlock(rgba, count, [&](float* p) {
        Block blk;
        loadBlock(k, p, blk);
        const __m256 fr = blk.f[0], fg = blk.f[1], fb = blk.f[2];
        const __m256 gr = _mm256_sub_ps(k.one, fr), gg = _mm256_sub_ps(k.one, fg),
                     gb = _mm256_sub_ps(k.one, fb);
        // Weights of the four red-axis edges of the cell; products of 0 and 1 are exact, so
        // lattice points still return their entries exactly.
        alignas(32) float w00[8], w10[8], w01[8], w11[8], wr0[8], wr1[8];
        alignas(32) int idx[8];
        _mm256_store_ps(w00, _mm256_mul_ps(gg, gb));
        _mm256_store_ps(w10, _mm256_mul_ps(fg, gb));
        _mm256_store_ps(w01, _mm256_mul_ps(gg, fb));
        _mm256_store_ps(w11, _mm256_mul_ps(fg, fb));
        _mm256_store_ps(wr0, gr);
        _mm256_store_ps(wr1, fr);
        _mm256_store_si256(reinterpret_cast<__m256i*>(idx), blk.base);
        // One pixel per iteration in a full register: entries (r, g, b) and (r+1, g, b) are
        // adjacent, so one 32-byte load fetches a whole red-axis edge; the weights come in as
        // broadcast loads, which cost no shuffle.
        for (int lane = 0; lane < 8; ++lane) {
            const int pix = lane < 4 ? 2 * lane : 2 * (lane - 4) + 1; // transposed lane order
            const float* e = t + idx[lane];
            __m256 acc = _mm256_mul_ps(_mm256_broadcast_ss(&w00[lane]), _mm256_loadu_ps(e));
            acc = _mm256_fmadd_ps(_mm256_broadcast_ss(&w10[lane]), _mm256_loadu_ps(e + dg), acc);
            acc = _mm256_fmadd_ps(_mm256_broadcast_ss(&w01[lane]), _mm256_loadu_ps(e + db), acc);
            acc =
                _mm256_fmadd_ps(_mm256_broadcast_ss(&w11[lane]), _mm256_loadu_ps(e + db + dg), acc);
            const __m128 lo = _mm256_castps256_ps128(acc), hi = _mm256_extractf128_ps(acc, 1);
            const __m128 o = _mm_fmadd_ps(_mm_broadcast_ss(&wr1[lane]), hi,
                                          _mm_mul_ps(_mm_broadcast_ss(&wr0[lane]), lo));
            float* q = p + 4 * pix;
            _mm_storeu_ps(q, _mm_blend_ps(o, _mm_loadu_ps(q), 0x8));
        }
    });
}

void tetrahedralAvx2(const KernelTable& table, float* rgba, std::size_t count) {
    const Consts k(table);
    const float* t = table.rgb;
    const int dAll = k.dr + k.dg + k.db;
    const __m256 offR = _mm256_castsi256_ps(_mm256_set1_epi32(k.dr));
    const __m256 offG = _mm256_castsi256_ps(_mm256_set1_epi32(k.dg));
    const __m256 offB = _mm256_castsi256_ps(_mm256_set1_epi32(k.db));
    const __m256i all = _mm256_set1_epi32(dAll);
    forEachBlock(rgba, count, [&](float* p) {
        Block blk;
        loadBlock(k, p, blk);
        const __m256 fr = blk.f[0], fg = blk.f[1], fb = blk.f[2];
        // The tetrahedron c000 -> +max axis -> c111 - min axis -> c111 and its weights.
        const Tetrahedron<Avx2Ops> tet = tetrahedron<Avx2Ops>(fr, fg, fb);
        // Its two middle vertices as table offsets from c000: + the max axis, + all - the min axis.
        const __m256i offMax = _mm256_castps_si256(
            _mm256_blendv_ps(_mm256_blendv_ps(offB, offG, tet.gIsMax), offR, tet.rIsMax));
        const __m256i offMin = _mm256_castps_si256(
            _mm256_blendv_ps(_mm256_blendv_ps(offR, offG, tet.gIsMin), offB, tet.bIsMin));
        __m256 w0 = tet.w0, w1 = tet.w1, w2 = tet.w2, w3 = tet.w3;
        transpose4(w0, w1, w2, w3); // now one register per pixel pair: [w0 w1 w2 w3 | ...]
        const __m256 wq[4] = {w0, w1, w2, w3};
        alignas(32) int i0[8], iA[8], iB[8];
        _mm256_store_si256(reinterpret_cast<__m256i*>(i0), blk.base);
        _mm256_store_si256(reinterpret_cast<__m256i*>(iA), _mm256_add_epi32(blk.base, offMax));
        _mm256_store_si256(reinterpret_cast<__m256i*>(iB),
                           _mm256_add_epi32(blk.base, _mm256_sub_epi32(all, offMin)));
        for (int q = 0; q < 4; ++q) {
            const int a = q, b = q + 4;
            const __m256 w = wq[q];
            __m256 o = _mm256_mul_ps(_mm256_permute_ps(w, 0x00), load2(t + i0[a], t + i0[b]));
            o = _mm256_fmadd_ps(_mm256_permute_ps(w, 0x55), load2(t + iA[a], t + iA[b]), o);
            o = _mm256_fmadd_ps(_mm256_permute_ps(w, 0xAA), load2(t + iB[a], t + iB[b]), o);
            o = _mm256_fmadd_ps(_mm256_permute_ps(w, 0xFF),
                                load2(t + i0[a] + dAll, t + i0[b] + dAll), o);
            _mm256_storeu_ps(p + 8 * q, _mm256_blend_ps(o, blk.px[q], 0x88));
        }
    });
}

// The shaper: 8 pixels at a time, transposed to R, G, B planes, each located on its axis as the
// scalar path does and blended from two gathered entries with the scalar path's operations
// (a multiply and an add each, no FMA), so both agree bit for bit.
void shaperAvx2(const ShaperTable& table, float* rgba, std::size_t count) {
    const LatticeMapping& m = table.map;
    const __m256 top = _mm256_set1_ps(static_cast<float>(m.size - 1));
    const __m256i maxCell = _mm256_set1_epi32(m.size - 2);
    const __m256 one = _mm256_set1_ps(1.0f);
    forEachBlock(rgba, count, [&](float* p) {
        __m256 v[4];
        for (int i = 0; i < 4; ++i)
            v[i] = _mm256_loadu_ps(p + 8 * i);
        transpose4(v[0], v[1], v[2], v[3]);
        for (int c = 0; c < 3; ++c) {
            __m256i cell;
            __m256 f;
            locateAxis<Avx2Ops>(v[c], _mm256_set1_ps(m.offset[c]), _mm256_set1_ps(m.scale[c]),
                                _mm256_set1_ps(m.snapBias[c]), top, maxCell, cell, f);
            const float* plane = table.planes + static_cast<std::ptrdiff_t>(c) * m.size;
            const __m256 a = _mm256_i32gather_ps(plane, cell, 4);
            const __m256 b = _mm256_i32gather_ps(plane + 1, cell, 4);
            v[c] = _mm256_add_ps(_mm256_mul_ps(_mm256_sub_ps(one, f), a), _mm256_mul_ps(f, b));
        }
        transpose4(v[0], v[1], v[2], v[3]); // alpha (v[3]) comes back unchanged
        for (int i = 0; i < 4; ++i)
            _mm256_storeu_ps(p + 8 * i, v[i]);
    });
}

} // namespace lut::detail
