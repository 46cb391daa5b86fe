// SPDX-License-Identifier: Apache-2.0
#include "ops/OpsDetail.h"

#include "interp/ScalarLattice.h"
#include "lut/Parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>

namespace lut::detail {

Lut3D sanitizedCopy(const Lut3D& lut, std::size_t& replaced) {
    Lut3D out = lut;
    replaced = 0;
    for (auto& e : out.entries()) {
        const glm::vec3 s(sanitizeValue(e.x), sanitizeValue(e.y), sanitizeValue(e.z));
        // Compare bit patterns through the values: NaN != NaN counts as replaced.
        if (!(s.x == e.x && s.y == e.y && s.z == e.z))
            ++replaced;
        e = s;
    }
    return out;
}

TetraEval::TetraEval(const Lut3D& lut)
    : m_lut(&lut), m_n(lut.size()), m_lo(lut.domainMin()), m_hi(lut.domainMax()) {
    for (int c = 0; c < 3; ++c)
        m_scale[c] = (m_n - 1) / (m_hi[c] - m_lo[c]);
}

glm::dvec3 TetraEval::operator()(glm::dvec3 in, glm::dmat3* jacobian) const {
    int idx[3];
    double frac[3];
    bool clamped[3];
    for (int c = 0; c < 3; ++c)
        locateContinuous(in[c], m_lo[c], m_scale[c], m_n, idx[c], frac[c], clamped[c]);
    // The sampler's tetrahedron (interp/Tetrahedral.h), in double: the path c000 -> c111 steps
    // along the axes in order of decreasing fraction; value and slopes follow from it.
    const auto t = tetrahedron<BasicScalarOps<double>>(frac[0], frac[1], frac[2]);
    const TetrahedronAxes axes = axesOf(t);
    int a[3] = {idx[0], idx[1], idx[2]};
    int b[3] = {idx[0] + 1, idx[1] + 1, idx[2] + 1};
    ++a[axes.max];
    --b[axes.min];
    auto entry = [&](const int* p) { return glm::dvec3(m_lut->at(p[0], p[1], p[2])); };
    const glm::dvec3 c000 = entry(idx), cA = entry(a), cB = entry(b);
    const glm::dvec3 c111 = glm::dvec3(m_lut->at(idx[0] + 1, idx[1] + 1, idx[2] + 1));
    if (jacobian) {
        glm::dvec3 steps[3];
        steps[axes.max] = cA - c000;
        steps[axes.mid] = cB - cA;
        steps[axes.min] = c111 - cB;
        for (int c = 0; c < 3; ++c)
            (*jacobian)[c] = clamped[c] ? glm::dvec3(0.0) : steps[c] * m_scale[c];
    }
    return t.w0 * c000 + t.w1 * cA + t.w2 * cB + t.w3 * c111;
}

int probeCount(int latticeSize) {
    const int full = 2 * (latticeSize - 1) + 1;
    if (full <= 129)
        return std::max(full, 9);
    // Too many to hit every cell centre: use a grid whose spacing shares no factor with the
    // lattice's, so the probes fall at every kind of position inside the cells instead of on
    // the lattice points (where the error is 0 and would be reported as such).
    for (int intervals = 127; intervals > 64; --intervals)
        if (std::gcd(intervals, latticeSize - 1) == 1)
            return intervals + 1;
    return 128;
}

PiecewiseLinearInverse::PiecewiseLinearInverse(std::vector<double> xs, std::vector<double> ys)
    : m_x(std::move(xs)) {
    const std::size_t n = ys.size();
    m_dir = ys.back() >= ys.front() ? 1.0 : -1.0;
    m_s.resize(n);
    m_max.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        m_s[i] = m_dir * ys[i];
        m_max[i] = i == 0 ? m_s[i] : std::max(m_max[i - 1], m_s[i]);
        if (m_s[i] < m_s[m_argMin])
            m_argMin = i;
        if (m_s[i] > m_s[m_argMax])
            m_argMax = i;
        if (i > 0 && !(m_s[i] > m_s[i - 1]))
            ++m_nonMonotone;
    }
}

CurveInverse PiecewiseLinearInverse::operator()(double y) const {
    const double u = m_dir * y;
    const std::size_t n = m_s.size();
    auto lerp = [&](std::size_t i) { // on segment (i, i+1), which crosses u
        const double d = m_s[i + 1] - m_s[i];
        const double t = d != 0.0 ? std::clamp((u - m_s[i]) / d, 0.0, 1.0) : 0.0;
        return m_x[i] + t * (m_x[i + 1] - m_x[i]);
    };
    if (std::isnan(u))
        return {m_x[m_argMin], false};
    if (u > m_max.back())
        return {m_x[m_argMax], false};
    if (u >= m_max.front()) {
        const std::size_t j = static_cast<std::size_t>(
            std::lower_bound(m_max.begin(), m_max.end(), u) - m_max.begin());
        if (j == 0 || m_s[j] == u)
            return {m_x[j], true};
        return {lerp(j - 1), true};
    }
    for (std::size_t i = 0; i + 1 < n; ++i)
        if ((m_s[i] - u) * (m_s[i + 1] - u) <= 0.0)
            return {lerp(i), true};
    return {m_x[m_argMin], false};
}

long long nowNanos() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double secondsSince(long long startNanos) {
    return static_cast<double>(nowNanos() - startNanos) * 1e-9;
}

} // namespace lut::detail
