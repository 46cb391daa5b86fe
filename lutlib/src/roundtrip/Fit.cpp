// SPDX-License-Identifier: Apache-2.0
// Regularised least-squares LUT fit from a before/after pair: see Fit.h for the model.
#include "lut/roundtrip/Fit.h"

#include "core/Printf.h"

#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "ops/LatticeLeastSquares.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <unordered_set>

namespace lut {

using detail::fmt;

namespace {

struct Sample {
    std::uint32_t base; // lattice index of the cell's lower corner
    float f[3];         // fractions inside the cell
    float y[3];         // edited value
};

// The normal equations' rows: 27 numbers per node (ops/LatticeLeastSquares.h).
constexpr int kStencil = detail::kLatticeStencil;
// Samples summed together before their sums are added to the normal equations (fitImpl).
constexpr std::size_t kAssemblyBlock = 65536;

float sanitize(float v) {
    return std::isfinite(v) ? v : 0.0f;
}

void cornerWeights(const float f[3], double w[8]) {
    for (int a = 0; a < 8; ++a) {
        const double wr = (a & 1) ? f[0] : 1.0 - f[0];
        const double wg = (a & 2) ? f[1] : 1.0 - f[1];
        const double wb = (a & 4) ? f[2] : 1.0 - f[2];
        w[a] = wr * wg * wb;
    }
}

using System = detail::LatticeLeastSquares;

void warn(FitResult& res, RoundtripWarning w, const std::string& message) {
    res.warnings.push_back(w);
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.message = message;
    res.diagnostics.push_back(std::move(d));
}

} // namespace

bool FitResult::has(RoundtripWarning w) const {
    return std::find(warnings.begin(), warnings.end(), w) != warnings.end();
}

namespace {
// Which colours a fit may use: all, those not held out, or (for measuring) only those held out.
enum class Colours { All, Training, HeldOut };
FitResult fitImpl(const ImageView& before, const ImageView& after, const FitOptions& o,
                  const Lut3D* start, Colours use);

constexpr double kHeldOutMarginSteps = 0.5;

// An eighth of the distinct (8-bit) colours, chosen by a hash of the colour: held out.
bool heldOutColour(std::uint32_t key) {
    std::uint64_t h =
        (static_cast<std::uint64_t>(key) + 0x9E3779B97F4A7C15ull) * 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
    return (h & 7u) == 0u;
}

std::uint32_t colourKey(const float* a) {
    std::uint32_t key = 0;
    for (int c = 0; c < 3; ++c) {
        const float v = std::clamp(sanitize(a[c]), 0.0f, 1.0f);
        key = (key << 8) | static_cast<std::uint32_t>(std::lround(v * 255.0f));
    }
    return key;
}

// The largest |lut(before) - after| over every pixel (of the held-out colours only, when asked),
// read trilinearly and tetrahedrally (the two ways readers of a .cube interpolate), in 8-bit
// steps; sum of squares and values counted from the trilinear read.
struct PixelError {
    double worst = 0.0, sumSq = 0.0;
    std::size_t values = 0;
    std::unordered_set<std::uint32_t> colours;
};
PixelError errorOverPixels(const Lut3D& lut, const ImageView& before, const ImageView& after,
                           bool heldOutOnly) {
    const auto tri = makeSampler(lut, Interpolation::Trilinear);
    const auto tet = makeSampler(lut, Interpolation::Tetrahedral);
    PixelError r;
    for (int y = 0; y < before.height; ++y)
        for (int x = 0; x < before.width; ++x) {
            const float* a = before.pixel(x, y);
            const std::uint32_t key = colourKey(a);
            if (heldOutOnly && !heldOutColour(key))
                continue;
            if (heldOutOnly)
                r.colours.insert(key);
            glm::vec3 in;
            for (int c = 0; c < 3; ++c)
                in[c] = std::clamp(sanitize(a[c]), 0.0f, 1.0f);
            const glm::vec3 got = tri->sample(in), other = tet->sample(in);
            const float* b = after.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                const double want = std::clamp(sanitize(b[c]), -1.0f, 2.0f);
                const double e = std::fabs(double(got[c]) - want);
                r.sumSq += e * e;
                r.worst = std::max({r.worst, e, std::fabs(double(other[c]) - want)});
                ++r.values;
            }
        }
    r.worst *= 255.0;
    return r;
}
} // namespace

