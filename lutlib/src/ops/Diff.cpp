// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Diff.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ColorDifference.h"
#include "lut/ops/ErrorBound.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>

namespace lut {

namespace {

struct RegionAcc {
    std::size_t count = 0;
    double sum = 0.0;
    double max = -1.0;
    glm::dvec3 maxSteps{0.0};
    glm::vec3 worst{0.0f};
};

struct Acc {
    std::size_t count = 0;
    glm::dvec3 sumSteps{0.0};
    glm::dvec3 maxSteps{0.0};
    double sumDe = 0.0;
    DiffPoint worst{{}, {}, {}, -1.0};
    std::array<RegionAcc, kRegionCount> regions{};

    void add(glm::vec3 in, glm::vec3 a, glm::vec3 b, double de) {
        ++count;
        const glm::dvec3 steps = glm::abs(glm::dvec3(a) - glm::dvec3(b)) * 255.0;
        sumSteps += steps;
        maxSteps = glm::max(maxSteps, steps);
        sumDe += de;
        if (de > worst.deltaE)
            worst = {in, a, b, de};
        const RegionOf r = classifyRegion(in);
        for (Region reg : {r.tone, r.hue}) {
            RegionAcc& ra = regions[static_cast<std::size_t>(reg)];
            ++ra.count;
            ra.sum += de;
            ra.maxSteps = glm::max(ra.maxSteps, steps);
            if (de > ra.max) {
                ra.max = de;
                ra.worst = in;
            }
        }
    }
    void merge(const Acc& o) {
        count += o.count;
        sumSteps += o.sumSteps;
        maxSteps = glm::max(maxSteps, o.maxSteps);
        sumDe += o.sumDe;
        if (o.worst.deltaE > worst.deltaE)
            worst = o.worst;
        for (std::size_t i = 0; i < regions.size(); ++i) {
            RegionAcc& r = regions[i];
            const RegionAcc& q = o.regions[i];
            r.count += q.count;
            r.sum += q.sum;
            r.maxSteps = glm::max(r.maxSteps, q.maxSteps);
            if (q.max > r.max) {
                r.max = q.max;
                r.worst = q.worst;
            }
        }
    }
};

// fn(i, input, a, b) fills in colour i of `count`; the rest is the same for every kind of diff.
using PointFn = std::function<void(std::size_t i, glm::vec3& in, glm::vec3& a, glm::vec3& b)>;

DiffReport runDiff(std::size_t count, int nthreads, const Progress* progress, const PointFn& fn) {
    if (count > static_cast<std::size_t>(INT32_MAX))
        throw Error("diff: too many colours to compare");
    std::vector<float> deltaEs(count);
    std::mutex mutex;
    Acc total;
    std::atomic<std::size_t> done{0};
    constexpr int kBlock = 4096; // colours between two progress reports and cancel checks
    parallelFor(static_cast<int>(count), count < 4096 ? 1 : nthreads, [&](int begin, int end) {
        Acc acc;
        for (int b0 = begin; b0 < end; b0 += kBlock) {
            checkCancelled(progress, "diff");
            const int b1 = std::min(end, b0 + kBlock);
            for (int i = b0; i < b1; ++i) {
                glm::vec3 in, a, b;
                fn(static_cast<std::size_t>(i), in, a, b);
                const double de = (a == b) ? 0.0 : deltaE2000(srgbToLab(a), srgbToLab(b));
                deltaEs[static_cast<std::size_t>(i)] = static_cast<float>(de);
                acc.add(in, a, b, de);
            }
            if (progress)
                progress->report(static_cast<double>(done += static_cast<std::size_t>(b1 - b0)) /
                                 static_cast<double>(count));
        }
        std::lock_guard lock(mutex);
        total.merge(acc);
    });
    DiffReport r;
    r.count = total.count;
    if (total.count == 0)
        return r;
    const double n = static_cast<double>(total.count);
    r.maxSteps8 = total.maxSteps;
    r.meanSteps8 = total.sumSteps / n;
    r.meanDeltaE = total.sumDe / n;
    r.worst = total.worst;
    r.maxDeltaE = total.worst.deltaE;
    const std::size_t k = std::min(count - 1, static_cast<std::size_t>(std::ceil(0.95 * n)) - 1);
    std::nth_element(deltaEs.begin(), deltaEs.begin() + static_cast<std::ptrdiff_t>(k),
                     deltaEs.end());
    r.p95DeltaE = deltaEs[k];
    for (std::size_t i = 0; i < r.regions.size(); ++i) {
        const RegionAcc& a = total.regions[i];
        RegionDiff& d = r.regions[i];
        d.region = static_cast<Region>(i);
        d.count = a.count;
        if (a.count) {
            d.meanDeltaE = a.sum / static_cast<double>(a.count);
            d.maxDeltaE = a.max;
            d.maxSteps8 = a.maxSteps;
            d.worstInput = a.worst;
        }
    }
    return r;
}

// The input at entry i of a lattice (the storage order of lut/Lut3D.h: red fastest).
glm::vec3 latticeInputAt(const Lut3D& lattice, std::size_t i) {
    const std::size_t n = static_cast<std::size_t>(lattice.size());
    return lattice.latticeInput(static_cast<int>(i % n), static_cast<int>((i / n) % n),
                                static_cast<int>(i / (n * n)));
}

struct Prepared {
    Lut3D a, b;
    std::size_t replacedA = 0, replacedB = 0;
};

Prepared prepare(const Lut3D& a, const Lut3D& b) {
    if (a.empty() || b.empty())
        throw Error("diff: both LUTs must have entries");
    Prepared p;
    p.a = detail::sanitizedCopy(a, p.replacedA);
    p.b = detail::sanitizedCopy(b, p.replacedB);
    return p;
}

DiffReport finish(DiffReport r, const Prepared& p, long long t0) {
    r.sanitizedEntriesA = p.replacedA;
    r.sanitizedEntriesB = p.replacedB;
    r.seconds = detail::secondsSince(t0);
    for (auto& reg : r.regions)
        reg.region = static_cast<Region>(&reg - r.regions.data());
    return r;
}

} // namespace

std::vector<RegionDiff> DiffReport::rankedRegions() const {
    std::vector<RegionDiff> out;
    for (const auto& r : regions)
        if (r.count)
            out.push_back(r);
    std::stable_sort(out.begin(), out.end(), [](const RegionDiff& x, const RegionDiff& y) {
        if (x.meanDeltaE != y.meanDeltaE)
            return x.meanDeltaE > y.meanDeltaE;
        return x.maxDeltaE > y.maxDeltaE;
    });
    return out;
}

DiffReport diffLuts(const Lut3D& a, const Lut3D& b, const DiffOptions& options) {
    const long long t0 = detail::nowNanos();
    const Prepared p = prepare(a, b);
    const int size = options.size > 0 ? options.size : std::max(a.size(), b.size());
    const Lut3D lattice(size); // validates the size; its entries are unused
    const bool direct = size == a.size() && size == b.size() && a.domainMin() == b.domainMin() &&
                        a.domainMax() == b.domainMax();
    const auto count = lattice.entryCount();
    if (direct) {
        DiffReport r =
            finish(runDiff(count, options.nthreads, options.progress,
                           [&](std::size_t i, glm::vec3& in, glm::vec3& va, glm::vec3& vb) {
                               in = latticeInputAt(a, i);
                               va = p.a.entries()[i];
                               vb = p.b.entries()[i];
                           }),
                   p, t0);
        r.maxEveryInput = true; // see DiffReport::maxEveryInput
        return r;
    }
    Lut3D grid(size);
    grid.setDomain(a.domainMin(), a.domainMax());
    const auto sa = makeSampler(p.a, options.method);
    const auto sb = makeSampler(p.b, options.method);
    DiffReport report =
        finish(runDiff(count, options.nthreads, options.progress,
                       [&](std::size_t i, glm::vec3& in, glm::vec3& va, glm::vec3& vb) {
                           in = latticeInputAt(grid, i);
                           va = sa->sample(in);
                           vb = sb->sample(in);
                       }),
               p, t0);
    if (options.boundBetween) {
        // Both interpolants kink (or jump) on their own lattice's planes: the grid holds both.
        BoundOptions bo;
        bo.lo = glm::dvec3(a.domainMin());
        bo.hi = glm::dvec3(a.domainMax());
        bo.cells = size - 1;
        bo.breaks = latticeBreaks(p.a, options.method);
        addBreaks(bo.breaks, latticeBreaks(p.b, options.method));
        bo.constantBetweenBreaks = options.method == Interpolation::Nearest;
        bo.nthreads = options.nthreads;
        const ErrorStats e = boundError(
            [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t n) {
                for (std::size_t i = 0; i < n; ++i) {
                    const glm::vec3 x(in[i]);
                    diff[i] = glm::dvec3(sa->sample(x)) - glm::dvec3(sb->sample(x));
                }
            },
            bo);
        // Never below what the compared points showed.
        report.boundSteps8 =
            std::max({e.maxSteps8(), report.maxSteps8.x, report.maxSteps8.y, report.maxSteps8.z});
        report.seconds = detail::secondsSince(t0);
    }
    return report;
}

DiffReport diffLutsOnColors(const Lut3D& a, const Lut3D& b, std::span<const glm::vec3> colors,
                            const DiffOptions& options) {
    const long long t0 = detail::nowNanos();
    const Prepared p = prepare(a, b);
    const auto sa = makeSampler(p.a, options.method);
    const auto sb = makeSampler(p.b, options.method);
    return finish(runDiff(colors.size(), options.nthreads, options.progress,
                          [&](std::size_t i, glm::vec3& in, glm::vec3& va, glm::vec3& vb) {
                              in = colors[i];
                              va = sa->sample(in);
                              vb = sb->sample(in);
                          }),
                  p, t0);
}

DiffReport diffLutsOnImage(const Lut3D& a, const Lut3D& b, const ImageView& image,
                           const DiffOptions& options) {
    const long long t0 = detail::nowNanos();
    const Prepared p = prepare(a, b);
    if (image.empty())
        return finish(DiffReport{}, p, t0);
    const auto sa = makeSampler(p.a, options.method);
    const auto sb = makeSampler(p.b, options.method);
    const std::size_t w = static_cast<std::size_t>(image.width);
    const std::size_t count = w * static_cast<std::size_t>(image.height);
    return finish(runDiff(count, options.nthreads, options.progress,
                          [&](std::size_t i, glm::vec3& in, glm::vec3& va, glm::vec3& vb) {
                              const float* px =
                                  image.pixel(static_cast<int>(i % w), static_cast<int>(i / w));
                              in = glm::vec3(px[0], px[1], px[2]);
                              va = sa->sample(in);
                              vb = sb->sample(in);
                          }),
                  p, t0);
}

DiffReport diffMaps(const ColourMap& a, const ColourMap& b, const DiffOptions& options) {
    const long long t0 = detail::nowNanos();
    const int size = options.size > 0 ? options.size : 33;
    const Lut3D lattice(size); // validates the size; its entries are unused
    DiffReport r = runDiff(lattice.entryCount(), options.nthreads, options.progress,
                           [&](std::size_t i, glm::vec3& in, glm::vec3& va, glm::vec3& vb) {
                               in = latticeInputAt(lattice, i);
                               va = a(in);
                               vb = b(in);
                           });
    return finish(std::move(r), Prepared{}, t0);
}

DiffReport diffMapsOnImage(const ColourMap& a, const ColourMap& b, const ImageView& image,
                           const DiffOptions& options) {
    const long long t0 = detail::nowNanos();
    if (image.empty())
        return finish(DiffReport{}, Prepared{}, t0);
    const std::size_t w = static_cast<std::size_t>(image.width);
    const std::size_t count = w * static_cast<std::size_t>(image.height);
    return finish(runDiff(count, options.nthreads, options.progress,
                          [&](std::size_t i, glm::vec3& in, glm::vec3& va, glm::vec3& vb) {
                              const float* px =
                                  image.pixel(static_cast<int>(i % w), static_cast<int>(i / w));
                              in = glm::vec3(px[0], px[1], px[2]);
                              va = a(in);
                              vb = b(in);
                          }),
                  Prepared{}, t0);
}

} // namespace lut
