// SPDX-License-Identifier: Apache-2.0
// Scalar, accurate (std::pow) forms of the Smash grading math. The pipeline's grading pass uses
// polynomial pows for speed (pipeline/GradeStages.cpp, core/FastMath.h) and is tested against
// these and a float64 reference.
#include "lut/smash/SmashGrading.h"
#include "lut/smash/SmashUngrader.h"

#include "core/FastMath.h"
#include "lut/Limits.h"
#include "lut/Math.h"
#include "lut/Parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace lut {

using detail::sanitizeValue;

float smashEncode(float x) {
    x = sanitizeValue(x, limits::kMaxColorValue);
    return x > 0.0f ? lut::math::pow(x, kSmashEncodeExponent) : 0.0f;
}

glm::vec3 smashEncode(glm::vec3 v) {
    return {smashEncode(v.x), smashEncode(v.y), smashEncode(v.z)};
}

float smashEncodeInverse(float s) {
    s = sanitizeValue(s, 1.0e6f);
    return s > 0.0f ? static_cast<float>(
                          lut::math::pow(static_cast<double>(s), 1.0 / kSmashEncodeExponent))
                    : 0.0f;
}

float smashDecode(float r) {
    r = sanitizeValue(r, 1.0e6f);
    return r > 0.0f ? lut::math::pow(r, kSmashDecodeExponent) : 0.0f;
}

glm::vec3 smashBrighten(glm::vec3 lutOut, glm::vec3 s) {
    return ((lutOut - s) * kSmashBrightenMix + s) * kSmashBrightenScale;
}

glm::vec3 smashBrightenInverse(glm::vec3 r, glm::vec3 s) {
    return (r / kSmashBrightenScale - s) / kSmashBrightenMix + s;
}

glm::vec3 smashGrade(glm::vec3 linear, const Sampler& lut) {
    const glm::vec3 s = smashEncode(linear);
    const glm::vec3 r = smashBrighten(lut.sample(s), s);
    return {smashDecode(r.x), smashDecode(r.y), smashDecode(r.z)};
}

glm::vec3 smashGradeMix(glm::vec3 linear, float alpha, const Sampler& lut) {
    const float a = detail::clamp01(alpha);
    if (a <= 0.0f)
        return linear;
    const glm::vec3 g = smashGrade(linear, lut);
    if (a >= 1.0f)
        return g;
    return linear * (1.0f - a) + g * a;
}

glm::vec3 smashLutEntryForTarget(glm::vec3 targetLinear, glm::vec3 s) {
    glm::vec3 r;
    for (int c = 0; c < 3; ++c) {
        const double t = sanitizeValue(targetLinear[c], limits::kMaxColorValue);
        r[c] = static_cast<float>(t > 0.0 ? lut::math::pow(t, 1.0 / kSmashDecodeExponent) : 0.0);
    }
    return smashBrightenInverse(r, s);
}

