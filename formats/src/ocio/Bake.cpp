// SPDX-License-Identifier: Apache-2.0
// lut::formats::bake: sample a colour conversion (a config's, LUT files' through OCIO, or a LUT
// with conversions around it) on a lattice, with a shaper when its input is HDR, write it in any
// format and measure the written file against the conversion (lut/formats/Bake.h).
#include "lut/formats/Bake.h"

#include "LutPrep.h"
#include "ocio/BakeSource.h"
#include "ocio/OcioMeasure.h"
#include "ocio/OcioSession.h"

#include "lut/Limits.h"
#include "lut/Math.h"
#include "lut/formats/Cube.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/io/FormatRegistry.h"
#include "lut/io/LutWriter.h"
#include "lut/ops/Lattice.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace lut::formats {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// ociobakelut's default lattice for a format (OpenColorIO 2.1's bakers, each format's
// DEFAULT_CUBE_SIZE in src/OpenColorIO/fileformats/FileFormat*.cpp), so `lutkit bake` and
// `ociobakelut` with the same --format write the same lattice: flame 17, lustre 33, cinespace,
// truelight and iridas_cube 32, resolve_cube, iridas_itx, houdini, CLF and CTF 64. A .cube named
// without a dialect (lutkit picks it), .spi3d (OCIO cannot bake it) and lutkit's own formats: 33.
// (Shapers stay at kDefaultShaperSize: lutkit's .csp prelut is its shaper's knots, not OCIO's
// 1024 samples, and Resolve's and CLF's 4096 are OCIO's 1D size too.)
int ociobakelutCubeSize(const Format& writer, const FormatOptions& write) {
    const std::string name = writer.name();
    if (name == "cube") {
        const auto dialect = write.attribute(kCubeDialectAttribute);
        return dialect == "resolve" ? 64 : dialect == "adobe" ? 32 : kDefaultBakeSize;
    }
    if (name == "flame")
        return 17;
    if (name == "csp" || name == "cub")
        return 32;
    if (name == "itx" || name == "houdini" || name == "clf" || name == "ctf")
        return 64;
    return kDefaultBakeSize; // lustre's 33 too
}

// A per-channel shaper: input -> [0,1] (forward) and back (inverse), over [lo, hi].
struct ShaperPlan {
    enum class Kind { None, Range, Curve } kind = Kind::None;
    RgbFunction forward, inverse;
    glm::vec3 lo{0.0f}, hi{1.0f};
    std::string text = "none";
};

ShaperPlan log2Shaper(const ColorSpaceInfo* input) {
    // OCIO's lg2 allocation: u = (log2(x + offset) - min) / (max - min).
    // Without an offset of its own, the curve is offset by 2^min so that it starts at input 0:
    // black keeps its value instead of being clamped to 2^min.
    double mn = -8.973931188, mx = 4.026068812;
    std::string from = "-6.5..+6.5 stops around 0.18";
    if (input && input->lg2Allocation && input->allocationVars.size() >= 2) {
        mn = input->allocationVars[0];
        mx = input->allocationVars[1];
        from = input->name + "'s lg2 allocation, " + num(mn) + ".." + num(mx) + " stops";
    }
    const double off = input && input->lg2Allocation && input->allocationVars.size() >= 3
                           ? input->allocationVars[2]
                           : lut::math::exp2(mn);
    ShaperPlan p;
    p.kind = ShaperPlan::Kind::Curve;
    p.forward = [mn, mx, off](float* rgb, std::size_t n) {
        for (std::size_t i = 0; i < 3 * n; ++i) {
            const double x = std::max(double(rgb[i]) + off, 1e-30);
            rgb[i] = static_cast<float>((lut::math::log2(x) - mn) / (mx - mn));
        }
    };
    p.inverse = [mn, mx, off](float* rgb, std::size_t n) {
        for (std::size_t i = 0; i < 3 * n; ++i)
            rgb[i] = static_cast<float>(lut::math::exp2(mn + double(rgb[i]) * (mx - mn)) - off);
    };
    p.lo = glm::vec3(static_cast<float>(lut::math::exp2(mn) - off));
    p.hi = glm::vec3(static_cast<float>(lut::math::exp2(mx) - off));
    p.text = "log2 (" + from + ": " + num(p.lo.x) + ".." + num(p.hi.x) + ")";
    return p;
}