FitResult fitLut(const ImageView& before, const ImageView& after, const FitOptions& o) {
    FitResult res = fitImpl(before, after, o, nullptr, Colours::All);
    // The pixels' maximum over every pixel (the fit samples a large picture regularly) and either
    // interpolation a reader may use (issue 40: 6.22 printed, 13.72 on the full-resolution
    // screenshot the fit was made from).
    res.maxSteps8 = std::max(res.maxSteps8, errorOverPixels(res.lut, before, after, false).worst);
    if (!o.heldOut || res.distinctColours < 16)
        return res;
    // The error on colours a fit never saw: a fit on the other seven eighths of the colours,
    // measured on the held-out eighth (the written LUT is fitted on all of them).
    FitOptions training = o;
    training.heldOut = false;
    const FitResult part = fitImpl(before, after, training, nullptr, Colours::Training);
    const PixelError held = errorOverPixels(part.lut, before, after, true);
    const double worst = held.worst / 255.0;
    res.heldOutColours = held.colours.size();
    res.heldOutPixels = held.values / 3;
    res.heldOutRmsSteps8 = held.values ? std::sqrt(held.sumSq / double(held.values)) * 255.0 : 0.0;
    // The largest of a sample is a low estimate of the largest elsewhere: the larger of the
    // held-out and the fitted pixels' maxima, plus half an 8-bit step (every target pixel is
    // rounded; another picture's pixels fall elsewhere in the rounding).
    res.heldOutMaxSteps8 = std::max(worst * 255.0, res.maxSteps8) + kHeldOutMarginSteps;
    return res;
}

namespace {

FitResult fitImpl(const ImageView& before, const ImageView& after, const FitOptions& o,
                  const Lut3D* start, Colours use) {
    if (before.empty() || after.empty())
        throw Error("fit: empty image");
    if (before.width != after.width || before.height != after.height)
        throw Error("fit: the images differ in size (" + std::to_string(before.width) + "x" +
                    std::to_string(before.height) + " vs " + std::to_string(after.width) + "x" +
                    std::to_string(after.height) + ")");
    const int n = o.size;
    if (n < limits::kMin3DSize || n > 129)
        throw Error("fit: size must be 2..129, not " + std::to_string(n));
    if (!(o.smoothness >= 0.0) || !std::isfinite(o.smoothness))
        throw Error("fit: smoothness must be >= 0");

    FitResult res;
    // --- samples ---
    std::vector<Sample> samples;
    samples.reserve(static_cast<std::size_t>(
        std::min<double>(static_cast<double>(before.width) * before.height, 8.0e6 + 1e5)));
    std::unordered_set<std::uint32_t> colours;
    const int cells = n - 1;
    std::vector<std::uint8_t> cellHit(std::size_t(cells) * cells * cells, 0);
    // Beyond ~8 megapixels a regular subsample says as much about a global edit (and bounds the
    // memory: 28 bytes per sample).
    constexpr double kMaxSamples = 8.0e6;
    const double total = static_cast<double>(before.width) * before.height;
    const int step =
        total > kMaxSamples ? static_cast<int>(std::ceil(std::sqrt(total / kMaxSamples))) : 1;
    for (int y = 0; y < before.height; y += step)
        for (int x = 0; x < before.width; x += step) {
            const float* a = before.pixel(x, y);
            const float* b = after.pixel(x, y);
            if (use != Colours::All && heldOutColour(colourKey(a)) != (use == Colours::HeldOut))
                continue;
            Sample s{};
            int idx[3];
            std::uint32_t key = 0;
            for (int c = 0; c < 3; ++c) {
                const float v = std::clamp(sanitize(a[c]), 0.0f, 1.0f);
                const float pos = v * static_cast<float>(cells);
                idx[c] = std::min(static_cast<int>(pos), cells - 1);
                s.f[c] = pos - static_cast<float>(idx[c]);
                s.y[c] = std::clamp(sanitize(b[c]), -1.0f, 2.0f);
                key = (key << 8) | static_cast<std::uint32_t>(std::lround(v * 255.0f));
            }
            s.base = static_cast<std::uint32_t>(idx[0] + n * (idx[1] + n * idx[2]));
            cellHit[std::size_t(idx[0]) +
                    std::size_t(cells) * (idx[1] + std::size_t(cells) * idx[2])] = 1;
            if (colours.size() < 100000)
                colours.insert(key);
            samples.push_back(s);
        }
    res.pixels = samples.size();
    res.distinctColours = colours.size();
    std::size_t hit = 0;
    for (auto h : cellHit)
        hit += h;
    res.extrapolatedShare = 1.0 - static_cast<double>(hit) / static_cast<double>(cellHit.size());

    const std::size_t nn = std::size_t(n) * n;
    const std::ptrdiff_t cornerOffset[8] = {0,
                                            1,
                                            n,
                                            n + 1,
                                            std::ptrdiff_t(nn),
                                            std::ptrdiff_t(nn) + 1,
                                            std::ptrdiff_t(nn) + n,
                                            std::ptrdiff_t(nn) + n + 1};
    auto stencilIndex = [](int a, int b) {
        const int dr = ((b & 1) - (a & 1)), dg = ((b >> 1 & 1) - (a >> 1 & 1)),
                  db = ((b >> 2 & 1) - (a >> 2 & 1));
        return (dr + 1) + 3 * (dg + 1) + 9 * (db + 1);
    };

    // The ridge is tiny next to the data and the smoothness: it only pins directions nothing else
    // determines, towards the identity.
    const double mu = 1e-4 * std::max(o.smoothness, 1e-3);
    std::vector<double> weights(samples.size(), 1.0);
    std::vector<std::vector<double>> solution(3, std::vector<double>(std::size_t(n) * nn));
    // Start from a fit on the lattice of half the resolution (recursively): CG removes the
    // high frequencies quickly and the smooth fill of empty regions slowly, which the coarse
    // solution already holds (a cascade, the cheap half of multigrid).
    Lut3D coarse;
    if (!start && n > 9) {
        FitOptions co = o;
        co.size = (n + 1) / 2;
        co.robustRounds = std::min(o.robustRounds, 2);
        coarse = fitImpl(before, after, co, nullptr, use).lut;
        start = &coarse;
    }
    std::unique_ptr<Sampler> startSampler;
    if (start)
        startSampler = makeSampler(*start, Interpolation::Trilinear);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const std::size_t i = std::size_t(r) + std::size_t(n) * (g + std::size_t(n) * b);
                glm::vec3 v = glm::vec3(r, g, b) / static_cast<float>(cells);
                if (startSampler)
                    v = startSampler->sample(v);
                solution[0][i] = v.x;
                solution[1][i] = v.y;
                solution[2][i] = v.z;
            }

