// SPDX-License-Identifier: Apache-2.0
// AVX-512 (F + DQ) tetrahedral kernel, 16 pixels per iteration: the AVX2 kernel's shape
// (SamplerKernels_avx2.cpp) at twice the width, and bit-identical to it.
//
// Shape: load 16 RGBA pixels (4 registers of 4 pixels, one per 128-bit lane), transpose each
// lane's 4x4 block to R, G, B planes, find cells, fractions and the tetrahedron with the scalar
// sampler's own templates (interp/LatticeMapping.h, interp/Tetrahedral.h) on 16 lanes, then go
// back to one pixel per 128-bit lane: each entry one 16-byte load from the padded RGBA table,
// four pixels' entries put side by side in one register and blended with weights broadcast
// within each lane. Every float operation of a pixel is the one the AVX2 kernel does, in the
// same order (multiply, then three fused multiply-adds), so the two give the same bits; only the
// number of pixels per instruction differs. The work before the table loads (half the
// instructions at 8 lanes) costs half as many instructions here. No gathers (slow on AMD cores,
// and microcoded against Downfall on recent Intel ones).
//
// Only <immintrin.h>, SimdKernels.h and the two glm- and std-free templates are included (see
// the note in SimdKernels.h about inline functions).
#include "SimdKernels.h"
#include "interp/LatticeMapping.h"
#include "interp/Tetrahedral.h"

// GCC 12's AVX-512 intrinsics start from _mm512_undefined_ps(), which its -Wuninitialized takes
// for a read of an uninitialised variable (GCC bug 105593); no variable of ours is.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