ShaperPlan spaceShaper(const ColorConfig& config, const std::string& input,
                       const std::string& shaperSpace) {
    const auto fwd = ColorTransform::convert(config, input, shaperSpace);
    if (fwd->hasChannelCrosstalk())
        throw ColorOptionError("the shaper space '" + shaperSpace + "' mixes channels (from '" +
                               config.colorSpace(input) +
                               "'): a shaper must work on each channel alone; pick another "
                               "--shaperspace or leave it out");
    const auto inv = ColorTransform::convert(config, shaperSpace, input);
    ShaperPlan p;
    p.kind = ShaperPlan::Kind::Curve;
    p.forward = [fwd](float* rgb, std::size_t n) { fwd->processRgb(rgb, n); };
    p.inverse = [inv](float* rgb, std::size_t n) { inv->processRgb(rgb, n); };
    float ends[6] = {0, 0, 0, 1, 1, 1};
    inv->processRgb(ends, 2);
    p.lo = glm::vec3(ends[0], ends[1], ends[2]);
    p.hi = glm::vec3(ends[3], ends[4], ends[5]);
    for (int c = 0; c < 3; ++c)
        if (!(p.lo[c] < p.hi[c]) || !std::isfinite(p.lo[c]) || !std::isfinite(p.hi[c]))
            throw ColorOptionError("the shaper space '" + shaperSpace +
                                   "' does not map 0..1 to an increasing input range of '" +
                                   config.colorSpace(input) + "'");
    p.text = "colour space '" + config.colorSpace(shaperSpace) + "' (" + num(p.lo.x) + ".." +
             num(p.hi.x) + ")";
    return p;
}

ShaperPlan rangeShaper(glm::vec3 lo, glm::vec3 hi) {
    ShaperPlan p;
    p.kind = ShaperPlan::Kind::Range;
    p.lo = lo;
    p.hi = hi;
    p.text = "input range " + num(lo.x) + ".." + num(hi.x);
    return p;
}

std::size_t replaceNonFiniteEntries(std::vector<glm::vec3>& entries) {
    std::size_t n = 0;
    for (auto& v : entries)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(v[c])) {
                v[c] = 0.0f;
                ++n;
            }
    return n;
}

Diagnostic diag(const std::string& path, std::string message,
                Diagnostic::Severity s = Diagnostic::Severity::Info) {
    return ocioDiagnostic(path, std::move(message), s);
}

// Points at which a bake's error is measured: about 1M, a few tenths of a second of
// OpenColorIO's processor for a config's conversion.
constexpr std::size_t kBakeBoundPoints = 1'100'000;

// Writes the file, reads it back and measures it against the function, probes spread like the
// lattice (through the shaper's inverse when there is one).
void finishBake(const std::string& output, const BakeOptions& o, const Format& writer,
                const LutFile& file, const BakeSource& source, const RgbFunction* shaperInverse,
                BakeReport& report) {
    FormatOptions w = o.write;
    w.size = file.cube ? file.cube->size() : 0;
    if (!o.format.empty())
        FormatRegistry::instance().applyAlias(o.format, w);
    const auto t0 = Clock::now();
    // "-" and special files in place (the bytes kept to read back), regular files atomically.
    std::string inPlaceBytes;
    const Diagnostics wd = writeLutFile(writer, output, file, w, &inPlaceBytes);
    report.writeSeconds = since(t0);
    report.diagnostics.insert(report.diagnostics.end(), wd.begin(), wd.end());

    // The bound: held-out points between the lattice points (in the coordinates the lattice is
    // uniform in: through the shaper's inverse when there is one) plus the slope between them.
    ProbeGrid grid;
    if (!file.cube) {
        grid.greyOnly = true;
        grid.cells = file.shaper->size() - 1;
    } else {
        grid.cells = file.cube->size() - 1;
    }
    grid.budget = kBakeBoundPoints;
    if (shaperInverse) {
        grid.toInput = *shaperInverse;
    } else {
        grid.domainMin = report.domainMin;
        grid.domainMax = report.domainMax;
        // the source file's kinks, where the grid is linear in the input
        // (a 3D table of a 3D source: a 1D bake's grey-axis grid is fine already)
        if (source.kinksOf && source.kinksOf->cube && file.cube) {
            const Breaks k = fileBreaks(*source.kinksOf, report.domainMin, report.domainMax);
            for (int a = 0; a < 3; ++a)
                for (const double x : k[static_cast<std::size_t>(a)])
                    grid.breaks[static_cast<std::size_t>(a)].push_back(
                        (x - report.domainMin[a]) /
                        (double(report.domainMax[a]) - report.domainMin[a]));
        }
    }
    LutFile measured = file;
    try {
        FormatOptions back;
        back.layout = o.write.layout;
        measured = inPlaceBytes.empty() ? readLut(output, back)
                                        : writer.readMemory(inPlaceBytes, output, back);
        report.measuredFile = true;
    } catch (const Error& e) {
        report.readBackError = e.what();
    }
    report.error =
        measureAgainst(LutFileFunction(measured).function(), source.truth, grid, o.nthreads);
}

} // namespace

