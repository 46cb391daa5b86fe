// SPDX-License-Identifier: Apache-2.0
// Baking a transfer into a LUT file, and matchLook's measurements: see lut/match/Match.h.
#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/match/Match.h"
#include "lut/match/MatchFinish.h"
#include "lut/match/WorkingSpace.h"
#include "match/MatchColours.h"
#include "match/MatchContext.h"
#include "match/MatchSamples.h"
#include "match/ShapeRepair.h"
#include "match/TableFit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

namespace lut {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Whether the shaper's knots all fall on 4 entries per 8-bit code (display data whose curves
// were built on code bins): then 1021 entries hold the curves exactly.
bool codeAlignedShaper(const MatchTransfer& t) {
    if (t.linear || t.domainMin != glm::dvec3(0.0) || t.domainMax != glm::dvec3(1.0))
        return false;
    for (const auto& c : t.pre) {
        if (c.empty())
            continue;
        const double k0 = (c.x0() + 0.5 / 255.0) * 255.0, steps = c.step() * 255.0;
        if (std::fabs(k0 - std::round(k0)) > 1e-6 || std::fabs(steps - 1.0) > 1e-9)
            return false;
    }
    return true;
}

// Radix sort of 24-bit keys (three passes of 8 bits).
void sortKeys(std::vector<std::uint32_t>& keys) {
    std::vector<std::uint32_t> tmp(keys.size());
    for (int shift = 0; shift < 24; shift += 8) {
        std::size_t count[257] = {};
        for (std::uint32_t k : keys)
            ++count[((k >> shift) & 255u) + 1];
        for (int i = 0; i < 256; ++i)
            count[i + 1] += count[i];
        for (std::uint32_t k : keys)
            tmp[count[(k >> shift) & 255u]++] = k;
        keys.swap(tmp);
    }
}

// The distinct stored colours of a sample set and how many samples hold each.
void distinctColours(const detail::SampleSet& set, bool linear, std::vector<glm::vec3>& colours,
                     std::vector<std::uint32_t>& counts) {
    colours.clear();
    counts.clear();
    if (set.codeAligned) {
        std::vector<std::uint32_t> keys(set.values.size());
        for (std::size_t i = 0; i < keys.size(); ++i) {
            std::uint32_t key = 0;
            for (int c = 0; c < 3; ++c)
                key = key << 8 | static_cast<std::uint32_t>(
                                     std::clamp(std::lround(set.values[i][c] * 255.0f), 0L, 255L));
            keys[i] = key;
        }
        sortKeys(keys);
        for (std::size_t i = 0; i < keys.size();) {
            std::size_t j = i;
            while (j < keys.size() && keys[j] == keys[i])
                ++j;
            const std::uint32_t k = keys[i];
            colours.emplace_back(static_cast<float>((k >> 16) & 255u) / 255.0f,
                                 static_cast<float>((k >> 8) & 255u) / 255.0f,
                                 static_cast<float>(k & 255u) / 255.0f);
            counts.push_back(static_cast<std::uint32_t>(j - i));
            i = j;
        }
        return;
    }
    colours.resize(set.values.size());
    counts.assign(set.values.size(), 1);
    for (std::size_t i = 0; i < set.values.size(); ++i)
        for (int c = 0; c < 3; ++c)
            colours[i][c] = static_cast<float>(decodeWorking(set.values[i][c], linear));
}

// A LUT file on colours, in chunks on all threads.
std::vector<glm::vec3> applyLut(const LutFileSampler& sampler, const std::vector<glm::vec3>& in,
                                int nthreads) {
    std::vector<glm::vec3> out(in.size());
    constexpr std::size_t kChunk = 4096;
    parallelForDynamic(
        static_cast<int>((in.size() + kChunk - 1) / kChunk), nthreads, 1, [&](int a, int b) {
            std::vector<float> rgba(4 * kChunk);
            for (int k = a; k < b; ++k) {
                const std::size_t first = static_cast<std::size_t>(k) * kChunk;
                const std::size_t n = std::min(kChunk, in.size() - first);
                for (std::size_t i = 0; i < n; ++i) {
                    rgba[4 * i] = in[first + i].x;
                    rgba[4 * i + 1] = in[first + i].y;
                    rgba[4 * i + 2] = in[first + i].z;
                    rgba[4 * i + 3] = 1.0f;
                }
                sampler.applyPixels(rgba.data(), n);
                for (std::size_t i = 0; i < n; ++i)
                    out[first + i] = glm::vec3(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
            }
        });
    return out;
}

} // namespace

LutFile bakeMatch(const MatchTransfer& t, const MatchOptions& o) {
    if (o.size < 2 || o.size > 129)
        throw Error("match: the LUT size must be 2..129, not " + std::to_string(o.size));
    const MatchFinish finish = MatchFinish::fromOptions(o, t.linear);
    finish.check();
    LutFile file;
    if (finish.isNeutral()) { // strength 0: the neutral LUT over the domain, to the bit
        const double a = std::min({t.domainMin.x, t.domainMin.y, t.domainMin.z});
        const double b = std::max({t.domainMax.x, t.domainMax.y, t.domainMax.z});
        Lut3D id = Lut3D::identity(o.size);
        if (a != 0.0 || b != 1.0) {
            id.setDomain(glm::vec3(static_cast<float>(a)), glm::vec3(static_cast<float>(b)));
            const int n = o.size;
            for (int bb = 0; bb < n; ++bb)
                for (int g = 0; g < n; ++g)
                    for (int r = 0; r < n; ++r)
                        id.at(r, g, bb) = id.latticeInput(r, g, bb);
        }
        id.setTitle("lutkit match (strength 0)");
        file.cube = std::move(id);
        file.format = "match";
        return file;
    }
    // One domain for every channel (formats such as Resolve's .cube have one input range): the
    // shaper covers the widest channel's range and maps each channel's u onto [0, 1], the
    // table's domain.
    glm::dvec3 uMin = t.domainMin, uMax = t.domainMax;
    const double lo = std::min({t.domainMin.x, t.domainMin.y, t.domainMin.z});
    const double hi = std::max({t.domainMax.x, t.domainMax.y, t.domainMax.z});
    const bool useShaper = t.hasShaper() && o.form != MatchLutForm::Table;
    if (useShaper) {
        const int n = codeAlignedShaper(t) ? 1021 : 4096;
        Lut1D shaper(n);
        shaper.setDomain(glm::vec3(static_cast<float>(lo)), glm::vec3(static_cast<float>(hi)));
        const double a = shaper.domainMin().x, b = shaper.domainMax().x;
        uMin = t.toLattice(glm::dvec3(a));
        uMax = t.toLattice(glm::dvec3(b));
        for (int c = 0; c < 3; ++c)
            if (!(uMax[c] > uMin[c])) // cannot happen for increasing curves; keep it valid
                uMax[c] = uMin[c] + 1e-6;
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 u =
                t.toLattice(glm::dvec3(a + (b - a) * (static_cast<double>(i) / (n - 1))));
            shaper[i] = glm::vec3((u - uMin) / (uMax - uMin));
        }
        file.shaper = std::move(shaper);
    }
    const bool normalised = useShaper;
    Lut3D cube(o.size);
    if (!normalised)
        cube.setDomain(glm::vec3(static_cast<float>(lo)), glm::vec3(static_cast<float>(hi)));
    const int n = o.size;
    const glm::dvec3 cubeLo(cube.domainMin()), cubeHi(cube.domainMax());
    parallelFor(n, o.nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::dvec3 s = cubeLo + (cubeHi - cubeLo) * (glm::dvec3(r, g, b) /
                                                                       static_cast<double>(n - 1));
                    // With a shaper the table's input is u; alone, the stored value x.
                    const glm::dvec3 u = normalised ? uMin + (uMax - uMin) * s : t.toLattice(s);
                    const glm::dvec3 y = t.latticeOutput(u);
                    const glm::dvec3 e =
                        finish.isIdentity() ? y : finish(normalised ? t.fromLattice(u) : s, y);
                    cube.at(r, g, b) = glm::vec3(e);
                }
    });
    // A title only on a plain table: .cube files with a shaper are Resolve's dialect, whose
    // OpenColorIO reader refuses a TITLE line (Nuke, Blender and ociochecklut read them so).
    if (!file.shaper)
        cube.setTitle(std::string("lutkit match (") + toString(t.method) + ")");
    file.cube = std::move(cube);
    file.format = "match";
    return file;
}