Lut3D smashCompensateLut(const Lut3D& target) {
    const int n = target.size();
    Lut3D out(n);
    const Lut3D ident = Lut3D::identity(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                out.at(r, g, b) = smashLutEntryForTarget(target.at(r, g, b), ident.at(r, g, b));
    out.setTitle(target.title());
    return out;
}

namespace {

// Gamma-space image of the graded+mixed output for gamma-space input s: pow(F(s), 1/2.2).
struct GradeMap {
    const Sampler& lut;
    float a;
    glm::dvec3 operator()(const glm::dvec3& s) const {
        const glm::vec3 sf(s);
        const glm::vec3 r = smashBrighten(lut.sample(sf), sf);
        if (a >= 1.0f)
            return glm::dvec3(r);
        glm::dvec3 out;
        for (int c = 0; c < 3; ++c) {
            const double x = s[c] > 0.0 ? lut::math::pow(s[c], 1.0 / kSmashEncodeExponent) : 0.0;
            const double g = r[c] > 0.0f ? lut::math::pow(static_cast<double>(r[c]), 2.2) : 0.0;
            const double f = (1.0 - a) * x + a * g;
            out[c] = f > 0.0 ? lut::math::pow(f, 1.0 / 2.2) : 0.0;
        }
        return out;
    }
};

double maxAbs(const glm::dvec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// The inverse for an identity LUT with alpha 1, one channel: a function of that channel's value
// alone (the brighten pass is per channel), so it can be memoised per value (smashUngrade).
float neutralUngradeChannel(float v) {
    const float o = std::max(sanitizeValue(v, limits::kMaxColorValue), 0.0f);
    const double target = o > 0.0f ? lut::math::pow(static_cast<double>(o), 1.0 / 2.2) : 0.0;
    const double k = 1.0 - static_cast<double>(kSmashBrightenMix);
    const double t = target / static_cast<double>(kSmashBrightenScale);
    const double s = t <= 1.0 ? t : (t - static_cast<double>(kSmashBrightenMix)) / k;
    return smashEncodeInverse(static_cast<float>(s));
}

// neutralUngradeChannel remembered for the values seen (a screenshot has at most 256 per
// channel): direct-mapped on the value's bits, one per thread, bit-identical by construction.
class NeutralUngradeMemo {
public:
    float operator()(float v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, 4);
        const std::uint32_t slot = (bits ^ (bits >> 13) ^ (bits >> 23)) & (kSlots - 1);
        if (!m_used[slot] || m_key[slot] != bits) {
            m_key[slot] = bits;
            m_value[slot] = neutralUngradeChannel(v);
            m_used[slot] = 1;
        }
        return m_value[slot];
    }

private:
    static constexpr std::uint32_t kSlots = 4096;
    std::vector<std::uint32_t> m_key = std::vector<std::uint32_t>(kSlots);
    std::vector<float> m_value = std::vector<float>(kSlots);
    std::vector<unsigned char> m_used = std::vector<unsigned char>(kSlots, 0);
};

} // namespace

glm::vec3 smashGradeInverse(glm::vec3 outputLinear, float alpha, const Sampler& lut,
                            bool identityLut, bool* converged) {
    const float a = detail::clamp01(alpha);
    if (identityLut && a >= 1.0f) {
        if (converged)
            *converged = true;
        return glm::vec3(neutralUngradeChannel(outputLinear.x),
                         neutralUngradeChannel(outputLinear.y),
                         neutralUngradeChannel(outputLinear.z));
    }
    glm::vec3 out;
    for (int c = 0; c < 3; ++c)
        out[c] = std::max(sanitizeValue(outputLinear[c], limits::kMaxColorValue), 0.0f);
    if (converged)
        *converged = true;
    if (a <= 0.0f)
        return out;

    glm::dvec3 target;
    for (int c = 0; c < 3; ++c)
        target[c] = out[c] > 0.0f ? lut::math::pow(static_cast<double>(out[c]), 1.0 / 2.2) : 0.0;
    // The neutral solution (exact for an identity LUT with alpha 1: above): the start point.
    const double k = 1.0 - static_cast<double>(kSmashBrightenMix);
    glm::dvec3 s;
    for (int c = 0; c < 3; ++c) {
        const double t = target[c] / static_cast<double>(kSmashBrightenScale);
        s[c] = t <= 1.0 ? t : (t - static_cast<double>(kSmashBrightenMix)) / k;
    }
    auto toLinear = [](const glm::dvec3& sv) {
        glm::vec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = smashEncodeInverse(static_cast<float>(sv[c]));
        return x;
    };

    const GradeMap phi{lut, a};
    const double tol = 1e-6 * std::max(1.0, maxAbs(target));
    glm::dvec3 f = phi(s) - target;
    double norm = maxAbs(f);
    for (int it = 0; it < 40 && norm > tol; ++it) {
        // Forward-difference Jacobian: the map is piecewise trilinear, so within a cell this is
        // (nearly) exact, and across a lattice plane Newton still makes progress.
        double J[3][3];
        const double h = 1e-4;
        for (int c = 0; c < 3; ++c) {
            glm::dvec3 sp = s;
            sp[c] += h;
            const glm::dvec3 fp = phi(sp) - target;
            for (int r = 0; r < 3; ++r)
                J[r][c] = (fp[r] - f[r]) / h;
        }
        const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                           J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        glm::dvec3 d;
        if (std::fabs(det) > 1e-12 && std::isfinite(det)) {
            // Cramer's rule for J d = -f.
            const glm::dvec3 b = -f;
            auto det3 = [&](int col) {
                double m[3][3];
                for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c)
                        m[r][c] = c == col ? b[r] : J[r][c];
                return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            };
            d = glm::dvec3(det3(0), det3(1), det3(2)) / det;
        } else {
            d = -f / static_cast<double>(kSmashBrightenScale); // fixed-point step
        }
        bool accepted = false;
        for (double lambda = 1.0; lambda >= 1.0 / 256.0; lambda *= 0.5) {
            glm::dvec3 sn = s + lambda * d;
            for (int c = 0; c < 3; ++c)
                sn[c] = std::clamp(sn[c], 0.0, 1.0e4);
            const glm::dvec3 fn = phi(sn) - target;
            const double nn = maxAbs(fn);
            if (nn < norm) {
                s = sn;
                f = fn;
                norm = nn;
                accepted = true;
                break;
            }
        }
        if (!accepted)
            break;
    }
    if (converged)
        *converged = norm <= tol * 4.0;
    return toLinear(s);
}

