// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioSampling.h"

#include "ocio/OcioMeasure.h"

#include "lut/Limits.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut::formats {

namespace {

OCIO::ConstCPUProcessorRcPtr cpuOf(const OCIO::ConstProcessorRcPtr& p) {
    return faithfulCpu(p);
}

RgbFunction functionOf(const OCIO::ConstCPUProcessorRcPtr& cpu) {
    return [cpu](float* rgb, std::size_t n) {
        OCIO::PackedImageDesc desc(rgb, static_cast<long>(n), 1, 3);
        cpu->apply(desc);
    };
}

// A lattice of edge n over [lo, hi], each entry what cpu computes at its input.
Lut3D sampleLattice(const std::string& path, const OCIO::ConstCPUProcessorRcPtr& cpu, int n,
                    glm::vec3 lo, glm::vec3 hi) {
    const std::uint64_t bytes = static_cast<std::uint64_t>(n) * n * n * 12;
    Lut3D lut = allocating(path, "the " + std::to_string(n) + "^3 lattice", bytes,
                           [&] { return Lut3D(n); });
    if (lo != glm::vec3(0.0f) || hi != glm::vec3(1.0f))
        lut.setDomain(lo, hi);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                lut.at(r, g, b) = lut.latticeInput(r, g, b);
    // The lattice is in our order (red fastest) already: OCIO maps it in place.
    applyRgb(cpu, lut.data(), lut.entryCount());
    return lut;
}

// Entries i = 0..n-1 over [lo, hi], what cpu computes at lo + (hi - lo) i / (n - 1).
Lut1D sampleCurves(const OCIO::ConstCPUProcessorRcPtr& cpu, int n, glm::vec3 lo, glm::vec3 hi) {
    Lut1D curve(n);
    if (lo != glm::vec3(0.0f) || hi != glm::vec3(1.0f))
        curve.setDomain(lo, hi);
    for (int i = 0; i < n; ++i)
        curve[i] = lo + (hi - lo) * (static_cast<float>(i) / static_cast<float>(n - 1));
    applyRgb(cpu, &curve.entries()[0].x, curve.entries().size());
    return curve;
}

Diagnostic note(const std::string& path, std::string message) {
    return ocioDiagnostic(path, std::move(message));
}

std::string errorText(const ErrorStats& e) {
    return "it differs from OpenColorIO's processor by " + e.str();
}

// A shaper that is a straight line from 0 at its first entry to 1 at its last, per channel (a
// .csp prelut that only sets the input range): the same as the cube over the shaper's domain.
bool isStraightRange(const Lut1D& sh) {
    const int n = sh.size();
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
            if (!(std::fabs(double(sh[i][c]) - double(i) / (n - 1)) <= 2e-6))
                return false;
    return true;
}

int clampedSize(unsigned long v, int fallback) {
    return v >= static_cast<unsigned long>(limits::kMin3DSize) &&
                   v <= static_cast<unsigned long>(limits::kMax3DSize)
               ? static_cast<int>(v)
               : fallback;
}

} // namespace