MatchResult matchLook(const MatchPicture& source, const std::vector<MatchPicture>& references,
                      const MatchOptions& o) {
    detail::MatchContext context;
    MatchFitResult fit = detail::fitMatch(source, references, o, &context);
    MatchResult res;
    res.transfer = std::move(fit.transfer);
    res.report = std::move(fit.report);
    res.diagnostics = std::move(fit.diagnostics);
    MatchReport& rep = res.report;
    const MatchTransfer& t = res.transfer;
    const bool linear = t.linear;

    auto start = Clock::now();
    // Auto: the shaper form when the transfer has curves, and the table alone to compare.
    MatchOptions shaperOptions = o;
    if (o.form == MatchLutForm::Auto)
        shaperOptions.form = MatchLutForm::ShaperTable;
    res.lut = bakeMatch(t, shaperOptions);
    std::optional<LutFile> tableAlone;
    if (o.form == MatchLutForm::Auto && res.lut.shaper) {
        MatchOptions q = o;
        q.form = MatchLutForm::Table;
        tableAlone = bakeMatch(t, q);
    }
    rep.secondsBake = secondsSince(start);

    start = Clock::now();
    const MatchFinish finish = MatchFinish::fromOptions(o, linear);
    const detail::SampleSet& src = context.source;
    // Every distinct colour once, with how many pixels hold it (8-bit codes are exact keys;
    // other values are taken one by one).
    std::vector<glm::vec3> colours;
    std::vector<std::uint32_t> counts;
    distinctColours(src, linear, colours, counts);
    rep.interpolationColours = colours.size();
    std::vector<glm::dvec3> wanted(colours.size());
    parallelFor(static_cast<int>(colours.size()), o.nthreads, [&](int a, int b) {
        for (int i = a; i < b; ++i) {
            const glm::dvec3 x(colours[static_cast<std::size_t>(i)]);
            const glm::dvec3 y = t(x);
            wanted[static_cast<std::size_t>(i)] = finish.isIdentity() ? y : finish(x, y);
        }
    });

    // A LUT file on those colours, against the transfer.
    auto measure = [&](const LutFile& lut, std::vector<glm::vec3>& got) {
        const LutFileSampler sampler(lut, Interpolation::Tetrahedral);
        got = applyLut(sampler, colours, o.nthreads);
        std::vector<double> steps(colours.size() * 3);
        parallelFor(static_cast<int>(colours.size()), o.nthreads, [&](int a, int b) {
            for (int i = a; i < b; ++i) {
                const std::size_t k = static_cast<std::size_t>(i);
                for (int c = 0; c < 3; ++c) {
                    const double d =
                        encodeWorking(got[k][c], linear) - encodeWorking(wanted[k][c], linear);
                    steps[3 * k + static_cast<std::size_t>(c)] =
                        std::isfinite(d) ? std::fabs(d) * 255.0 : INFINITY;
                }
            }
        });
        return summariseSteps(steps);
    };
    std::vector<glm::vec3> got;
    rep.interpolation = measure(res.lut, got);
    rep.shaper = res.lut.shaper.has_value();
    if (tableAlone) {
        // The table alone unless the look needs the shaper to be held (MatchOptions.h).
        std::vector<glm::vec3> gotTable;
        const GameError e = measure(*tableAlone, gotTable);
        rep.bothForms = true;
        rep.shaperError = rep.interpolation;
        rep.tableAloneError = e;
        // A scene-linear source keeps its shaper: it carries the ACEScct curve and the range.
        if (!linear && e.p99Steps <= 8.0 && e.meanSteps <= 1.0) {
            res.lut = std::move(*tableAlone);
            got = std::move(gotTable);
            rep.interpolation = e;
            rep.shaper = false;
        }
    }
    // A look with steps: the table's values fitted over the source's colours, so each step
    // falls where the pixels put it rather than across a whole cell (match/TableFit.h).
    if (t.method == MatchMethod::GradientMap && !res.lut.shaper && res.lut.cube) {
        detail::fitTableToColours(*res.lut.cube, colours, counts, wanted);
        rep.interpolation = measure(res.lut, got);
        rep.tableFitted = true;
    }
    // A dip along grey is repaired on the table, not a reason to fall back (match/ShapeRepair.h):
    // the table alone over one domain for the three channels, where grey is its diagonal. A
    // gradient map is a colour per luma, its table fitted over the source's colours: left as is.
    if (t.method != MatchMethod::GradientMap && !res.lut.shaper && res.lut.cube &&
        res.lut.cube->domainMin() == glm::vec3(res.lut.cube->domainMin().x) &&
        res.lut.cube->domainMax() == glm::vec3(res.lut.cube->domainMax().x)) {
        const LutQuality before = measureLutQuality(res.lut, linear, t.domainMin, t.domainMax);
        if (before.largestGreyDrop > 0.0) {
            const detail::GreyRepair g = detail::repairGreyDip(*res.lut.cube);
            if (g.nodesMoved > 0) {
                rep.greyDipRepaired = before.largestGreyDrop;
                rep.greyNodesMoved = g.nodesMoved;
                rep.greyLargestMove = g.largestMove;
                rep.interpolation = measure(res.lut, got);
            }
        }
    }
    const LutFileSampler sampler(res.lut, Interpolation::Tetrahedral);

    // What the LUT clips, per pixel: display values beyond half an 8-bit step outside [0, 1]
    // (closer ones round to 0 or 255 as they are), scene-linear values below -0.5/255.
    const double loLimit = -0.5 / 255.0;
    const double hiLimit = linear ? INFINITY : 1.0 + 0.5 / 255.0;
    for (std::size_t i = 0; i < colours.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = got[i][c];
            rep.values += counts[i];
            if (v < loLimit || v > hiLimit) {
                rep.clippedValues += counts[i];
                rep.clippedMaxSteps =
                    std::max(rep.clippedMaxSteps, (v < 0.0 ? -v : v - 1.0) * 255.0);
            }
        }
    for (const auto& e : res.lut.cube->entries())
        for (int c = 0; c < 3; ++c) {
            ++rep.tableValues;
            if (e[c] < loLimit || e[c] > hiLimit)
                ++rep.tableValuesOutside;
        }
    if (rep.clippedValues > 0) {
        Diagnostic w;
        w.severity = Diagnostic::Severity::Warning;
        w.path = source.name;
        char buf[300];
        std::snprintf(buf, sizeof buf,
                      "the LUT takes %.3g%% of the picture's channel values %s (up to %.3g 8-bit "
                      "steps beyond): an 8-bit output clips them",
                      100.0 * static_cast<double>(rep.clippedValues) /
                          static_cast<double>(std::max<std::size_t>(rep.values, 1)),
                      linear ? "below 0" : "outside [0, 1]", rep.clippedMaxSteps);
        w.message = buf;
        res.diagnostics.push_back(std::move(w));
    }

    // After: the LUT's result on SOURCE vs REFERENCE (the same subsample as before).
    const detail::SampleSet thin = detail::thinSamples(src, 1 << 15);
    std::vector<glm::vec3> thinStored(thin.values.size());
    for (std::size_t i = 0; i < thin.values.size(); ++i)
        for (int c = 0; c < 3; ++c)
            thinStored[i][c] = static_cast<float>(decodeWorking(thin.values[i][c], linear));
    rep.after = distributionDistance(
        ColourDistribution(
            detail::labOfStored(applyLut(sampler, thinStored, o.nthreads), linear, o.nthreads),
            thin.weights, o.nthreads),
        context.reference);
    rep.quality = measureLutQuality(res.lut, linear, t.domainMin, t.domainMax);
    rep.secondsMeasure = secondsSince(start);
    return res;
}

} // namespace lut
