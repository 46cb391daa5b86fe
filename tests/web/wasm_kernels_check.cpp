// SPDX-License-Identifier: Apache-2.0
// The browser edition's WebAssembly SIMD sampler kernels (lutlib/src/interp/simd/
// SamplerKernels_wasm.cpp) against their definition, run under Node by tests/web/run.sh: each
// output float must have the bits of the kernels' arithmetic written out here, each fused
// multiply-add computed in binary128 and rounded once (not lutkit's emulation), and so must the
// scalar portable kernels (interp/PortableKernels.cpp). Cases: random pixels on random tables, and
// tables built so that a fused multiply-add's double sum lands on a halfway point between two
// floats without being exact (where rounding the double sum to float gives the wrong float, so
// the kernel must take its exact path), about one trial in 30. Prints one line per kernel and
// exits 1 on any difference.
#include "interp/ScalarLattice.h"
#include "interp/simd/SimdKernels.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

using namespace lut::detail;

namespace {

std::uint32_t bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

struct Table {
    int n;
    std::vector<float> rgb; // 4 floats per entry, red fastest
    KernelTable view() const {
        KernelTable t;
        t.rgb = rgb.data();
        t.map.size = n;
        for (int c = 0; c < 3; ++c) {
            t.map.offset[c] = 0.0f;
            t.map.scale[c] = static_cast<float>(n - 1);
            t.map.snapBias[c] = 0.0f;
        }
        return t;
    }
    float* at(int r, int g, int b) { return &rgb[4 * (r + n * (g + n * b))]; }
};

// The fused multiply-add of the definition: a * b + c in binary128 (long double here; the
// product of two floats and its sum with a third are exact in 113 bits wherever their exponents
// lie within 60 of each other, as in every case below), rounded once to float. Not std::fma: the
// C library's fmaf of this edition (musl's) fixes a halfway sum by switching the rounding mode,
// which WebAssembly lacks, and is wrong in about half of those cases. naiveFma (the double sum
// rounded to float, wrong at halfway sums) only counts the trials that reach the kernels' exact
// path.
float exactFma(float a, float b, float c) {
    return static_cast<float>(static_cast<long double>(a) * b + c);
}
float naiveFma(float a, float b, float c) {
    return static_cast<float>(static_cast<double>(a) * b + c);
}
float (*fmaOf)(float, float, float) = &exactFma;

// The cell and fractions of one pixel, as locateAxis gives them (the oracle's own inputs).
void cellOf(const KernelTable& t, const float* p, int cell[3], float f[3]) {
    const float top = static_cast<float>(t.map.size - 1);
    for (int c = 0; c < 3; ++c)
        locateAxis<ScalarOps>(p[c], t.map.offset[c], t.map.scale[c], t.map.snapBias[c], top,
                              t.map.size - 2, cell[c], f[c]);
}

// The kernels' definition, per channel, with the exact fused multiply-add.
void trilinearDefinition(Table& tab, const KernelTable& t, const float* in, float* out) {
    int c[3];
    float f[3];
    cellOf(t, in, c, f);
    const float gr = 1.0f - f[0], gg = 1.0f - f[1], gb = 1.0f - f[2];
    const float w00 = gg * gb, w10 = f[1] * gb, w01 = gg * f[2], w11 = f[1] * f[2];
    for (int ch = 0; ch < 3; ++ch) {
        float edge[2];
        for (int h = 0; h < 2; ++h) {
            float acc = w00 * tab.at(c[0] + h, c[1], c[2])[ch];
            acc = fmaOf(w10, tab.at(c[0] + h, c[1] + 1, c[2])[ch], acc);
            acc = fmaOf(w01, tab.at(c[0] + h, c[1], c[2] + 1)[ch], acc);
            acc = fmaOf(w11, tab.at(c[0] + h, c[1] + 1, c[2] + 1)[ch], acc);
            edge[h] = acc;
        }
        out[ch] = fmaOf(f[0], edge[1], gr * edge[0]);
    }
    out[3] = in[3];
}

void tetrahedralDefinition(Table& tab, const KernelTable& t, const float* in, float* out) {
    int c[3];
    float f[3];
    cellOf(t, in, c, f);
    const Tetrahedron<ScalarOps> w = tetrahedron<ScalarOps>(f[0], f[1], f[2]);
    const TetrahedronAxes axes = axesOf(w);
    int a[3] = {c[0], c[1], c[2]}, b[3] = {c[0] + 1, c[1] + 1, c[2] + 1};
    ++a[axes.max];
    --b[axes.min];
    for (int ch = 0; ch < 3; ++ch) {
        float o = w.w0 * tab.at(c[0], c[1], c[2])[ch];
        o = fmaOf(w.w1, tab.at(a[0], a[1], a[2])[ch], o);
        o = fmaOf(w.w2, tab.at(b[0], b[1], b[2])[ch], o);
        o = fmaOf(w.w3, tab.at(c[0] + 1, c[1] + 1, c[2] + 1)[ch], o);
        out[ch] = o;
    }
    out[3] = in[3];
}

using Kernel = void (*)(const KernelTable&, float*, std::size_t);
using Definition = void (*)(Table&, const KernelTable&, const float*, float*);

struct Count {
    long pixels = 0, wrong = 0, portableWrong = 0;
};

// Runs the kernel, the portable kernel and the definition on the same pixels; counts pixels
// whose R, G, B or A bits differ.
void compare(Table& tab, std::vector<float> px, Kernel kernel, Kernel portable, Definition def,
             Count& n) {
    const KernelTable t = tab.view();
    std::vector<float> got = px, ref = px, want(px.size());
    kernel(t, got.data(), px.size() / 4);
    portable(t, ref.data(), px.size() / 4);
    for (std::size_t i = 0; i < px.size(); i += 4) {
        def(tab, t, &px[i], &want[i]);
        bool bad = false, badRef = false;
        for (int c = 0; c < 4; ++c) {
            bad = bad || bits(got[i + c]) != bits(want[i + c]);
            badRef = badRef || bits(ref[i + c]) != bits(want[i + c]);
        }
        if (bad && n.wrong < 5)
            std::printf("  pixel (%a %a %a): got %a %a %a, want %a %a %a\n", px[i], px[i + 1],
                        px[i + 2], got[i], got[i + 1], got[i + 2], want[i], want[i + 1],
                        want[i + 2]);
        n.pixels++;
        n.wrong += bad;
        n.portableWrong += badRef;
    }
}

bool run(const char* name, Kernel kernel, Kernel portable, Definition def) {
    std::mt19937 rng(38);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), wide(-0.25f, 1.25f);
    Count n;
    // Random tables and pixels (some outside the domain, a few NaN and infinite inputs).
    for (int trial = 0; trial < 20; ++trial) {
        Table tab{2 + trial % 17, {}};
        tab.rgb.assign(4 * tab.n * tab.n * tab.n, 0.0f);
        for (std::size_t i = 0; i < tab.rgb.size(); ++i)
            if (i % 4 != 3)
                tab.rgb[i] = wide(rng);
        std::vector<float> px(4 * 20000);
        for (float& v : px)
            v = wide(rng);
        px[0] = NAN;
        px[5] = INFINITY;
        px[10] = -INFINITY;
        compare(tab, px, kernel, portable, def, n);
    }
    // Halfway sums: 2^3 tables built along the pixel's own chain of multiply-adds, each entry
    // q = fl(h / w) for its weight w and h half an ulp of the running sum, so w * q lands within
    // 2^-24 relative of h: about one step in 32 rounds to a halfway double that is not exact.
    long reached = 0;
    for (int trial = 0; trial < 40000; ++trial) {
        Table tab{2, std::vector<float>(32, 0.0f)};
        const float in[4] = {unit(rng), unit(rng), unit(rng), 1.0f};
        int c[3];
        float f[3];
        cellOf(tab.view(), in, c, f);
        const auto entry = [&](int r, int g, int b) { return tab.at(r, g, b); };
        const auto halfUlp = [](float x) { return (std::nextafter(x, INFINITY) - x) * 0.5f; };
        // Along a chain: the first entry random in [1, 1.5), each next from the running sum.
        const auto chain = [&](float* const* q, const float* w, int steps) {
            for (int ch = 0; ch < 3; ++ch) {
                q[0][ch] = 1.0f + static_cast<float>(rng() % 4194304) * 0x1p-23f;
                float acc = w[0] * q[0][ch];
                for (int k = 1; k < steps; ++k) {
                    if (w[k] > 0.0f)
                        q[k][ch] = halfUlp(acc) / w[k];
                    acc = exactFma(w[k], q[k][ch], acc);
                }
            }
        };
        if (def == &trilinearDefinition) {
            const float gg = 1.0f - f[1], gb = 1.0f - f[2];
            const float w[4] = {gg * gb, f[1] * gb, gg * f[2], f[1] * f[2]};
            for (int h = 0; h < 2; ++h) {
                float* q[4] = {entry(h, 0, 0), entry(h, 1, 0), entry(h, 0, 1), entry(h, 1, 1)};
                chain(q, w, 4);
            }
        } else {
            const Tetrahedron<ScalarOps> t = tetrahedron<ScalarOps>(f[0], f[1], f[2]);
            const TetrahedronAxes axes = axesOf(t);
            int a[3] = {0, 0, 0}, b[3] = {1, 1, 1};
            ++a[axes.max];
            --b[axes.min];
            const float w[4] = {t.w0, t.w1, t.w2, t.w3};
            float* q[4] = {entry(0, 0, 0), entry(a[0], a[1], a[2]), entry(b[0], b[1], b[2]),
                           entry(1, 1, 1)};
            chain(q, w, 4);
        }
        const std::vector<float> px(in, in + 4);
        compare(tab, px, kernel, portable, def, n);
        float exact[4], naive[4];
        def(tab, tab.view(), in, exact);
        fmaOf = &naiveFma;
        def(tab, tab.view(), in, naive);
        fmaOf = &exactFma;
        reached += std::memcmp(exact, naive, sizeof exact) != 0;
    }
    std::printf("%s: %ld pixels, %ld differ from the definition (portable kernel: %ld); %ld "
                "halfway pixels where the double sum rounded to float is wrong\n",
                name, n.pixels, n.wrong, n.portableWrong, reached);
    return n.wrong == 0 && n.portableWrong == 0 && reached >= 100;
}

} // namespace

int main() {
    bool ok = run("trilinear", &trilinearWasm, &trilinearPortable, &trilinearDefinition);
    ok = run("tetrahedral", &tetrahedralWasm, &tetrahedralPortable, &tetrahedralDefinition) && ok;
    return ok ? 0 : 1;
}
