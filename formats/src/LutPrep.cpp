// SPDX-License-Identifier: Apache-2.0
#include "LutPrep.h"

#include "lut/ErrorStats.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/Lattice.h"
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

Lut3D prepareUnitLut(const LutFile& file, int size, const std::string& path, Diagnostics& diags,
                     ErrorStats* shaperError) {
    using S = Diagnostic::Severity;
    if (file.shaper) {
        // The shaper, then the table, evaluated exactly at the format's lattice over [0,1] --
        // never first merged into a table of the table's size over the shaper's range.
        LatticeRequest q;
        q.size = size > 0 ? size : file.cube ? file.cube->size() : 33;
        q.domainMin = glm::vec3(0.0f);
        q.domainMax = glm::vec3(1.0f);
        LatticeResult r = sampleOnLattice(file, q);
        if (shaperError)
            *shaperError = r.error;
        r.error.seconds = 0.0;
        const glm::vec3 lo = file.inputDomainMin(), hi = file.inputDomainMax();
        const bool wider = lo.x < 0 || lo.y < 0 || lo.z < 0 || hi.x > 1 || hi.y > 1 || hi.z > 1;
        diags.push_back(makeDiagnostic(
            r.error.maxSteps8() > 1.0 ? S::Warning : S::Info, path,
            std::string("the 1D shaper") +
                (file.cube ? " and " + std::to_string(file.cube->size()) + "^3 table" : "") +
                " sampled at a " + std::to_string(q.size) + "^3 lattice " + kDisplayRangeWords +
                " (this format stores no shaper" +
                (wider
                     ? "; inputs outside 0..1 of the shaper's " + vecStr(lo) + " .. " + vecStr(hi) +
                           " take the edge value: a format that keeps the shaper, such as "
                           "--format resolve_cube, .clf or .csp, keeps them"
                     : std::string()) +
                "): " + r.error.str() + " on " + std::to_string(r.heldOut) +
                " inputs between lattice points"));
        return std::move(r.lut);
    }
    Lut3D lut = file.toLut3D(0);
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
