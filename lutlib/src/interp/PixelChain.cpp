// SPDX-License-Identifier: Apache-2.0
#include "lut/interp/PixelChain.h"

#include "core/simd/DomainCheck.h"
#include "lut/interp/Sampler.h"

#include <cmath>
#include <cstdio>

namespace lut {

void DomainStats::merge(const DomainStats& o) {
    pixels += o.pixels;
    outside += o.outside;
    nan += o.nan;
    if (o.worstDistance > worstDistance) {
        worstDistance = o.worstDistance;
        worst = o.worst;
    }
}

std::string DomainStats::str(glm::vec3 lo, glm::vec3 hi) const {
    if (outside == 0)
        return {};
    auto num = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%.6g", v);
        return std::string(b);
    };
    std::string dom;
    if (lo.x == lo.y && lo.y == lo.z && hi.x == hi.y && hi.y == hi.z)
        dom = "[" + num(lo.x) + ", " + num(hi.x) + "]";
    else
        dom = "[" + num(lo.x) + " " + num(lo.y) + " " + num(lo.z) + ", " + num(hi.x) + " " +
              num(hi.y) + " " + num(hi.z) + "]";
    std::string s =
        std::to_string(outside) + " of " + std::to_string(pixels) + " pixels (" +
        num(pixels ? 100.0 * static_cast<double>(outside) / static_cast<double>(pixels) : 0.0) +
        "%) outside the LUT's domain " + dom;
    if (outside > nan)
        s += " (worst " + num(worst) + ")";
    if (nan)
        s += (outside > nan ? ", " : " (") + std::to_string(nan) + " with NaN" +
             (outside > nan ? "" : ")");
    return s;
}

void countOutsideDomain(const float* rgba, std::size_t count, glm::vec3 lo, glm::vec3 hi,
                        DomainStats& st) {
    st.pixels += count;
    // A first pass without branches: most runs have nothing outside. With AVX2 where the CPU has
    // it (the plain loop does not vectorize: ~3 ns per pixel, a third of the LUT kernel's time).
    const float l0 = lo.x, l1 = lo.y, l2 = lo.z, h0 = hi.x, h1 = hi.y, h2 = hi.z;
    unsigned any = 0;
#if defined(__x86_64__) || defined(__i386__)
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2) {
        const float l[3] = {l0, l1, l2}, h[3] = {h0, h1, h2};
        any = detail::anyOutsideDomainAvx2(rgba, count, l, h);
    } else
#endif
        for (std::size_t i = 0; i < count; ++i) {
            const float* p = rgba + 4 * i;
            // !(a >= l && a <= h) is true for NaN too.
            any |= static_cast<unsigned>(!(p[0] >= l0 && p[0] <= h0)) |
                   static_cast<unsigned>(!(p[1] >= l1 && p[1] <= h1)) |
                   static_cast<unsigned>(!(p[2] >= l2 && p[2] <= h2));
        }
    if (!any)
        return;
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = rgba + 4 * i;
        bool out = false, isNan = false;
        for (int c = 0; c < 3; ++c) {
            const float v = p[c];
            if (std::isnan(v)) {
                out = isNan = true;
                continue;
            }
            const double d = v < lo[c]   ? static_cast<double>(lo[c]) - v
                             : v > hi[c] ? static_cast<double>(v) - hi[c]
                                         : 0.0;
            if (d > 0.0) {
                out = true;
                if (d > st.worstDistance) {
                    st.worstDistance = d;
                    st.worst = v;
                }
            }
        }
        st.outside += out;
        st.nan += isNan;
    }
}

namespace {

// Every value of the table in [0, 1] (NaN is not).
bool entriesInUnit(const Lut3D& lut) {
    const float* v = lut.data();
    const std::size_t n = 3 * lut.entryCount();
    bool in = true;
    for (std::size_t i = 0; i < n; ++i)
        in &= v[i] >= 0.0f && v[i] <= 1.0f;
    return in;
}

} // namespace

PixelChain::PixelChain() = default;
PixelChain::~PixelChain() = default;
PixelChain::PixelChain(const PixelChain&) = default;
PixelChain& PixelChain::operator=(const PixelChain&) = default;
PixelChain::PixelChain(PixelChain&&) noexcept = default;
PixelChain& PixelChain::operator=(PixelChain&&) noexcept = default;

void PixelChain::setLut(const Lut3D& lut, Interpolation method) {
    m_sampler = makeSampler(lut, method);
    m_domainMin = lut.domainMin();
    m_domainMax = lut.domainMax();
    const glm::vec3 lo = m_domainMin, hi = m_domainMax;
    const bool coversUnit = lo.x <= 0.0f && lo.y <= 0.0f && lo.z <= 0.0f && hi.x >= 1.0f &&
                            hi.y >= 1.0f && hi.z >= 1.0f;
    m_identityLut = coversUnit && lut.isIdentity(1e-6f);
    m_entriesInUnit = entriesInUnit(lut);
}

void PixelChain::setLut(const LutFile& file, Interpolation method) {
    if (!file.shaper && file.cube) {
        setLut(*file.cube, method);
        return;
    }
    m_sampler = makeSampler(file, method);
    m_domainMin = file.inputDomainMin();
    m_domainMax = file.inputDomainMax();
    // A shaper is taken as changing values (no identity shortcut): the chain runs.
    m_identityLut = false;
    // The table's entries bound the output whatever the shaper gives it (a 1D-only file: not
    // known, taken as unbounded).
    m_entriesInUnit = file.cube && entriesInUnit(*file.cube);
}

void PixelChain::addBefore(std::string name, PixelStep step) {
    m_before.push_back({std::move(name), std::move(step)});
}

void PixelChain::addAfter(std::string name, PixelStep step) {
    m_after.push_back({std::move(name), std::move(step)});
}

std::vector<std::string> PixelChain::stepNames() const {
    std::vector<std::string> names;
    for (const auto& s : m_before)
        names.push_back(s.name);
    if (m_sampler)
        names.emplace_back("lut");
    for (const auto& s : m_after)
        names.push_back(s.name);
    return names;
}

void PixelChain::run(float* rgba, std::size_t count, DomainStats* stats) const {
    for (const auto& s : m_before)
        s.step(rgba, count);
    if (m_sampler) {
        if (stats)
            countOutsideDomain(rgba, count, m_domainMin, m_domainMax, *stats);
        m_sampler->applyPixels(rgba, count);
    }
    for (const auto& s : m_after)
        s.step(rgba, count);
}

} // namespace lut
