// SPDX-License-Identifier: Apache-2.0
// Extract's expected error; see ExtractBounds.h.
#include "roundtrip/ExtractBounds.h"

#include "interp/LatticeMapping.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"
#include "lut/smash/GameDisplay.h"
#include "lut/smash/SmashConstants.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

namespace lut::detail {

namespace {

// The interpolation error of the patch between its entries, from the sub-lattice check: its
// residual is the error of predicting an entry from its neighbours one spacing away, i.e. of
// interpolating over two spacings. Over one spacing a smooth edit's error is a quarter of that;
// next to a kink, blended across the cell, up to all of it (the kink shows in the residuals of
// the cell's two ends, in proportion to its distance from each); next to a steep power near
// black (levels' gamma, x^0.4) about all of it. The maximum and the 99th percentile count all
// of it (issue 22: half of it fell short for hard levels and steep gammas); the mean, over every
// input where kinks are rare, half.
constexpr double kSubLatticeShareMax = 1.0;
constexpr double kSubLatticeShareMean = 0.5;

// Float rounding of the LUT and the samplers, in 8-bit steps.
constexpr double kNumericalMargin = 0.01;

struct Located {
    int cell[3];
    float frac[3];
};

Located locate(const std::vector<float>& axis, glm::vec3 x) {
    Located l{};
    for (int c = 0; c < 3; ++c)
        locateOnAxis(axis.data(), static_cast<int>(axis.size()), x[c], l.cell[c], l.frac[c]);
    return l;
}

// How much of the local interpolation error a point gets: none on an entry (the patch holds the
// edit there; within half a storage code of it, since the patch's colours are stored as codes),
// growing with the distance to the nearest entry up to all of it from `reach` of the cell on: a
// twentieth for the largest values (the error next to a steep power grows faster than the
// distance), a quarter for the mean (next to a kink it grows with the distance).
double tent(const Located& at, const std::vector<float>& axis, double halfCode, double reach) {
    double t = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double width = std::max(1e-9, double(axis[static_cast<std::size_t>(at.cell[c]) + 1]) -
                                                axis[static_cast<std::size_t>(at.cell[c])]);
        const double away = std::min(at.frac[c], 1.0f - at.frac[c]) * width;
        t = std::max(t, std::max(0.0, away - halfCode) / width);
    }
    return std::min(1.0, t / reach);
}

// The kinds of per-value bound at one input (model + margin + interpolation + noise): `max` and
// `p99` for the output LUT's lattice points (the interpolation term falling to 0 on an entry),
// `envelope` and `p99Everywhere` the same without that fall, for the held-out points between
// (the envelope then varies no faster than the model error: what the maximum between the
// points is bounded from).
struct Bounds3 {
    glm::dvec3 model{0.0}, max{0.0}, envelope{0.0}, p99{0.0}, p99Everywhere{0.0}, mean{0.0};
};

// Per entry and channel (8-bit steps), the larger of the sub-lattice check's residual and each
// entry's own prediction from its two neighbours along each axis (the check predicts only the
// odd entries from the even ones: a kink just past an even entry, a clamp's black point with a
// steep rise after it, shows at that entry and barely at the odd one next to it).
Lut3D interpolationResiduals(const PatchReading& patch, const SubLattice& sub) {
    const int n = patch.values.size();
    Lut3D out = sub.residual;
    if (out.size() != n)
        out = Lut3D(n);
    const std::vector<float>& a = patch.axis;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const int idx[3] = {r, g, b};
                glm::vec3& v = out.at(r, g, b);
                for (int axis = 0; axis < 3; ++axis) {
                    const int i = idx[axis];
                    if (i == 0 || i + 1 >= n)
                        continue;
                    int lo[3] = {r, g, b}, hi[3] = {r, g, b};
                    --lo[axis];
                    ++hi[axis];
                    const double t = (double(a[i]) - a[i - 1]) / (double(a[i + 1]) - a[i - 1]);
                    const glm::vec3 fl = patch.values.at(lo[0], lo[1], lo[2]);
                    const glm::vec3 fh = patch.values.at(hi[0], hi[1], hi[2]);
                    const glm::vec3 f = patch.values.at(r, g, b);
                    for (int c = 0; c < 3; ++c) {
                        const double pred = (1.0 - t) * fl[c] + t * fh[c];
                        v[c] = std::max(v[c], static_cast<float>(std::fabs(f[c] - pred) * 255.0));
                    }
                }
            }
    return out;
}