namespace lut::detail {
namespace {

// The lanes of locateAxis and tetrahedron: 16 floats, 16 ints, comparison masks as bit masks.
struct Avx512Ops {
    using Float = __m512;
    using Int = __m512i;
    using Mask = __mmask16;
    static __m512 splat(float v) { return _mm512_set1_ps(v); }
    static __m512 add(__m512 a, __m512 b) { return _mm512_add_ps(a, b); }
    static __m512 sub(__m512 a, __m512 b) { return _mm512_sub_ps(a, b); }
    static __m512 mul(__m512 a, __m512 b) { return _mm512_mul_ps(a, b); }
    static __m512 abs(__m512 a) {
        return _mm512_castsi512_ps(
            _mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32(0x7fffffff)));
    }
    static __m512 min(__m512 a, __m512 b) { return _mm512_min_ps(a, b); }
    static __m512 max(__m512 a, __m512 b) { return _mm512_max_ps(a, b); }
    // vmaxps returns its second operand when either is NaN: NaN (and -Inf) land on 0.
    static __m512 maxWithZero(__m512 a) { return _mm512_max_ps(a, _mm512_setzero_ps()); }
    // Ties to even, as the AVX2 kernel's roundps (a tie never changes t: see locateAxis).
    static __m512 roundNearest(__m512 t) {
        return _mm512_roundscale_ps(t, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    }
    static __mmask16 lessEqual(__m512 a, __m512 b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
    static __mmask16 greaterEqual(__m512 a, __m512 b) {
        return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ);
    }
    static __mmask16 maskAnd(__mmask16 a, __mmask16 b) { return _kand_mask16(a, b); }
    static __mmask16 maskAndNot(__mmask16 a, __mmask16 b) { return _kandn_mask16(a, b); }
    static __m512 select(__mmask16 m, __m512 a, __m512 b) { return _mm512_mask_blend_ps(m, b, a); }
    static __m512i truncate(__m512 t) { return _mm512_cvttps_epi32(t); }
    static __m512i minInt(__m512i a, __m512i b) { return _mm512_min_epi32(a, b); }
    static __m512 toFloat(__m512i i) { return _mm512_cvtepi32_ps(i); }
};

// Four registers of four RGBA pixels each (one per 128-bit lane), lane l of a, b, c, d holding
// pixels l, 4+l, 8+l, 12+l: -> a = R, b = G, c = B, d = A, element 4l+j of a plane being pixel
// 4j+l. Its own inverse, as the AVX2 transpose4.
inline void transpose4x4(__m512& a, __m512& b, __m512& c, __m512& d) {
    const __m512 t0 = _mm512_unpacklo_ps(a, b);
    const __m512 t1 = _mm512_unpackhi_ps(a, b);
    const __m512 t2 = _mm512_unpacklo_ps(c, d);
    const __m512 t3 = _mm512_unpackhi_ps(c, d);
    a = _mm512_shuffle_ps(t0, t2, 0x44);
    b = _mm512_shuffle_ps(t0, t2, 0xEE);
    c = _mm512_shuffle_ps(t1, t3, 0x44);
    d = _mm512_shuffle_ps(t1, t3, 0xEE);
}

// Four pixels' entries, one per 128-bit lane (the 4th float is padding; alpha is restored later).
inline __m512 load4(const float* p0, const float* p1, const float* p2, const float* p3) {
    __m512 v = _mm512_castps128_ps512(_mm_loadu_ps(p0));
    v = _mm512_insertf32x4(v, _mm_loadu_ps(p1), 1);
    v = _mm512_insertf32x4(v, _mm_loadu_ps(p2), 2);
    return _mm512_insertf32x4(v, _mm_loadu_ps(p3), 3);
}

} // namespace

void tetrahedralAvx512(const KernelTable& table, float* rgba, std::size_t count) {
    const LatticeMapping& m = table.map;
    __m512 offset[3], scale[3], snapBias[3];
    for (int c = 0; c < 3; ++c) {
        offset[c] = _mm512_set1_ps(m.offset[c]);
        scale[c] = _mm512_set1_ps(m.scale[c]);
        snapBias[c] = _mm512_set1_ps(m.snapBias[c]);
    }
    const __m512 top = _mm512_set1_ps(static_cast<float>(m.size - 1));
    const __m512i maxCell = _mm512_set1_epi32(m.size - 2);
    const __m512i n = _mm512_set1_epi32(m.size);
    const int dr = 4, dg = 4 * m.size, db = 4 * m.size * m.size, dAll = dr + dg + db;
    const __m512i offR = _mm512_set1_epi32(dr), offG = _mm512_set1_epi32(dg),
                  offB = _mm512_set1_epi32(db), all = _mm512_set1_epi32(dAll);
    const float* t = table.rgb;

    auto block = [&](float* p) {
        __m512 px[4];
        for (int i = 0; i < 4; ++i)
            px[i] = _mm512_loadu_ps(p + 16 * i);
        __m512 r = px[0], g = px[1], b = px[2], a = px[3];
        transpose4x4(r, g, b, a);
        __m512i cell[3];
        __m512 f[3];
        const __m512 in[3] = {r, g, b};
        for (int c = 0; c < 3; ++c)
            locateAxis<Avx512Ops>(in[c], offset[c], scale[c], snapBias[c], top, maxCell, cell[c],
                                  f[c]);
        // Float offset of the cell's origin entry in the padded table (4 floats per entry).
        const __m512i base = _mm512_slli_epi32(
            _mm512_add_epi32(
                cell[0],
                _mm512_mullo_epi32(n, _mm512_add_epi32(cell[1], _mm512_mullo_epi32(n, cell[2])))),
            2);
        const Tetrahedron<Avx512Ops> tet = tetrahedron<Avx512Ops>(f[0], f[1], f[2]);
        // The two middle vertices as table offsets from c000: + the max axis, + all - the min axis.
        const __m512i offMax = _mm512_mask_blend_epi32(
            tet.rIsMax, _mm512_mask_blend_epi32(tet.gIsMax, offB, offG), offR);
        const __m512i offMin = _mm512_mask_blend_epi32(
            tet.bIsMin, _mm512_mask_blend_epi32(tet.gIsMin, offR, offG), offB);
        __m512 w0 = tet.w0, w1 = tet.w1, w2 = tet.w2, w3 = tet.w3;
        transpose4x4(w0, w1, w2, w3); // one pixel's [w0 w1 w2 w3] per 128-bit lane
        const __m512 wq[4] = {w0, w1, w2, w3};
        alignas(64) int i0[16], iA[16], iB[16];
        _mm512_store_si512(i0, base);
        _mm512_store_si512(iA, _mm512_add_epi32(base, offMax));
        _mm512_store_si512(iB, _mm512_add_epi32(base, _mm512_sub_epi32(all, offMin)));
        for (int q = 0; q < 4; ++q) {
            // Register q holds pixels 4q..4q+3; pixel 4q+l is element 4l+q of the planes.
            const __m512 w = wq[q];
            __m512 o =
                _mm512_mul_ps(_mm512_permute_ps(w, 0x00),
                              load4(t + i0[q], t + i0[4 + q], t + i0[8 + q], t + i0[12 + q]));
            o = _mm512_fmadd_ps(_mm512_permute_ps(w, 0x55),
                                load4(t + iA[q], t + iA[4 + q], t + iA[8 + q], t + iA[12 + q]), o);
            o = _mm512_fmadd_ps(_mm512_permute_ps(w, 0xAA),
                                load4(t + iB[q], t + iB[4 + q], t + iB[8 + q], t + iB[12 + q]), o);
            o = _mm512_fmadd_ps(_mm512_permute_ps(w, 0xFF),
                                load4(t + i0[q] + dAll, t + i0[4 + q] + dAll, t + i0[8 + q] + dAll,
                                      t + i0[12 + q] + dAll),
                                o);
            _mm512_storeu_ps(p + 16 * q, _mm512_mask_blend_ps(0x8888, o, px[q]));
        }
    };

    std::size_t i = 0;
    for (; i + 16 <= count; i += 16)
        block(rgba + 4 * i);
    if (i < count) { // the tail through a padded copy: the same arithmetic as the rest
        alignas(64) float tmp[64] = {};
        const std::size_t rest = count - i;
        for (std::size_t j = 0; j < 4 * rest; ++j)
            tmp[j] = rgba[4 * i + j];
        block(tmp);
        for (std::size_t j = 0; j < 4 * rest; ++j)
            rgba[4 * i + j] = tmp[j];
    }
}

} // namespace lut::detail
