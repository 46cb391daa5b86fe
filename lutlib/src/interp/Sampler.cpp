// SPDX-License-Identifier: Apache-2.0
// Samplers: one class per interpolation, chosen once by makeSampler(). sample() is the scalar
// reference (the readable definition); applyPixels() runs the SIMD kernel picked at run time for
// this CPU (src/interp/simd/), which must agree with sample() to float rounding. Both map inputs
// to cells with the same template (interp/LatticeMapping.h) and pick tetrahedra with the same
// template (interp/Tetrahedral.h), so they choose the same cells, fractions and tetrahedra.
#include "lut/interp/Sampler.h"

#include "interp/LatticeMapping.h"
#include "interp/ScalarLattice.h"
#include "interp/simd/SimdKernels.h"
#include "lut/Error.h"
#include "lut/LutFile.h"
#include "lut/Parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace lut {

Sampler::~Sampler() = default;

void Sampler::apply(const ImageView& image, int nthreads) const {
    if (image.empty())
        return;
    const int threads = std::min(resolveThreads(nthreads), image.height);
    // Workers take bands of rows from a shared counter instead of one fixed half each: on a busy
    // machine a descheduled thread then delays the frame by one band, not by half of it.
    const std::size_t w = static_cast<std::size_t>(image.width);
    const int band =
        std::max(1, std::min(64, static_cast<int>((1u << 16) / std::max<std::size_t>(w, 1))));
    std::atomic<int> next{0};
    parallelFor(threads, threads, [&](int, int) {
        for (;;) {
            const int y0 = next.fetch_add(band, std::memory_order_relaxed);
            if (y0 >= image.height)
                break;
            const int y1 = std::min(image.height, y0 + band);
            if (image.strideFloats == static_cast<std::ptrdiff_t>(4 * w))
                applyPixels(image.row(y0),
                            w * static_cast<std::size_t>(y1 - y0)); // contiguous rows
            else
                for (int y = y0; y < y1; ++y)
                    applyPixels(image.row(y), w);
        }
    });
}

namespace {

using detail::KernelFn;
using detail::KernelTable;

// The table as the kernels read it: RGB plus one float of padding per entry.
std::vector<float> packTable(const Lut3D& lut) {
    std::vector<float> t(4 * lut.entryCount(), 0.0f);
    const float* src = lut.data();
    for (std::size_t i = 0; i < lut.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            t[4 * i + c] = src[3 * i + c];
    return t;
}

enum class Isa { Scalar, Avx2, Avx512 };

// A kernel of simd/ where it is compiled (x86), else none (the browser edition: the portable
// forms).
#if defined(__x86_64__) || defined(__i386__)
#define LUTKIT_X86_KERNEL(f) (&f)
#else
#define LUTKIT_X86_KERNEL(f) nullptr
#endif

// The portable form of a kernel: WebAssembly SIMD in the browser edition, else scalar C++ (the
// same bits either way).
#if defined(__wasm_simd128__)
#define LUTKIT_PORTABLE_KERNEL(name) (&detail::name##Wasm)
#else
#define LUTKIT_PORTABLE_KERNEL(name) (&detail::name##Portable)
#endif

Isa detectIsa() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
        return Isa::Scalar;
    // libgcc checks the OS saves the ZMM state (XCR0) before it reports avx512f.
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq"))
        return Isa::Avx512;
    return Isa::Avx2;
#else
    return Isa::Scalar;
#endif
}

// The path new samplers use: the best this CPU has, unless LUTKIT_SIMD asks for a lesser one
// ("scalar": the portable forms of the kernels, PortableKernels.cpp; "avx2": the AVX2 kernels on
// an AVX-512 CPU), so benchmarks and
// tests can compare them. Read on every makeSampler() call so a benchmark can switch between
// samplers in one run.
Isa chosenIsa() {
    static const Isa best = detectIsa();
    const char* env = std::getenv("LUTKIT_SIMD");
    if (env && std::strcmp(env, "scalar") == 0)
        return Isa::Scalar;
    if (env && std::strcmp(env, "avx2") == 0 && best == Isa::Avx512)
        return Isa::Avx2;
    return best;
}

// The kernel for this CPU: the AVX-512 one where there is one and the CPU has it, else AVX2,
// else the portable form of their arithmetic (null: the scalar loop, nearest's).
KernelFn pickKernel(KernelFn avx2, KernelFn avx512, KernelFn portable) {
    switch (chosenIsa()) {
    case Isa::Avx512:
        return avx512 ? avx512 : avx2;
    case Isa::Avx2:
        return avx2;
    case Isa::Scalar:
        break;
    }
    return portable;
}

class SamplerBase : public Sampler {
public:
    SamplerBase(const Lut3D& lut, KernelFn avx2, KernelFn avx512, KernelFn portable)
        : m_table(packTable(lut)), m_kernel(pickKernel(avx2, avx512, portable)) {
        m_view.rgb = m_table.data();
        m_view.map = detail::makeLatticeMapping(lut);
    }

protected:
    // The shared applyPixels body, instantiated per final class so sample() is a direct,
    // inlinable call in the scalar loop (the path CPUs without AVX2 take).
    template <class Self> static void applyWith(const Self& self, float* rgba, std::size_t count) {
        if (self.m_kernel) {
            self.m_kernel(self.m_view, rgba, count);
            return;
        }
        for (std::size_t i = 0; i < count; ++i) {
            float* p = rgba + 4 * i;
            const glm::vec3 o = self.Self::sample(glm::vec3(p[0], p[1], p[2]));
            p[0] = o.x;
            p[1] = o.y;
            p[2] = o.z;
        }
    }