// The residual and the three noise kinds, one table: blended across a cell in one pass.
struct Terms {
    glm::vec3 residual, noiseMax, noiseP99, noiseMean;
};

// Evaluates the bounds at an input from the model error there and the point on the patch's
// lattice to take the interpolation and noise terms from.
class BoundField {
public:
    BoundField(const PatchReading& patch, const SubLattice& sub, const ReadNoise& noise)
        : m_patch(patch), m_n(patch.values.size()),
          m_halfCode(patch.storedBits == 8 ? 0.5 / 255.0 : 0.5 / 65535.0) {
        const Lut3D residual = interpolationResiduals(patch, sub);
        m_terms.resize(residual.entryCount());
        for (std::size_t i = 0; i < m_terms.size(); ++i)
            m_terms[i] = {residual.entries()[i], noise.max.entries()[i], noise.p99.entries()[i],
                          noise.mean.entries()[i]};
        for (const auto& e : residual.entries())
            m_largestResidual =
                std::max({m_largestResidual, double(e.x), double(e.y), double(e.z)});
    }

    Bounds3 at(const glm::dvec3& model, glm::vec3 where) const {
        const Located l = locate(m_patch.axis, where);
        const double shareMax = kSubLatticeShareMax * tent(l, m_patch.axis, m_halfCode, 0.05);
        const double shareMean = kSubLatticeShareMean * tent(l, m_patch.axis, m_halfCode, 0.25);
        // the trilinear blend of the cell's corners (a bound at the corners gives one at the
        // point: the patch's interpolant blends its corners with these weights or tetrahedral
        // ones, and both put the point inside the corners' hull)
        glm::dvec3 r(0.0), nMax(0.0), nP99(0.0), nMean(0.0);
        for (int db = 0; db < 2; ++db)
            for (int dg = 0; dg < 2; ++dg)
                for (int dr = 0; dr < 2; ++dr) {
                    const double w = (dr ? l.frac[0] : 1.0f - l.frac[0]) *
                                     (dg ? l.frac[1] : 1.0f - l.frac[1]) *
                                     (db ? l.frac[2] : 1.0f - l.frac[2]);
                    if (w <= 0.0)
                        continue;
                    const std::size_t i =
                        static_cast<std::size_t>(std::min(l.cell[0] + dr, m_n - 1)) +
                        static_cast<std::size_t>(m_n) *
                            (static_cast<std::size_t>(std::min(l.cell[1] + dg, m_n - 1)) +
                             static_cast<std::size_t>(m_n) *
                                 static_cast<std::size_t>(std::min(l.cell[2] + db, m_n - 1)));
                    const Terms& t = m_terms[i];
                    r += w * glm::dvec3(t.residual);
                    nMax += w * glm::dvec3(t.noiseMax);
                    nP99 += w * glm::dvec3(t.noiseP99);
                    nMean += w * glm::dvec3(t.noiseMean);
                }
        Bounds3 b;
        for (int c = 0; c < 3; ++c) {
            const double m = model[c] + kNumericalMargin;
            b.model[c] = model[c];
            b.max[c] = m + shareMax * r[c] + nMax[c];
            b.envelope[c] = m + kSubLatticeShareMax * r[c] + nMax[c];
            b.p99[c] = m + shareMax * r[c] + nP99[c];
            b.p99Everywhere[c] = m + kSubLatticeShareMax * r[c] + nP99[c];
            b.mean[c] = m + shareMean * r[c] + nMean[c];
        }
        return b;
    }

    double largestResidual() const { return m_largestResidual; }

private:
    const PatchReading& m_patch;
    int m_n;
    double m_halfCode;
    std::vector<Terms> m_terms;
    double m_largestResidual = 0.0;
};

