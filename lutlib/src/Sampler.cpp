// Scalar reference samplers: one class per interpolation, chosen once by makeSampler().
// The SIMD kernels (src/simd/) must agree with these; they are the readable definition.
#include "lut/Sampler.h"

#include "SamplerDetail.h"
#include "lut/Error.h"
#include "lut/Parallel.h"

#include <algorithm>
#include <cmath>

namespace lut {

Sampler::~Sampler() = default;

void Sampler::apply(const ImageView& image, int nthreads) const {
    if (image.empty()) return;
    parallelFor(image.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) applyPixels(image.row(y), static_cast<std::size_t>(image.width));
    });
}

namespace detail {

LatticeMap::LatticeMap(const Lut3D& lut) : size(lut.size()) {
    for (int c = 0; c < 3; ++c) {
        const double lo = lut.domainMin()[c], hi = lut.domainMax()[c];
        double s = (size - 1) / (hi - lo);
        if (!std::isfinite(s)) s = 3.0e38; // degenerate domain: keep the scale finite
        scale[c] = s;
        offset[c] = lo;
    }
}

void LatticeMap::locate(glm::vec3 in, int idx[3], float frac[3]) const {
    const double top = size - 1;
    for (int c = 0; c < 3; ++c) {
        double t = (static_cast<double>(in[c]) - offset[c]) * scale[c];
        // NaN and -Inf fail the comparison and land on 0; +Inf clamps to the top.
        if (!(t > 0.0)) t = 0.0;
        if (t > top) t = top;
        int i = static_cast<int>(t);
        if (i > size - 2) i = size - 2;
        idx[c] = i;
        frac[c] = static_cast<float>(t - i);
    }
}

} // namespace detail

namespace {

using detail::LatticeMap;

class ScalarSamplerBase : public Sampler {
public:
    explicit ScalarSamplerBase(const Lut3D& lut) : m_map(lut), m_entries(lut.entries()) {}
    void applyPixels(float* rgba, std::size_t count) const override {
        for (std::size_t i = 0; i < count; ++i) {
            float* p = rgba + 4 * i;
            const glm::vec3 o = sample(glm::vec3(p[0], p[1], p[2]));
            p[0] = o.x;
            p[1] = o.y;
            p[2] = o.z;
        }
    }

protected:
    const glm::vec3& e(int r, int g, int b) const {
        const std::size_t n = static_cast<std::size_t>(m_map.size);
        return m_entries[static_cast<std::size_t>(r) + n * (static_cast<std::size_t>(g) + n * b)];
    }
    LatticeMap m_map;
    std::vector<glm::vec3> m_entries;
};

class NearestSampler final : public ScalarSamplerBase {
public:
    using ScalarSamplerBase::ScalarSamplerBase;
    Interpolation method() const override { return Interpolation::Nearest; }
    glm::vec3 sample(glm::vec3 in) const override {
        int i[3];
        float f[3];
        m_map.locate(in, i, f);
        // Round half up to the upper lattice point.
        return e(i[0] + (f[0] >= 0.5f), i[1] + (f[1] >= 0.5f), i[2] + (f[2] >= 0.5f));
    }
};

class TrilinearSampler final : public ScalarSamplerBase {
public:
    using ScalarSamplerBase::ScalarSamplerBase;
    Interpolation method() const override { return Interpolation::Trilinear; }
    glm::vec3 sample(glm::vec3 in) const override {
        int i[3];
        float f[3];
        m_map.locate(in, i, f);
        const int r = i[0], g = i[1], b = i[2];
        // (1-f)*a + f*b returns a exactly at f = 0 and b exactly at f = 1.
        auto lerp = [](const glm::vec3& a, const glm::vec3& c, float t) { return (1.0f - t) * a + t * c; };
        const glm::vec3 c00 = lerp(e(r, g, b), e(r + 1, g, b), f[0]);
        const glm::vec3 c10 = lerp(e(r, g + 1, b), e(r + 1, g + 1, b), f[0]);
        const glm::vec3 c01 = lerp(e(r, g, b + 1), e(r + 1, g, b + 1), f[0]);
        const glm::vec3 c11 = lerp(e(r, g + 1, b + 1), e(r + 1, g + 1, b + 1), f[0]);
        return lerp(lerp(c00, c10, f[1]), lerp(c01, c11, f[1]), f[2]);
    }
};

class TetrahedralSampler final : public ScalarSamplerBase {
public:
    using ScalarSamplerBase::ScalarSamplerBase;
    Interpolation method() const override { return Interpolation::Tetrahedral; }
    glm::vec3 sample(glm::vec3 in) const override {
        int i[3];
        float f[3];
        m_map.locate(in, i, f);
        const int r = i[0], g = i[1], b = i[2];
        const float fr = f[0], fg = f[1], fb = f[2];
        const glm::vec3& c000 = e(r, g, b);
        const glm::vec3& c111 = e(r + 1, g + 1, b + 1);
        // The cube is split into six tetrahedra by the order of the fractions; each shares the
        // main diagonal c000-c111, so greys stay on it.
        if (fr > fg) {
            if (fg > fb)
                return (1 - fr) * c000 + (fr - fg) * e(r + 1, g, b) + (fg - fb) * e(r + 1, g + 1, b) + fb * c111;
            if (fr > fb)
                return (1 - fr) * c000 + (fr - fb) * e(r + 1, g, b) + (fb - fg) * e(r + 1, g, b + 1) + fg * c111;
            return (1 - fb) * c000 + (fb - fr) * e(r, g, b + 1) + (fr - fg) * e(r + 1, g, b + 1) + fg * c111;
        }
        if (fb > fg)
            return (1 - fb) * c000 + (fb - fg) * e(r, g, b + 1) + (fg - fr) * e(r, g + 1, b + 1) + fr * c111;
        if (fb > fr)
            return (1 - fg) * c000 + (fg - fb) * e(r, g + 1, b) + (fb - fr) * e(r, g + 1, b + 1) + fr * c111;
        return (1 - fg) * c000 + (fg - fr) * e(r, g + 1, b) + (fr - fb) * e(r + 1, g + 1, b) + fb * c111;
    }
};

} // namespace

std::unique_ptr<Sampler> makeSampler(const Lut3D& lut, Interpolation method) {
    if (lut.empty()) throw Error("cannot sample an empty LUT");
    switch (method) {
    case Interpolation::Nearest: return std::make_unique<NearestSampler>(lut);
    case Interpolation::Trilinear: return std::make_unique<TrilinearSampler>(lut);
    case Interpolation::Tetrahedral: return std::make_unique<TetrahedralSampler>(lut);
    }
    throw Error("unknown interpolation");
}

const char* samplerIsa() { return "scalar"; }

} // namespace lut