    const int rounds = o.robust ? std::max(1, o.robustRounds + 1) : 1;
    const double delta = o.huberSteps / 255.0;
    for (int round = 0; round < rounds; ++round) {
        System sys(n, o.smoothness, mu);
        std::vector<std::vector<double>> rhs(3, std::vector<double>(sys.count(), 0.0));
        // identity prior on the right-hand side
        for (int c = 0; c < 3; ++c)
            for (int b = 0; b < n; ++b)
                for (int g = 0; g < n; ++g)
                    for (int r = 0; r < n; ++r) {
                        const int coord[3] = {r, g, b};
                        rhs[c][std::size_t(r) + std::size_t(n) * (g + std::size_t(n) * b)] =
                            mu * coord[c] / cells;
                    }
        // The normal equations, summed in one order whatever the threads: the samples in blocks
        // of a fixed size, each summed on its own, the blocks added in their order (a wave of
        // blocks at a time, one per thread). The same pictures give the same bytes on every run
        // and every machine (floating-point addition is not associative).
        const std::size_t blocks = (samples.size() + kAssemblyBlock - 1) / kAssemblyBlock;
        const std::size_t wave = std::min<std::size_t>(blocks, resolveThreads(o.nthreads));
        std::vector<std::vector<double>> local(wave), localRhs(wave);
        for (std::size_t first = 0; first < blocks; first += wave) {
            const std::size_t count = std::min(wave, blocks - first);
            parallelFor(static_cast<int>(count), o.nthreads, [&](int begin, int end) {
                double w[8];
                for (int k = begin; k < end; ++k) {
                    auto& lhs = local[static_cast<std::size_t>(k)];
                    auto& rhsK = localRhs[static_cast<std::size_t>(k)];
                    lhs.assign(sys.count() * kStencil, 0.0);
                    rhsK.assign(sys.count() * 3, 0.0);
                    const std::size_t p0 = (first + static_cast<std::size_t>(k)) * kAssemblyBlock;
                    const std::size_t p1 = std::min(samples.size(), p0 + kAssemblyBlock);
                    for (std::size_t p = p0; p < p1; ++p) {
                        const Sample& s = samples[p];
                        const double pw = weights[p];
                        if (pw <= 0.0)
                            continue;
                        cornerWeights(s.f, w);
                        for (int a = 0; a < 8; ++a) {
                            if (w[a] == 0.0)
                                continue;
                            const std::size_t node = s.base + cornerOffset[a];
                            double* row = &lhs[node * kStencil];
                            for (int b = 0; b < 8; ++b)
                                row[stencilIndex(a, b)] += pw * w[a] * w[b];
                            for (int c = 0; c < 3; ++c)
                                rhsK[node * 3 + c] += pw * w[a] * s.y[c];
                        }
                    }
                }
            });
            auto& global = sys.data();
            for (std::size_t k = 0; k < count; ++k) {
                for (std::size_t i = 0; i < local[k].size(); ++i)
                    global[i] += local[k][i];
                for (std::size_t i = 0; i < sys.count(); ++i)
                    for (int c = 0; c < 3; ++c)
                        rhs[c][i] += localRhs[k][i * 3 + c];
            }
        }
        sys.finishAssembly();
        const std::vector<double> diag = sys.diagonal();
        int iterations[3] = {0, 0, 0};
        bool conv[3] = {true, true, true};
        parallelFor(3, o.nthreads, [&](int begin, int end) {
            for (int c = begin; c < end; ++c) {
                const detail::CgResult cg = detail::solveJacobiCg(sys, diag, rhs[c], solution[c],
                                                                  o.maxIterations, o.tolerance);
                iterations[c] = cg.iterations;
                conv[c] = cg.converged;
            }
        });
        res.iterations += std::max({iterations[0], iterations[1], iterations[2]});
        res.converged = conv[0] && conv[1] && conv[2];

        // residuals -> Huber weights for the next round (and the final statistics)
        double sumSq = 0.0, maxAbs = 0.0;
        std::size_t outliers = 0;
        double w[8];
        for (std::size_t p = 0; p < samples.size(); ++p) {
            const Sample& s = samples[p];
            cornerWeights(s.f, w);
            double worst = 0.0;
            for (int c = 0; c < 3; ++c) {
                double v = 0.0;
                for (int a = 0; a < 8; ++a)
                    if (w[a] != 0.0)
                        v += w[a] * std::clamp(solution[c][s.base + cornerOffset[a]], 0.0, 1.0);
                const double e = std::fabs(v - s.y[c]);
                sumSq += e * e;
                worst = std::max(worst, e);
            }
            maxAbs = std::max(maxAbs, worst);
            if (worst > 4.0 * delta)
                ++outliers;
            weights[p] = worst <= delta ? 1.0 : delta / worst;
        }
        res.rmsSteps8 = samples.empty() ? 0.0 : std::sqrt(sumSq / (3.0 * samples.size())) * 255.0;
        res.maxSteps8 = maxAbs * 255.0;
        res.outlierPixels = outliers;
    }