// Adds to each value of an m^3 grid of centres (3 channels, red fastest) half the largest change
// between neighbouring centres along each axis over its 3x3x3 neighbourhood, summed over the
// axes: the slope term of a Lipschitz bound over the centre's box.
void addSlopeTerm(std::vector<double>& v, int m) {
    const std::size_t mm = static_cast<std::size_t>(m);
    const std::size_t stride[3] = {3, 3 * mm, 3 * mm * mm};
    std::vector<double> term(v.size(), 0.0), change(v.size()), tmp(v.size());
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t s = stride[axis];
        // the largest change to a neighbour along `axis`; then its largest over the 3x3x3
        // neighbourhood, a running maximum of width 3 along each axis
        for (std::size_t b = 0, i = 0; b < mm; ++b)
            for (std::size_t g = 0; g < mm; ++g)
                for (std::size_t r = 0; r < mm; ++r)
                    for (std::size_t c = 0; c < 3; ++c, ++i) {
                        const std::size_t q = axis == 0 ? r : axis == 1 ? g : b;
                        double d = 0.0;
                        if (q > 0)
                            d = std::fabs(v[i] - v[i - s]);
                        if (q + 1 < mm)
                            d = std::max(d, std::fabs(v[i + s] - v[i]));
                        change[i] = d;
                    }
        for (int along = 0; along < 3; ++along) {
            const std::size_t t = stride[along];
            for (std::size_t b = 0, i = 0; b < mm; ++b)
                for (std::size_t g = 0; g < mm; ++g)
                    for (std::size_t r = 0; r < mm; ++r)
                        for (std::size_t c = 0; c < 3; ++c, ++i) {
                            const std::size_t q = along == 0 ? r : along == 1 ? g : b;
                            double d = change[i];
                            if (q > 0)
                                d = std::max(d, change[i - t]);
                            if (q + 1 < mm)
                                d = std::max(d, change[i + t]);
                            tmp[i] = d;
                        }
            change.swap(tmp);
        }
        for (std::size_t i = 0; i < v.size(); ++i)
            term[i] += 0.5 * change[i];
    }
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] += term[i];
}

// The bound at the output LUT's lattice points, and over every input: mean and p99 over the
// held-out points of a grid k times finer than the lattice (the centres of its boxes), the
// maximum the largest bound at those points plus the slope between them (lut/ops/ErrorBound.h).
ExpectedError summarise(const std::function<Bounds3(const glm::dvec3&)>& boundsAt, int cells, int k,
                        GameError& model, int nthreads) {
    ExpectedError e;
    std::vector<double> latticeModel;
    {
        const int n = cells + 1;
        std::vector<double> mx, p99, mean;
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const Bounds3 v = boundsAt(glm::dvec3(r, g, b) / static_cast<double>(cells));
                    for (int c = 0; c < 3; ++c) {
                        mx.push_back(v.max[c]);
                        p99.push_back(v.p99[c]);
                        mean.push_back(v.mean[c]);
                        latticeModel.push_back(v.model[c]);
                    }
                }
        e.atLattice.maxSteps = summariseSteps(mx).maxSteps;
        e.atLattice.p99Steps = summariseSteps(p99).p99Steps;
        const GameError mm = summariseSteps(mean);
        e.atLattice.meanSteps = mm.meanSteps;
        e.atLattice.count = mm.count;
    }
    // The held-out points are the centres (i + 0.5) / m of an m^3 grid: their other kinds are
    // kept by index as the bound visits them (the refinement's points are not kept).
    const int m = cells * k;
    const std::size_t points =
        static_cast<std::size_t>(m) * static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
    // The bound works in slabs of planes on several threads, and two neighbouring slabs both
    // evaluate the planes of their shared halo: the same centre can be written by two threads
    // (with the same value), so the stores are atomic.
    std::vector<std::atomic<double>> kept(9 * points);
    BoundOptions o;
    o.cells = cells;
    o.perCell = k;
    o.nthreads = nthreads;
    const ErrorStats bound = boundError(
        [&](const glm::dvec3* in, glm::dvec3* out, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i) {
                const Bounds3 v = boundsAt(in[i]);
                out[i] = v.envelope;
                std::size_t index = 0, scale = 1;
                bool centre = true;
                for (int c = 0; c < 3; ++c) {
                    const double q = in[i][c] * m - 0.5;
                    const double qi = std::round(q);
                    centre = centre && std::fabs(q - qi) < 1e-6 && qi >= 0 && qi < m;
                    index += static_cast<std::size_t>(std::max(qi, 0.0)) * scale;
                    scale *= static_cast<std::size_t>(m);
                }
                if (!centre)
                    continue;
                for (int c = 0; c < 3; ++c) {
                    const std::size_t at = 9 * index + static_cast<std::size_t>(c);
                    kept[at].store(v.p99Everywhere[c], std::memory_order_relaxed);
                    kept[at + 3].store(v.mean[c], std::memory_order_relaxed);
                    kept[at + 6].store(v.model[c], std::memory_order_relaxed);
                }
            }
        },
        o);
    std::vector<double> p99(3 * points), mean(3 * points), mdl(3 * points);
    for (std::size_t i = 0; i < 3 * points; ++i) {
        const std::size_t at = 9 * (i / 3) + i % 3;
        p99[i] = kept[at].load(std::memory_order_relaxed);
        mean[i] = kept[at + 3].load(std::memory_order_relaxed);
        mdl[i] = kept[at + 6].load(std::memory_order_relaxed);
    }
    e.overall.maxSteps = std::max(bound.maxAbs, e.atLattice.maxSteps);
    // The p99 counts each box at its centre's value plus what the value can add within the box
    // (as the maximum does, lut/ops/ErrorBound.h): along each axis the largest change between
    // neighbouring centres over the centre's 3x3x3 neighbourhood, times half. A peak between the
    // centres (a steep power's largest error sits near a corner of its box) would otherwise fall
    // out of the percentile.
    addSlopeTerm(p99, m);
    // (never above the maximum, which bounds every input)
    e.overall.p99Steps = std::min(summariseSteps(p99).p99Steps, e.overall.maxSteps);
    const GameError mm = summariseSteps(mean);
    e.overall.meanSteps = mm.meanSteps;
    e.overall.count = mm.count;
    mdl.insert(mdl.end(), latticeModel.begin(), latticeModel.end());
    model = summariseSteps(mdl); // the LUT against the patch's edit: lattice and held-out points
    return e;
}

} // namespace

