// SPDX-License-Identifier: Apache-2.0
// The SIMD kernels' arithmetic, one pixel at a time, in portable C++: what applyPixels runs where
// there is no AVX2 (the browser edition's WebAssembly, a CPU without AVX2), so that every
// machine and every edition gives the same bits (docs/portable.md). Each output is the AVX2
// kernel's sequence of operations on its lane (simd/SamplerKernels_avx2.cpp): the same weights,
// the same order, and its fused multiply-adds as fused multiply-adds (detail::madd: the FMA
// instruction, or its exact emulation). The readable definition stays each sampler's sample().
#include "core/FastMath.h"
#include "interp/ScalarLattice.h"
#include "interp/simd/SimdKernels.h"

namespace lut::detail {

namespace {

struct Cell {
    std::size_t base; // float offset of the cell's origin entry (4 floats per entry)
    float f[3];       // fractions
};

inline Cell locateCell(const KernelTable& t, const float* p) {
    const LatticeMapping& m = t.map;
    const float top = static_cast<float>(m.size - 1);
    int cell[3];
    Cell c;
    for (int ch = 0; ch < 3; ++ch)
        locateAxis<ScalarOps>(p[ch], m.offset[ch], m.scale[ch], m.snapBias[ch], top, m.size - 2,
                              cell[ch], c.f[ch]);
    const std::size_t n = static_cast<std::size_t>(m.size);
    c.base = 4 * (static_cast<std::size_t>(cell[0]) +
                  n * (static_cast<std::size_t>(cell[1]) + n * static_cast<std::size_t>(cell[2])));
    return c;
}

} // namespace

void trilinearPortable(const KernelTable& table, float* rgba, std::size_t count) {
    const std::size_t n = static_cast<std::size_t>(table.map.size);
    const std::size_t dr = 4, dg = 4 * n, db = 4 * n * n;
    for (std::size_t i = 0; i < count; ++i) {
        float* p = rgba + 4 * i;
        const Cell c = locateCell(table, p);
        const float fr = c.f[0], fg = c.f[1], fb = c.f[2];
        const float gr = 1.0f - fr, gg = 1.0f - fg, gb = 1.0f - fb;
        const float w00 = gg * gb, w10 = fg * gb, w01 = gg * fb, w11 = fg * fb;
        const float* e = table.rgb + c.base;
        for (int ch = 0; ch < 3; ++ch) {
            // The red-axis edge at r (lo) and at r + 1 (hi), as the kernel's two halves.
            float edge[2];
            for (int h = 0; h < 2; ++h) {
                const float* q = e + ch + h * dr;
                float acc = w00 * q[0];
                acc = madd(w10, q[dg], acc);
                acc = madd(w01, q[db], acc);
                acc = madd(w11, q[db + dg], acc);
                edge[h] = acc;
            }
            p[ch] = madd(fr, edge[1], gr * edge[0]);
        }
    }
}

void tetrahedralPortable(const KernelTable& table, float* rgba, std::size_t count) {
    const std::size_t n = static_cast<std::size_t>(table.map.size);
    const std::size_t dr = 4, dg = 4 * n, db = 4 * n * n, dAll = dr + dg + db;
    for (std::size_t i = 0; i < count; ++i) {
        float* p = rgba + 4 * i;
        const Cell c = locateCell(table, p);
        const Tetrahedron<ScalarOps> t = tetrahedron<ScalarOps>(c.f[0], c.f[1], c.f[2]);
        const std::size_t offMax = t.rIsMax ? dr : t.gIsMax ? dg : db;
        const std::size_t offMin = t.bIsMin ? db : t.gIsMin ? dg : dr;
        const float* c000 = table.rgb + c.base;
        const float* cA = c000 + offMax;
        const float* cB = c000 + dAll - offMin;
        const float* c111 = c000 + dAll;
        for (int ch = 0; ch < 3; ++ch) {
            float o = t.w0 * c000[ch];
            o = madd(t.w1, cA[ch], o);
            o = madd(t.w2, cB[ch], o);
            o = madd(t.w3, c111[ch], o);
            p[ch] = o;
        }
    }
}

} // namespace lut::detail