    glm::vec3 e(int r, int g, int b) const {
        const std::size_t n = static_cast<std::size_t>(m_view.map.size);
        const float* p =
            &m_table[4 * (static_cast<std::size_t>(r) + n * (static_cast<std::size_t>(g) + n * b))];
        return glm::vec3(p[0], p[1], p[2]);
    }
    std::vector<float> m_table;
    KernelTable m_view;
    KernelFn m_kernel;
};

class NearestSampler final : public SamplerBase {
public:
    explicit NearestSampler(const Lut3D& lut)
        : SamplerBase(lut, LUTKIT_X86_KERNEL(detail::nearestAvx2), nullptr, nullptr) {}
    Interpolation method() const override { return Interpolation::Nearest; }
    void applyPixels(float* rgba, std::size_t count) const override {
        applyWith(*this, rgba, count);
    }
    glm::vec3 sample(glm::vec3 in) const override {
        int i[3];
        float f[3];
        detail::locate(m_view.map, in, i, f);
        // Round half up to the upper lattice point.
        return e(i[0] + (f[0] >= 0.5f), i[1] + (f[1] >= 0.5f), i[2] + (f[2] >= 0.5f));
    }
};

class TrilinearSampler final : public SamplerBase {
public:
    explicit TrilinearSampler(const Lut3D& lut)
        : SamplerBase(lut, LUTKIT_X86_KERNEL(detail::trilinearAvx2), nullptr,
                      LUTKIT_PORTABLE_KERNEL(trilinear)) {}
    Interpolation method() const override { return Interpolation::Trilinear; }
    void applyPixels(float* rgba, std::size_t count) const override {
        applyWith(*this, rgba, count);
    }
    glm::vec3 sample(glm::vec3 in) const override {
        int i[3];
        float f[3];
        detail::locate(m_view.map, in, i, f);
        const int r = i[0], g = i[1], b = i[2];
        // (1-f)*a + f*b returns a exactly at f = 0 and b exactly at f = 1.
        auto lerp = [](const glm::vec3& a, const glm::vec3& c, float t) {
            return (1.0f - t) * a + t * c;
        };
        const glm::vec3 c00 = lerp(e(r, g, b), e(r + 1, g, b), f[0]);
        const glm::vec3 c10 = lerp(e(r, g + 1, b), e(r + 1, g + 1, b), f[0]);
        const glm::vec3 c01 = lerp(e(r, g, b + 1), e(r + 1, g, b + 1), f[0]);
        const glm::vec3 c11 = lerp(e(r, g + 1, b + 1), e(r + 1, g + 1, b + 1), f[0]);
        return lerp(lerp(c00, c10, f[1]), lerp(c01, c11, f[1]), f[2]);
    }
};

class TetrahedralSampler final : public SamplerBase {
public:
    explicit TetrahedralSampler(const Lut3D& lut)
        : SamplerBase(lut, LUTKIT_X86_KERNEL(detail::tetrahedralAvx2),
                      LUTKIT_X86_KERNEL(detail::tetrahedralAvx512),
                      LUTKIT_PORTABLE_KERNEL(tetrahedral)) {}
    Interpolation method() const override { return Interpolation::Tetrahedral; }
    void applyPixels(float* rgba, std::size_t count) const override {
        applyWith(*this, rgba, count);
    }
    glm::vec3 sample(glm::vec3 in) const override {
        int i[3];
        float f[3];
        detail::locate(m_view.map, in, i, f);
        return detail::tetrahedralBlend([this](int r, int g, int b) { return e(r, g, b); }, i[0],
                                        i[1], i[2], f[0], f[1], f[2]);
    }
};

// A LUT file's 1D shaper, then its 3D table (when it has one), both exact: the shaper's kernel
// (ShaperTable, SIMD when the CPU has AVX2) on runs of kRun pixels that stay in L1, then the
// table's own sampler on the same run.
class ShapedSampler final : public Sampler {
public:
    ShapedSampler(const Lut1D& shaper, const Lut3D* cube, Interpolation method)
        : m_method(method),
          m_kernel(chosenIsa() != Isa::Scalar ? LUTKIT_X86_KERNEL(detail::shaperAvx2) : nullptr) {
        const int n = shaper.size();
        if (n < 2)
            throw Error("cannot sample a shaper of fewer than 2 entries");
        m_planes.resize(3 * static_cast<std::size_t>(n));
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < n; ++i)
                m_planes[static_cast<std::size_t>(c * n + i)] = shaper[i][c];
        const glm::vec3 lo = shaper.domainMin(), hi = shaper.domainMax();
        const float mn[3] = {lo.x, lo.y, lo.z}, mx[3] = {hi.x, hi.y, hi.z};
        m_view.planes = m_planes.data();
        m_view.map = detail::makeLatticeMapping(n, mn, mx);
        if (cube)
            m_cube = makeSampler(*cube, method);
    }
    Interpolation method() const override { return m_method; }
    glm::vec3 sample(glm::vec3 in) const override {
        const glm::vec3 v = shape(in);
        return m_cube ? m_cube->sample(v) : v;
    }
    void applyPixels(float* rgba, std::size_t count) const override {
        constexpr std::size_t kRun = 1024;
        for (std::size_t i = 0; i < count; i += kRun) {
            const std::size_t n = std::min(kRun, count - i);
            float* p = rgba + 4 * i;
            if (m_kernel) {
                m_kernel(m_view, p, n);
            } else {
                for (std::size_t k = 0; k < n; ++k) {
                    const glm::vec3 o = shape(glm::vec3(p[4 * k], p[4 * k + 1], p[4 * k + 2]));
                    p[4 * k] = o.x;
                    p[4 * k + 1] = o.y;
                    p[4 * k + 2] = o.z;
                }
            }
            if (m_cube)
                m_cube->applyPixels(p, n);
        }
    }

private:
    glm::vec3 shape(glm::vec3 in) const {
        const detail::LatticeMapping& m = m_view.map;
        const float top = static_cast<float>(m.size - 1);
        glm::vec3 out;
        for (int c = 0; c < 3; ++c) {
            int cell;
            float f;
            detail::locateAxis<detail::ScalarOps>(in[c], m.offset[c], m.scale[c], m.snapBias[c],
                                                  top, m.size - 2, cell, f);
            const float* plane = m_planes.data() + static_cast<std::size_t>(c) * m.size;
            out[c] = (1.0f - f) * plane[cell] + f * plane[cell + 1];
        }
        return out;
    }

