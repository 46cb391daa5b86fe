// SPDX-License-Identifier: Apache-2.0
// The linear Monge-Kantorovich map: see lut/match/MongeKantorovich.h.
#include "lut/match/MongeKantorovich.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lut {

void ColourMoments::add(const glm::dvec3& c, double w) {
    if (!(w > 0.0) || !std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
        return;
    m_weight += w;
    m_sum += w * c;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m_sumSquares[i][j] += w * c[i] * c[j];
}

void ColourMoments::merge(const ColourMoments& o) {
    m_weight += o.m_weight;
    m_sum += o.m_sum;
    m_sumSquares += o.m_sumSquares;
}

glm::dvec3 ColourMoments::mean() const {
    return m_weight > 0.0 ? m_sum / m_weight : glm::dvec3(0.0);
}

glm::dmat3 ColourMoments::covariance() const {
    if (!(m_weight > 0.0))
        return glm::dmat3(0.0);
    const glm::dvec3 mu = mean();
    glm::dmat3 c;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            c[i][j] = m_sumSquares[i][j] / m_weight - mu[i] * mu[j];
    // symmetric by construction up to rounding; make it exactly so
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            c[i][j] = c[j][i] = 0.5 * (c[i][j] + c[j][i]);
    return c;
}

void symmetricEigen(const glm::dmat3& m, glm::dvec3& values, glm::dmat3& vectors) {
    double a[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            a[i][j] = 0.5 * (m[j][i] + m[i][j]);
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int sweep = 0; sweep < 64; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double scale = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-30 * std::max(scale, 1e-300) || off == 0.0)
            break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0)
                    continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) { // columns p, q
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) { // rows p, q
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; ++i) {
        values[i] = a[i][i];
        for (int k = 0; k < 3; ++k)
            vectors[i][k] = v[k][i]; // column i = eigenvector i
    }
}

namespace {

// f applied to the eigenvalues of a symmetric matrix.
template <class F> glm::dmat3 spectral(const glm::dmat3& m, F f) {
    glm::dvec3 values;
    glm::dmat3 vectors;
    symmetricEigen(m, values, vectors);
    glm::dmat3 d(0.0);
    for (int i = 0; i < 3; ++i)
        d[i][i] = f(values[i]);
    return vectors * d * glm::transpose(vectors);
}

} // namespace

AffineColourMap mongeKantorovich(const ColourMoments& source, const ColourMoments& reference,
                                 double maxGain, double floor, MklNotes* notes) {
    MklNotes local;
    MklNotes& n = notes ? *notes : local;
    n = MklNotes{};
    maxGain = std::max(maxGain, 1.0);
    floor = std::max(floor, 1e-300);
    const glm::dmat3 su = source.covariance();
    const glm::dmat3 sv = reference.covariance();
    {
        glm::dvec3 values;
        glm::dmat3 vectors;
        symmetricEigen(su, values, vectors);
        n.sourceSpread = std::sqrt(std::max(0.0, std::min({values.x, values.y, values.z})));
    }
    const glm::dmat3 suHalf =
        spectral(su, [floor](double l) { return std::sqrt(std::max(l, floor)); });
    const glm::dmat3 suInvHalf =
        spectral(su, [floor](double l) { return 1.0 / std::sqrt(std::max(l, floor)); });
    const glm::dmat3 c = suHalf * sv * suHalf;
    const glm::dmat3 cHalf = spectral(c, [](double l) { return std::sqrt(std::max(l, 0.0)); });
    const glm::dmat3 t = suInvHalf * cHalf * suInvHalf;

    glm::dvec3 gains;
    glm::dmat3 axes;
    symmetricEigen(t, gains, axes);
    n.largestGain = std::max({gains.x, gains.y, gains.z});
    n.smallestGain = std::min({gains.x, gains.y, gains.z});
    glm::dmat3 d(0.0);
    for (int i = 0; i < 3; ++i) {
        const double g = std::isfinite(gains[i]) ? gains[i] : 1.0;
        d[i][i] = std::clamp(g, 1.0 / maxGain, maxGain);
        if (std::fabs(d[i][i] - g) > 1e-9 * std::max(1.0, std::fabs(g)))
            n.gainLimited = true;
    }
    AffineColourMap map;
    map.matrix = axes * d * glm::transpose(axes);
    map.offset = reference.mean() - map.matrix * source.mean();
    return map;
}

} // namespace lut