ReadNoise estimateReadNoise(const PatchReading& patch) {
    const int n = patch.values.size();
    ReadNoise out;
    const double q = patch.storedBits == 8 ? 1.0 : patch.storedBits == 16 ? 1.0 / 257.0 : 0.0;
    out.half = 0.5 * q;
    out.frame = patch.frameSpread * 255.0;
    out.spread = patch.blockSpread;
    for (auto& e : out.spread.entries())
        e *= 255.0f;
    // Neighbouring entries: along each axis a cubic through i-2, i-1, i+1, i+2 (Lagrange on the
    // patch's own axis values) predicts entry i. Its misfit is noise (scaled by the prediction's
    // own noise gain) plus what the edit does that a cubic does not: a kink (a clamp, a gradient
    // map's stop, a hue edit's sector edge). A kink is a plane in the cube, so across it along one
    // axis an entry is usually smooth along another: the smallest misfit of the three axes is
    // kept, and the median of those (for pure noise the median of the smallest of three |N(0,
    // sigma)| is 0.26 sigma) gives the noise level.
    const std::vector<float>& a = patch.axis;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> misfit;
        for (int b = 2; b + 2 < n; ++b)
            for (int g = 2; g + 2 < n; ++g)
                for (int r = 2; r + 2 < n; ++r) {
                    const double v = patch.values.at(r, g, b)[c];
                    if (v <= 0.5 / 255.0 || v >= 1.0 - 0.5 / 255.0)
                        continue; // clipped: says nothing about noise
                    double smallest = 1e30;
                    for (int axis = 0; axis < 3; ++axis) {
                        const int idx[3] = {r, g, b};
                        const int i = idx[axis];
                        auto value = [&](int k) {
                            int q3[3] = {r, g, b};
                            q3[axis] = k;
                            return static_cast<double>(patch.values.at(q3[0], q3[1], q3[2])[c]);
                        };
                        const int ks[4] = {i - 2, i - 1, i + 1, i + 2};
                        double pred = 0.0, gain = 1.0;
                        for (int j = 0; j < 4; ++j) {
                            double l = 1.0;
                            for (int m = 0; m < 4; ++m)
                                if (m != j)
                                    l *= (double(a[i]) - a[ks[m]]) / (double(a[ks[j]]) - a[ks[m]]);
                            pred += l * value(ks[j]);
                            gain += l * l;
                        }
                        smallest =
                            std::min(smallest, std::fabs(v - pred) * 255.0 / std::sqrt(gain));
                    }
                    misfit.push_back(smallest);
                }
        if (misfit.size() < 8)
            continue;
        std::nth_element(misfit.begin(), misfit.begin() + misfit.size() / 2, misfit.end());
        const double sigma = misfit[misfit.size() / 2] / 0.26;
        // the storage rounding (uniform, variance q^2/12) is counted on its own
        out.sigma[c] = std::sqrt(std::max(0.0, sigma * sigma - q * q / 12.0));
    }
    out.max = Lut3D(n);
    out.p99 = Lut3D(n);
    out.mean = Lut3D(n);
    for (std::size_t i = 0; i < out.spread.entryCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double sp = out.spread.entries()[i][c];
            out.max.entries()[i][c] =
                static_cast<float>(out.half + std::max(3.5 * out.sigma[c], out.frame) + sp);
            out.p99.entries()[i][c] = static_cast<float>(out.half + 2.6 * out.sigma[c] + sp);
            // the mean of a rounding error is half a half step; 0.6 leaves room for a sample of
            // a few thousand entries
            out.mean.entries()[i][c] =
                static_cast<float>(0.6 * out.half + 0.8 * out.sigma[c] + 0.8 * sp);
        }
    return out;
}

