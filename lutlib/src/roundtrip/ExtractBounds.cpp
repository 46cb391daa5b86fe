// Extract's expected error; see ExtractBounds.h.
#include "roundtrip/ExtractBounds.h"

#include "interp/LatticeMapping.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/pipeline/SmashConstants.h"
#include "pipeline/GameDisplay.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace lut::detail {

namespace {

// The trilinear blend of `table` (channel c) over the patch cell around a point whose
// per-channel position on the patch lattice is (cell, frac): a bound at the corners gives one at
// the point (the patch's interpolant blends its corners with these weights or tetrahedral ones,
// and both put the point inside the corners' hull).
double cellBlend(const Lut3D& table, const int cell[3], const float frac[3], int c) {
    const int n = table.size();
    double v = 0.0;
    for (int db = 0; db < 2; ++db)
        for (int dg = 0; dg < 2; ++dg)
            for (int dr = 0; dr < 2; ++dr) {
                const double w = (dr ? frac[0] : 1.0f - frac[0]) * (dg ? frac[1] : 1.0f - frac[1]) *
                                 (db ? frac[2] : 1.0f - frac[2]);
                if (w <= 0.0)
                    continue;
                const int r = std::min(cell[0] + dr, n - 1), g = std::min(cell[1] + dg, n - 1),
                          b = std::min(cell[2] + db, n - 1);
                v += w * static_cast<double>(table.at(r, g, b)[c]);
            }
    return v;
}

// The share of the sub-lattice check's residual (spacing 2h) counted as the interpolation error at
// the patch's spacing h: a quarter for smooth edits (O(h^2)), up to a half at kinks (O(h));
// docs/roundtrip.md has the measurements behind it.
constexpr double kSubLatticeShare = 0.5;

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

// How much of the local interpolation error a point gets: none on an entry, growing linearly
// with the distance to the nearest entry (the error next to a kink grows so), all of it from a
// quarter of the cell on.
double tent(const Located& at) {
    double t = 0.0;
    for (int c = 0; c < 3; ++c)
        t = std::max(t, static_cast<double>(std::min(at.frac[c], 1.0f - at.frac[c])));
    return std::min(1.0, 4.0 * t);
}

// Per-value bounds of the three kinds, and the model error, gathered over a grid.
struct Field {
    std::vector<double> max, p99, mean;
    void add(double model, double delta, const ReadNoise& noise, const Located& at, int c) {
        model += kNumericalMargin;
        max.push_back(model + delta + cellBlend(noise.max, at.cell, at.frac, c));
        p99.push_back(model + delta + cellBlend(noise.p99, at.cell, at.frac, c));
        mean.push_back(model + delta + cellBlend(noise.mean, at.cell, at.frac, c));
    }
    void append(const Field& o) {
        max.insert(max.end(), o.max.begin(), o.max.end());
        p99.insert(p99.end(), o.p99.begin(), o.p99.end());
        mean.insert(mean.end(), o.mean.begin(), o.mean.end());
    }
    GameError summary() {
        GameError e;
        GameError a = summariseSteps(max), b = summariseSteps(p99), m = summariseSteps(mean);
        e.maxSteps = a.maxSteps;
        e.p99Steps = b.p99Steps;
        e.meanSteps = m.meanSteps;
        e.count = a.count;
        return e;
    }
};

struct Gathered {
    Field lattice, all;
    std::vector<double> model;
};

Gathered merge(std::vector<Gathered>& parts) {
    Gathered all;
    for (auto& p : parts) {
        all.lattice.append(p.lattice);
        all.all.append(p.all);
        all.model.insert(all.model.end(), p.model.begin(), p.model.end());
    }
    return all;
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
    const int k = 4, m = (kSmashLutSize - 1) * k + 1;
    const int planes = m;
    std::vector<Gathered> parts(static_cast<std::size_t>(planes));
    parallelForDynamic(planes, nthreads, 1, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b) {
            Gathered& out = parts[static_cast<std::size_t>(b)];
            for (int g = 0; g < m; ++g)
                for (int r = 0; r < m; ++r) {
                    const glm::dvec3 s = glm::dvec3(r, g, b) / static_cast<double>(m - 1);
                    const bool onLattice = r % k == 0 && g % k == 0 && b % k == 0;
                    const glm::vec3 l = game->sample(glm::vec3(s));
                    const glm::dvec3 want = wanted(s);
                    glm::vec3 where;
                    if (stage) {
                        where = glm::vec3(s);
                    } else {
                        const glm::vec3 l0 =
                            original ? original->sample(glm::vec3(s)) : glm::vec3(s);
                        for (int c = 0; c < 3; ++c)
                            where[c] = static_cast<float>(gameShown(l0[c], s[c]));
                    }
                    const Located at = locate(patch.axis, where);
                    const double share = kSubLatticeShare * tent(at);
                    for (int c = 0; c < 3; ++c) {
                        const double shown = gameShown(l[c], s[c]);
                        const double m1 = std::fabs(shown - clampUnit(want[c])) * 255.0;
                        const double delta = share * cellBlend(sub.residual, at.cell, at.frac, c);
                        out.model.push_back(m1);
                        out.all.add(m1, delta, noise, at, c);
                        if (onLattice)
                            out.lattice.add(m1, delta, noise, at, c);
                    }
                }
        }
    });
    Gathered all = merge(parts);
    ExpectedError e;
    e.atLattice = all.lattice.summary();
    e.overall = all.all.summary();
    model = summariseSteps(all.model);
    e.covers = "what the game shows with the 8-bit LUT (trilinear between its 16^3 points) vs the "
               "edited screenshot's colours, 8-bit display steps, over inputs on a 61^3 grid";
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
    std::vector<Gathered> parts(static_cast<std::size_t>(m));
    parallelForDynamic(m, nthreads, 1, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b) {
            Gathered& out = parts[static_cast<std::size_t>(b)];
            for (int g = 0; g < m; ++g)
                for (int r = 0; r < m; ++r) {
                    const glm::vec3 y = glm::vec3(r, g, b) / static_cast<float>(m - 1);
                    const bool onLattice = r % k == 0 && g % k == 0 && b % k == 0;
                    const glm::vec3 got = applied->sample(y);
                    const glm::vec3 want = edit(y);
                    const Located at = locate(patch.axis, y);
                    const double share = kSubLatticeShare * tent(at);
                    for (int c = 0; c < 3; ++c) {
                        const double m1 = std::fabs(double(got[c]) - double(want[c])) * 255.0;
                        const double delta = share * cellBlend(sub.residual, at.cell, at.frac, c);
                        out.model.push_back(m1);
                        out.all.add(m1, delta, noise, at, c);
                        if (onLattice)
                            out.lattice.add(m1, delta, noise, at, c);
                    }
                }
        }
    });
    Gathered all = merge(parts);
    ExpectedError e;
    e.atLattice = all.lattice.summary();
    e.overall = all.all.summary();
    model = summariseSteps(all.model);
    e.covers = "the LUT applied with trilinear interpolation vs the edit, 8-bit steps, over "
               "colours on a " +
               std::to_string(m) + "^3 grid";
    return e;
}

} // namespace lut::detail