SmashUngrader::SmashUngrader(const Lut3D* stageLut, Interpolation interp) {
    const Lut3D neutral = Lut3D::identity(kSmashLutSize);
    const Lut3D& lut = stageLut ? *stageLut : neutral;
    m_sampler = makeSampler(lut, interp); // its own copy of the table
    m_identity = lut.hasDefaultDomain() && lut.isIdentity(1e-6f);
}

SmashUngrader::~SmashUngrader() = default;

float SmashUngrader::neutralChannel(float linear) {
    return neutralUngradeChannel(linear);
}
SmashUngrader::SmashUngrader(SmashUngrader&&) noexcept = default;
SmashUngrader& SmashUngrader::operator=(SmashUngrader&&) noexcept = default;

std::size_t SmashUngrader::apply(float* p, std::size_t count) const {
    // The memo holds a pure function of the value (the neutral ungrade), so one per thread serves
    // every ungrader and every call.
    thread_local NeutralUngradeMemo memo;
    std::size_t bad = 0;
    for (std::size_t i = 0; i < count; ++i, p += 4) {
        if (m_identity && detail::clamp01(p[3]) >= 1.0f) { // the same as smashGradeInverse
            p[0] = memo(p[0]);
            p[1] = memo(p[1]);
            p[2] = memo(p[2]);
            continue;
        }
        bool ok = true;
        const glm::vec3 v =
            smashGradeInverse(glm::vec3(p[0], p[1], p[2]), p[3], *m_sampler, m_identity, &ok);
        p[0] = v.x;
        p[1] = v.y;
        p[2] = v.z;
        bad += ok ? 0 : 1;
    }
    return bad;
}

Diagnostics ungradeNotes(std::size_t unconverged) {
    Diagnostics notes;
    Diagnostic note;
    note.severity = Diagnostic::Severity::Info;
    note.id = NoteId::BloomNotUndone;
    note.message = "bloom cannot be undone: the screenshot's bloom stays in the recovered frame "
                   "(and is added again unless bloom is disabled)";
    notes.push_back(note);
    if (unconverged > 0) {
        Diagnostic w;
        w.severity = Diagnostic::Severity::Warning;
        w.message = std::to_string(unconverged) +
                    " pixel(s) have colours the original LUT cannot produce; kept the closest";
        notes.push_back(w);
    }
    return notes;
}

UngradeResult smashUngrade(const ImageView& frame, const Lut3D* originalLut, Interpolation interp,
                           int nthreads) {
    UngradeResult result;
    const SmashUngrader ungrader(originalLut, interp);
    std::atomic<std::size_t> bad{0};
    if (!frame.empty()) {
        parallelFor(frame.height, nthreads, [&](int y0, int y1) {
            std::size_t localBad = 0;
            for (int y = y0; y < y1; ++y)
                localBad += ungrader.apply(frame.row(y), static_cast<std::size_t>(frame.width));
            bad += localBad;
        });
        result.pixels = static_cast<std::size_t>(frame.width) * frame.height;
    }
    result.unconverged = bad.load();
    result.diagnostics = ungradeNotes(result.unconverged);
    return result;
}

} // namespace lut
