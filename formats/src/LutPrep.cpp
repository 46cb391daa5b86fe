#include "LutPrep.h"

#include "lut/ErrorStats.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/Resample.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut::formats {

Diagnostic makeDiagnostic(Diagnostic::Severity severity, const std::string& path,
                          std::string message) {
    Diagnostic d;
    d.severity = severity;
    d.path = path;
    d.message = std::move(message);
    return d;
}

static std::string vecStr(glm::vec3 v) {
    auto f = [](float x) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", static_cast<double>(x));
        return std::string(buf);
    };
    return f(v.x) + " " + f(v.y) + " " + f(v.z);
}

Lut3D prepareUnitLut(const LutFile& file, int size, const std::string& path, Diagnostics& diags) {
    using S = Diagnostic::Severity;
    Lut3D lut = file.toLut3D(0);
    if (file.shaper)
        diags.push_back(makeDiagnostic(S::Info, path,
                                       "the 1D shaper was baked into a " +
                                           std::to_string(lut.size()) +
                                           "^3 table (this format stores no shaper)"));
    const int target = size > 0 ? size : lut.size();
    if (!lut.hasDefaultDomain()) {
        // The file format implies inputs 0..1: evaluate the source there.
        const auto sampler = makeSampler(lut, Interpolation::Tetrahedral);
        Lut3D out(target);
        out.setTitle(lut.title());
        out.comments() = lut.comments();
        const float inv = 1.0f / static_cast<float>(target - 1);
        for (int b = 0; b < target; ++b)
            for (int g = 0; g < target; ++g)
                for (int r = 0; r < target; ++r)
                    out.at(r, g, b) = sampler->sample(glm::vec3(r * inv, g * inv, b * inv));
        diags.push_back(makeDiagnostic(S::Warning, path,
                                       "the domain " + vecStr(lut.domainMin()) + " .. " +
                                           vecStr(lut.domainMax()) +
                                           " was re-sampled onto 0..1 (this format has no domain; "
                                           "inputs outside the old domain "
                                           "take its edge value)"));
        return out;
    }
    if (target != lut.size()) {
        const int from = lut.size();
        ResampleResult rr = resampleWithError(lut, target, Interpolation::Tetrahedral);
        rr.lut.setTitle(lut.title());
        rr.lut.comments() = lut.comments();
        diags.push_back(makeDiagnostic(S::Info, path,
                                       "resampled " + std::to_string(from) + "^3 -> " +
                                           std::to_string(target) +
                                           "^3 (tetrahedral): " + rr.error.str()));
        return std::move(rr.lut);
    }
    return lut;
}

std::size_t countOutOfUnitRange(const Lut3D& lut) {
    std::size_t n = 0;
    for (const glm::vec3& v : lut.entries())
        for (int c = 0; c < 3; ++c)
            if (!(v[c] >= 0.0f && v[c] <= 1.0f))
                ++n;
    return n;
}

void addClampDiagnostic(std::size_t count, int bits, const std::string& path, Diagnostics& diags) {
    if (count == 0)
        return;
    diags.push_back(makeDiagnostic(
        Diagnostic::Severity::Warning, path,
        std::to_string(count) + " channel value" + (count == 1 ? "" : "s") +
            " outside 0..1 (or NaN) clamped to fit " + std::to_string(bits) + "-bit output"));
}

void addQuantizationDiagnostic(const Lut3D& lut, int bits, const std::string& path,
                               Diagnostics& diags) {
    ErrorAccumulator acc;
    for (const glm::vec3& v : lut.entries())
        for (int c = 0; c < 3; ++c) {
            const float q = bits == 8 ? fromUnorm8(toUnorm8(v[c])) : fromUnorm16(toUnorm16(v[c]));
            const float ref = std::isfinite(v[c]) ? std::max(0.0f, std::min(1.0f, v[c])) : q;
            acc.add(q, ref);
        }
    const ErrorStats e = acc.result();
    if (e.maxAbs > 0)
        diags.push_back(
            makeDiagnostic(Diagnostic::Severity::Info, path,
                           "quantised to " + std::to_string(bits) + " bits: " + e.str()));
}

} // namespace lut::formats