BakeReport bake(const std::string& output, const BakeOptions& o) {
    const auto tStart = Clock::now();
    registerBuiltinFormats();
    auto& registry = FormatRegistry::instance();
    if (!o.format.empty() && !registry.byName(o.format))
        throw ColorOptionError("unknown format '" + o.format + "'", "output format", o.format);
    // Where the bake goes (lut/formats/LutDestination.h): the writer of --format or of the
    // output's extension. A bake says nothing of what it is for.
    const LutDestination dest =
        resolveLutDestination({output, o.format, std::nullopt, o.cubeSize, o.write.layout, 0});
    const Format* writer = &dest.requireWriter();
    if (o.cubeSize != 0 && (o.cubeSize < limits::kMin3DSize || o.cubeSize > limits::kMax3DSize))
        throw ColorOptionError("cube size " + std::to_string(o.cubeSize) + " is outside " +
                               std::to_string(limits::kMin3DSize) + ".." +
                               std::to_string(limits::kMax3DSize));
    if (o.shaperSize != 0 &&
        (o.shaperSize < limits::kMin1DSize || o.shaperSize > limits::kMax1DSize))
        throw ColorOptionError("shaper size " + std::to_string(o.shaperSize) + " is outside " +
                               std::to_string(limits::kMin1DSize) + ".." +
                               std::to_string(limits::kMax1DSize));

    BakeReport report;
    report.outputFormat = writer->name();
    BakeSource source = makeBakeSource(o, output);
    report.what = source.what;
    report.configUsed = source.configUsed;
    report.diagnostics = source.diagnostics;

    FormatOptions named = o.write; // with the dialect --format names (resolve_cube ...)
    if (!o.format.empty())
        registry.applyAlias(o.format, named);
    // A shaper in the file (the Adobe .cube dialect bakes it in).
    const bool keepsShaper =
        writer->holdsShaper() && named.attribute(kCubeDialectAttribute) != "adobe";

    // The shaper.
    ShaperPlan shaper;
    const bool hdr = source.inputInfo && source.inputInfo->isHdrLinear();
    if (!o.shaperSpace.empty()) {
        if (!source.config || source.inputSpace.empty())
            throw ColorOptionError(
                "--shaperspace needs a colour space to start from (--inputspace, "
                "or --from with a LUT)");
        shaper = spaceShaper(*source.config, source.inputSpace, o.shaperSpace);
    } else if (o.shaper == ShaperChoice::Log2) {
        shaper = log2Shaper(source.inputInfo ? &*source.inputInfo : nullptr);
    } else if (o.shaper == ShaperChoice::Auto) {
        if (hdr && writer->holdsShaper())
            shaper = log2Shaper(&*source.inputInfo);
        else if (source.ownRange && source.shaped &&
                 samplesDisplayRange(source.ownRange->first, source.ownRange->second))
            // A shaper + table becomes one table over 0..1, as convert writes it where the
            // format holds no shaper (LutPrep.h's rule): over the shaper's own 0..64 inputs in
            // 0..1 fell in the first cells (off by 100+ 8-bit steps).
            report.diagnostics.push_back(diag(
                output,
                "the source's 1D shaper and 3D table sampled at one table " +
                    std::string(kDisplayRangeWords) + ": inputs outside 0..1 of its shaper's " +
                    num(source.ownRange->first.x) + ".." + num(source.ownRange->second.x) +
                    " take the edge value (" +
                    (keepsShaper
                         ? std::string("--shaper log2 keeps inputs up to 16 in a log2 shaper")
                         : std::string("a Resolve .cube, .clf or .ctf with --shaper log2 keeps "
                                       "inputs up to 16 in a log2 shaper")) +
                    "; lutkit convert keeps the source's own shaper)",
                Diagnostic::Severity::Warning));
        else if (source.ownRange && writer->holdsShaper())
            shaper = rangeShaper(source.ownRange->first, source.ownRange->second);
        else if (hdr)
            report.diagnostics.push_back(
                diag(output,
                     "'" + source.inputInfo->name + "' is scene-linear, but " + writer->name() +
                         " holds no shaper: the table covers inputs 0..1 only and clamps the rest "
                         "(write .cube, .clf, .ctf or .csp to keep them, or name --shaperspace)",
                     Diagnostic::Severity::Warning));
        else if (source.ownRange)
            report.diagnostics.push_back(
                diag(output,
                     "the source's input range " + num(source.ownRange->first.x) + ".." +
                         num(source.ownRange->second.x) +
                         " is sampled over 0..1: " + writer->name() + " holds no input range",
                     Diagnostic::Severity::Warning));
    }
    report.shaper = shaper.text;
    const int fixed = writer->fixedSizeFor(o.write);
    const int n = o.cubeSize ? o.cubeSize : (fixed ? fixed : ociobakelutCubeSize(*writer, named));
    report.cubeSize = n;

    // A conversion that mixes no channels is per-channel curves: a 1D table holds it exactly at
    // its entries (as ociobakelut writes it), where the format holds one.
    const bool curvesOnly = !source.crosstalk && o.cubeSize == 0 &&
                            o.shaper == ShaperChoice::Auto && o.shaperSpace.empty() &&
                            shaper.kind != ShaperPlan::Kind::Curve && writer->holdsShaper();
    auto t0 = Clock::now();
    LutFile file;
    file.format = writer->name();
    if (curvesOnly) {
        const int ns = o.shaperSize ? o.shaperSize : kDefaultShaperSize;
        Lut1D curves(ns);
        if (shaper.kind == ShaperPlan::Kind::Range)
            curves.setDomain(shaper.lo, shaper.hi);
        for (int i = 0; i < ns; ++i)
            curves[i] = curves.domainMin() + (curves.domainMax() - curves.domainMin()) *
                                                 (static_cast<float>(i) / (ns - 1));
        source.truth(&curves.entries()[0].x, curves.entries().size());
        if (const std::size_t bad = replaceNonFiniteEntries(curves.entries()))
            report.diagnostics.push_back(diag(
                output, std::to_string(bad) + " NaN/Inf values of the conversion replaced by 0",
                Diagnostic::Severity::Warning));
        curves.setTitle(source.what);
        report.cubeSize = 0;
        report.shaperSize = ns;
        report.shaper = "1D table per channel (the conversion mixes no channels)";
        report.domainMin = curves.domainMin();
        report.domainMax = curves.domainMax();
        file.shaper = std::move(curves);
        report.sampleSeconds = since(t0);
        finishBake(output, o, *writer, file, source, nullptr, report);
        report.totalSeconds = since(tStart);
        return report;
    }
    Lut3D cube(n);
    if (shaper.kind == ShaperPlan::Kind::Range)
        cube.setDomain(shaper.lo, shaper.hi);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                cube.at(r, g, b) = cube.latticeInput(r, g, b);
    if (shaper.kind == ShaperPlan::Kind::Curve) {
        const int ns = o.shaperSize ? o.shaperSize : kDefaultShaperSize;
        Lut1D sh(ns);
        sh.setDomain(shaper.lo, shaper.hi);
        for (int i = 0; i < ns; ++i)
            sh[i] = shaper.lo + (shaper.hi - shaper.lo) * (static_cast<float>(i) / (ns - 1));
        shaper.forward(&sh.entries()[0].x, sh.entries().size());
        report.shaperSize = ns;
        file.shaper = std::move(sh);
        shaper.inverse(cube.data(), cube.entryCount());
        report.domainMin = shaper.lo;
        report.domainMax = shaper.hi;
    } else {
        report.domainMin = cube.domainMin();
        report.domainMax = cube.domainMax();
    }
    source.truth(cube.data(), cube.entryCount());
    std::size_t nonFinite = replaceNonFiniteEntries(cube.entries());
    if (file.shaper)
        nonFinite += replaceNonFiniteEntries(file.shaper->entries());
    if (nonFinite)
        report.diagnostics.push_back(diag(
            output, std::to_string(nonFinite) + " NaN/Inf values of the conversion replaced by 0",
            Diagnostic::Severity::Warning));
    // A comment, not a title: OpenColorIO 2.1 refuses TITLE in a Resolve .cube (the dialect that
    // keeps a shaper or an input range).
    cube.comments().push_back("lutkit bake: " + source.what);
    file.cube = std::move(cube);
    report.sampleSeconds = since(t0);

    finishBake(output, o, *writer, file, source,
               shaper.kind == ShaperPlan::Kind::Curve ? &shaper.inverse : nullptr, report);
    report.totalSeconds = since(tStart);
    return report;
}

} // namespace lut::formats