    Interpolation m_method;
    std::vector<float> m_planes;
    detail::ShaperTable m_view;
    detail::ShaperFn m_kernel;
    std::unique_ptr<Sampler> m_cube;
};

} // namespace

std::unique_ptr<Sampler> makeSampler(const LutFile& file, Interpolation method) {
    if (file.shaper)
        return std::make_unique<ShapedSampler>(*file.shaper, file.cube ? &*file.cube : nullptr,
                                               method);
    if (!file.cube)
        throw Error("the LUT file holds no table");
    return makeSampler(*file.cube, method);
}

std::unique_ptr<Sampler> makeSampler(const Lut3D& lut, Interpolation method) {
    if (lut.empty())
        throw Error("cannot sample an empty LUT");
    switch (method) {
    case Interpolation::Nearest:
        return std::make_unique<NearestSampler>(lut);
    case Interpolation::Trilinear:
        return std::make_unique<TrilinearSampler>(lut);
    case Interpolation::Tetrahedral:
        return std::make_unique<TetrahedralSampler>(lut);
    }
    throw Error("unknown interpolation");
}

const char* samplerIsa() {
    switch (chosenIsa()) {
    case Isa::Avx512:
        return "avx512";
    case Isa::Avx2:
        return "avx2";
    case Isa::Scalar:
        break;
    }
    return "scalar";
}

} // namespace lut