    res.lut = Lut3D(n);
    for (std::size_t i = 0; i < res.lut.entryCount(); ++i)
        res.lut.entries()[i] = glm::vec3(static_cast<float>(std::clamp(solution[0][i], 0.0, 1.0)),
                                         static_cast<float>(std::clamp(solution[1][i], 0.0, 1.0)),
                                         static_cast<float>(std::clamp(solution[2][i], 0.0, 1.0)));
    res.lut.setTitle("fitted from a before/after pair");

    if (!res.converged)
        warn(res, RoundtripWarning::FewColours,
             fmt("the solver stopped after %g iterations before converging: the fit may be rough",
                 double(res.iterations)));
    if (res.distinctColours < 64)
        warn(res, RoundtripWarning::FewColours,
             fmt("the before image has only %g distinct colours: the fit is exact at those and a "
                 "smooth "
                 "guess everywhere else",
                 double(res.distinctColours)));
    if (res.extrapolatedShare > 0.9)
        warn(res, RoundtripWarning::LowCoverage,
             fmt("the pixels cover only %.3g%% of the %g^3 lattice cells; %.3g%% of the cube is "
                 "extrapolated "
                 "(colours the screenshot does not contain follow a smooth continuation)",
                 100.0 * (1.0 - res.extrapolatedShare), double(n), 100.0 * res.extrapolatedShare));
    if (res.pixels > 0 && res.outlierPixels * 100 > res.pixels)
        warn(res, RoundtripWarning::Outliers,
             fmt("%.3g%% of the pixels (%g) are more than %g 8-bit steps off any global colour "
                 "edit (local "
                 "edits, noise, misaligned images?); the robust fit down-weighted them",
                 100.0 * double(res.outlierPixels) / double(res.pixels), double(res.outlierPixels),
                 4.0 * o.huberSteps));
    return res;
}

} // namespace

} // namespace lut