ExpectedError smashExpectedError(const PatchReading& patch, const SubLattice& sub,
                                 const ReadNoise& noise, const Lut3D& shipped,
                                 const std::function<glm::dvec3(const glm::dvec3&)>& wanted,
                                 const Lut3D* originalLut, GameError& model, int nthreads) {
    const bool stage = patch.placement.lattice == PatchLattice::SmashStage;
    const auto game = makeSampler(shipped, Interpolation::Trilinear);
    std::unique_ptr<Sampler> original;
    if (originalLut)
        original = makeSampler(*originalLut, Interpolation::Trilinear);
    const BoundField field(patch, sub, noise);
    const auto boundsAt = [&](const glm::dvec3& s) {
        const glm::vec3 l = game->sample(glm::vec3(s));
        const glm::dvec3 want = wanted(s);
        glm::vec3 where;
        if (stage) {
            where = glm::vec3(s);
        } else {
            const glm::vec3 l0 = original ? original->sample(glm::vec3(s)) : glm::vec3(s);
            for (int c = 0; c < 3; ++c)
                where[c] = static_cast<float>(gameShownTabulated(l0[c], s[c]));
        }
        glm::dvec3 m;
        for (int c = 0; c < 3; ++c)
            m[c] = std::fabs(gameShownTabulated(l[c], s[c]) - clampUnit(want[c])) * 255.0;
        return field.at(m, where);
    };
    ExpectedError e = summarise(boundsAt, kSmashLutSize - 1, 4, model, nthreads);
    e.interpolationSteps = field.largestResidual();
    e.covers = "what the game shows with the 8-bit LUT (trilinear between its 16^3 points) vs the "
               "edited screenshot's colours, 8-bit display steps, over every input (mean and p99 "
               "over a 61^3 grid, the maximum bounded between its points too)";
    return e;
}

ExpectedError rawExpectedError(const PatchReading& patch, const SubLattice& sub,
                               const ReadNoise& noise, const Lut3D& lut, const PatchFunction& edit,
                               GameError& model, int nthreads) {
    const int size = lut.size();
    // A grid up to four times finer than the output lattice, at most 65 points per axis.
    int k = 4;
    while (k > 1 && (size - 1) * k + 1 > 65)
        --k;
    const int m = (size - 1) * k + 1;
    const auto applied = makeSampler(lut, Interpolation::Trilinear);
    const BoundField field(patch, sub, noise);
    const auto boundsAt = [&](const glm::dvec3& y) {
        const glm::vec3 got = applied->sample(glm::vec3(y));
        const glm::vec3 want = edit(glm::vec3(y));
        glm::dvec3 mdl;
        for (int c = 0; c < 3; ++c)
            mdl[c] = std::fabs(double(got[c]) - double(want[c])) * 255.0;
        return field.at(mdl, glm::vec3(y));
    };
    ExpectedError e = summarise(boundsAt, size - 1, k, model, nthreads);
    e.interpolationSteps = field.largestResidual();
    e.covers = "the LUT applied with trilinear interpolation vs the edit, 8-bit steps, over every "
               "colour (mean and p99 over a " +
               std::to_string(m) + "^3 grid, the maximum bounded between its points too)";
    return e;
}

} // namespace lut::detail