void sampleProcessor(const std::string& path, const OCIO::ConstProcessorRcPtr& processor,
                     const OcioStructure& s, const ProcessorFacts& facts, int size, LutFile& out) {
    using K = OcioStructure::Kind;
    const auto whole = cpuOf(processor);
    const RgbFunction truth = functionOf(whole);

    if (s.kind == K::Curves && size == 0) {
        out.shaper =
            sampleCurves(cpuOf(s.rest), static_cast<int>(s.length1d), s.domainMin, s.domainMax);
        out.shaper->setTitle(facts.title);
        return;
    }
    if (s.kind == K::Cube) {
        const int own = clampedSize(s.gridSize, kDefaultChainSize);
        const int n = size ? size : own;
        out.cube = sampleLattice(path, cpuOf(s.rest), n, s.domainMin, s.domainMax);
    } else if (s.kind == K::ShaperCube) {
        out.shaper =
            sampleCurves(cpuOf(s.shaper), static_cast<int>(s.length1d), s.domainMin, s.domainMax);
        const int own = clampedSize(s.gridSize, kDefaultChainSize);
        const int n = size ? size : own;
        out.cube = sampleLattice(path, cpuOf(s.rest), n, glm::vec3(0.0f), glm::vec3(1.0f));
        if (isStraightRange(*out.shaper)) {
            out.cube->setDomain(s.domainMin, s.domainMax);
            out.shaper.reset();
        }
    } else if (size == 0 && !processor->hasChannelCrosstalk()) {
        // Per-channel chain: a 1D table over [0,1] holds it far better than a lattice.
        const int n = std::max(
            kDefaultCurveLength,
            std::min(static_cast<int>(std::min<unsigned long>(facts.length1d, limits::kMax1DSize)),
                     limits::kMax1DSize));
        out.shaper = sampleCurves(whole, n, glm::vec3(0.0f), glm::vec3(1.0f));
        out.shaper->setTitle(facts.title);
        ProbeGrid grid;
        grid.perAxis = 4 * (n - 1) + 1;
        grid.greyOnly = true;
        const ErrorStats e = measureAgainst(LutFileFunction(out).function(), truth, grid);
        out.diagnostics.push_back(note(path, "sampled OpenColorIO's processor (" + facts.opsText() +
                                                 ") as a " + std::to_string(n) +
                                                 "-entry 1D table per channel over [0,1]; " +
                                                 errorText(e)));
        return;
    } else {
        const int n =
            size ? size
                 : std::max(kDefaultChainSize, clampedSize(facts.gridSize, kDefaultChainSize));
        out.cube = sampleLattice(path, whole, n, glm::vec3(0.0f), glm::vec3(1.0f));
    }
    out.cube->setTitle(facts.title);
    out.cube->comments() = facts.comments;

    // Exact: the file's own lattice holds the whole processor. Otherwise say what it cost.
    const bool exact = (s.kind == K::Cube || s.kind == K::ShaperCube) &&
                       out.cube->size() == clampedSize(s.gridSize, 0);
    if (exact)
        return;
    ProbeGrid grid;
    grid.perAxis = probesFor(out.cube->size());
    if (s.kind == K::ShaperCube) {
        // Probe where the lattice is: evenly in the cube's coordinates, mapped back through the
        // shaper's domain (its input range) linearly.
        grid.domainMin = s.domainMin;
        grid.domainMax = s.domainMax;
    } else {
        grid.domainMin = out.cube->domainMin();
        grid.domainMax = out.cube->domainMax();
    }
    const ErrorStats e = measureAgainst(LutFileFunction(out).function(), truth, grid);
    std::string what;
    if (s.kind == K::Cube || s.kind == K::ShaperCube)
        what = "the file's " + std::to_string(s.gridSize) +
               "^3 table resampled by "
               "OpenColorIO onto a " +
               std::to_string(out.cube->size()) + "^3 lattice";
    else
        what = "sampled OpenColorIO's processor (" + facts.opsText() + ") on a " +
               std::to_string(out.cube->size()) + "^3 lattice over [0,1]";
    out.diagnostics.push_back(note(path, what + "; " + errorText(e)));
}

void replaceNonFinite(const std::string& path, LutFile& file) {
    std::size_t nonFinite = 0;
    auto fix = [&](std::vector<glm::vec3>& entries) {
        for (auto& v : entries)
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(v[c])) {
                    v[c] = 0.0f;
                    ++nonFinite;
                }
    };
    if (file.cube)
        fix(file.cube->entries());
    if (file.shaper)
        fix(file.shaper->entries());
    if (nonFinite)
        file.diagnostics.push_back(
            ocioDiagnostic(path, std::to_string(nonFinite) + " NaN/Inf values replaced by 0",
                           Diagnostic::Severity::Warning));
}

} // namespace lut::formats
