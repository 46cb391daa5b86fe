// SPDX-License-Identifier: Apache-2.0
#include "lut/match/MatchTransfer.h"

#include "lut/match/WorkingSpace.h"

#include <algorithm>
#include <cmath>

namespace lut {

bool MatchTransfer::hasShaper() const {
    if (linear)
        return true;
    for (const auto& c : pre)
        if (!c.empty())
            return true;
    return false;
}

glm::dvec3 MatchTransfer::toLattice(const glm::dvec3& x) const {
    glm::dvec3 u;
    for (int c = 0; c < 3; ++c) {
        const double w = encodeWorking(x[c], linear);
        u[c] = pre[c].empty() ? w : pre[c](w);
    }
    return u;
}

glm::dvec3 MatchTransfer::fromLattice(const glm::dvec3& u) const {
    glm::dvec3 x;
    for (int c = 0; c < 3; ++c) {
        const double w = pre[c].empty() ? u[c] : pre[c].inverse(u[c]);
        x[c] = decodeWorking(w, linear);
    }
    return x;
}

glm::dvec3 MatchTransfer::residualAt(const glm::dvec3& u) const {
    if (residualSize < 2 || residual.empty())
        return glm::dvec3(0.0);
    const int n = residualSize;
    int i0[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double range = residualMax[c] - residualMin[c];
        double p = range > 0.0 ? (u[c] - residualMin[c]) / range * (n - 1) : 0.0;
        p = std::clamp(std::isnan(p) ? 0.0 : p, 0.0, static_cast<double>(n - 1));
        i0[c] = std::min(static_cast<int>(p), n - 2);
        f[c] = p - i0[c];
    }
    glm::dvec3 acc(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        const int dr = corner & 1, dg = (corner >> 1) & 1, db = (corner >> 2) & 1;
        const double w =
            (dr ? f[0] : 1.0 - f[0]) * (dg ? f[1] : 1.0 - f[1]) * (db ? f[2] : 1.0 - f[2]);
        if (w == 0.0)
            continue;
        const std::size_t idx =
            static_cast<std::size_t>(i0[0] + dr) +
            static_cast<std::size_t>(n) *
                (static_cast<std::size_t>(i0[1] + dg) +
                 static_cast<std::size_t>(n) * static_cast<std::size_t>(i0[2] + db));
        acc += w * glm::dvec3(residual[idx]);
    }
    return acc;
}

glm::dvec3 MatchTransfer::workingOutput(const glm::dvec3& u) const {
    if (!tone.empty()) {
        const double l = lumaMatch(0.2126 * u.x + 0.7152 * u.y + 0.0722 * u.z);
        const double n = static_cast<double>(tone.size() - 1);
        double p = toneMax > toneMin ? (l - toneMin) / (toneMax - toneMin) * n : 0.0;
        p = std::clamp(std::isnan(p) ? 0.0 : p, 0.0, n);
        const std::size_t k = std::min(static_cast<std::size_t>(p), tone.size() - 1);
        const std::size_t k1 = std::min(k + 1, tone.size() - 1);
        const double f = p - static_cast<double>(k);
        return tone[k] * (1.0 - f) + tone[k1] * f;
    }
    const glm::dvec3 a = affine(u);
    glm::dvec3 v;
    for (int c = 0; c < 3; ++c)
        v[c] = post[c].empty() ? a[c] : post[c](a[c]);
    return v + residualAt(u);
}

glm::dvec3 MatchTransfer::latticeOutput(const glm::dvec3& u) const {
    const glm::dvec3 v = workingOutput(u);
    return {decodeWorking(v.x, linear), decodeWorking(v.y, linear), decodeWorking(v.z, linear)};
}

} // namespace lut
