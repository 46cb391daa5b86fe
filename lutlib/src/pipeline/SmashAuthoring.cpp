// The exact Smash composition, the colours it is measured over, the refinement; see
// lut/pipeline/SmashAuthoring.h.
#include "lut/pipeline/SmashAuthoring.h"

#include "lut/Error.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/pipeline/SmashConstants.h"
#include "lut/pipeline/SmashGrading.h"
#include "pipeline/GameDisplay.h"
#include "pipeline/GameSamples.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace lut {

namespace {

using detail::GameSamples;

// What the unedited game shows, with the stage LUT read directly at its own lattice points.
class StageModel {
public:
    explicit StageModel(const Lut3D* lut) : m_lut(lut) {
        m_direct = lut && lut->size() == kSmashLutSize && lut->hasDefaultDomain();
        if (lut)
            m_sampler = makeSampler(*lut, Interpolation::Trilinear);
    }
    glm::dvec3 lutOut(const glm::dvec3& s) const {
        if (!m_lut)
            return s;
        if (m_direct) {
            const double x = s.x * (kSmashLutSize - 1), y = s.y * (kSmashLutSize - 1),
                         z = s.z * (kSmashLutSize - 1);
            const long ix = std::lround(x), iy = std::lround(y), iz = std::lround(z);
            if (std::fabs(x - ix) < 1e-9 && std::fabs(y - iy) < 1e-9 && std::fabs(z - iz) < 1e-9)
                return glm::dvec3(m_lut->at(int(ix), int(iy), int(iz)));
        }
        return glm::dvec3(m_sampler->sample(glm::vec3(s)));
    }
    glm::dvec3 shown(const glm::dvec3& s, bool clip) const {
        const glm::dvec3 l = lutOut(s);
        glm::dvec3 d;
        for (int c = 0; c < 3; ++c)
            d[c] = clip ? detail::gameShown(l[c], s[c]) : detail::gameShownUnclipped(l[c], s[c]);
        return d;
    }
    const Sampler* sampler() const { return m_sampler.get(); }

private:
    const Lut3D* m_lut;
    bool m_direct = false;
    std::unique_ptr<Sampler> m_sampler;
};

// A deterministic number in [0, 1) for pixel p, channel c: where a clipped pixel's input was.
double spread(std::size_t p, int c) {
    std::uint64_t h = (static_cast<std::uint64_t>(p) << 2 | static_cast<std::uint64_t>(c)) *
                      0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return static_cast<double>(h >> 11) / 9007199254740992.0;
}

// The input s the unedited game had for a displayed colour d (display-encoded, [0,1]).
glm::dvec3 inputForShown(const glm::dvec3& d, const StageModel& stage, std::size_t p) {
    const double clipS = 1.0 / static_cast<double>(kSmashBrightenScale);
    if (!stage.sampler()) {
        glm::dvec3 s;
        for (int c = 0; c < 3; ++c) {
            if (d[c] >= 1.0 - 1e-7) // white: any input above the clip point showed it
                s[c] = clipS + (1.0 - clipS) * spread(p, c);
            else
                s[c] = std::pow(detail::srgbDecodeUnit(d[c]), 1.0 / kSmashDecodeExponent) /
                       kSmashBrightenScale;
        }
        return s;
    }
    const glm::vec3 linear(static_cast<float>(detail::srgbDecodeUnit(d.x)),
                           static_cast<float>(detail::srgbDecodeUnit(d.y)),
                           static_cast<float>(detail::srgbDecodeUnit(d.z)));
    const glm::vec3 scene = smashGradeInverse(linear, 1.0f, *stage.sampler());
    return glm::dvec3(smashEncode(scene));
}

// The grid's cell centres (offset by half a sample): where the error is reported besides the grid
// itself, so a refinement fitted to the grid is not measured only where it was fitted.
GameSamples offsetGrid(const WantedDisplay& wanted, int k) {
    GameSamples samples(kSmashLutSize);
    const int m = (kSmashLutSize - 1) * k;
    samples.reserve(static_cast<std::size_t>(m) * m * m);
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r) {
                const glm::dvec3 s = (glm::dvec3(r, g, b) + 0.5) / static_cast<double>(m);
                samples.add(s, wanted(s));
            }
    return samples;
}

// The largest error between the samples of an m^3 grid (errors given per sample and channel,
// red fastest): along each axis, between two neighbouring samples a, b the error can peak where
// a kink sits (a clamp of the edit, the 8-bit steps of the LUT); its height is at most the two
// samples' mean plus half the steeper of the slopes just outside them times the spacing.
double peakBetween(const std::vector<double>& e, int m) {
    auto at = [&](int r, int g, int b, int c) {
        return e[3 * (static_cast<std::size_t>(r) +
                      static_cast<std::size_t>(m) * (g + static_cast<std::size_t>(m) * b)) +
                 static_cast<std::size_t>(c)];
    };
    double best = 0.0;
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r)
                for (int axis = 0; axis < 3; ++axis) {
                    int q[3] = {r, g, b};
                    if (q[axis] + 1 >= m)
                        continue;
                    for (int c = 0; c < 3; ++c) {
                        auto v = [&](int offset) {
                            int t[3] = {r, g, b};
                            t[axis] = std::clamp(q[axis] + offset, 0, m - 1);
                            return at(t[0], t[1], t[2], c);
                        };
                        const double ea = v(0), eb = v(1);
                        const double slope = std::max(std::fabs(ea - v(-1)), std::fabs(v(2) - eb));
                        best = std::max(best, 0.5 * (ea + eb) + 0.5 * slope);
                    }
                }
    return best;
}

// The error over the samples and, when given, the offset grid: the larger of each statistic
// (means over both together).
GameError reportOver(const GameSamples& a, const GameSamples* b, const Lut3D& lut, int nthreads) {
    const GameError ea = detail::gameErrorOver(a, lut, nthreads);
    if (!b)
        return ea;
    const GameError eb = detail::gameErrorOver(*b, lut, nthreads);
    GameError e = GameError::worst(ea, eb);
    e.count = ea.count + eb.count;
    e.meanSteps = (ea.meanSteps * double(ea.count) + eb.meanSteps * double(eb.count)) /
                  double(std::max<std::size_t>(1, e.count));
    return e;
}

GameSamples makeSamples(const WantedDisplay& wanted, const StageModel& stage,
                        const SmashAuthoringOptions& o, std::string& over) {
    GameSamples samples(kSmashLutSize);
    if (o.screenshot && !o.screenshot->empty()) {
        const ImageView& img = *o.screenshot;
        const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
        const std::size_t stride = std::max<std::size_t>(
            1, (pixels + o.maxSamples - 1) / std::max<std::size_t>(1, o.maxSamples));
        samples.reserve(pixels / stride + 1);
        for (std::size_t p = 0; p < pixels; p += stride) {
            const float* px =
                img.pixel(static_cast<int>(p % img.width), static_cast<int>(p / img.width));
            const glm::dvec3 d(detail::clampUnit(px[0]), detail::clampUnit(px[1]),
                               detail::clampUnit(px[2]));
            const glm::dvec3 s = inputForShown(d, stage, p);
            samples.add(s, wanted(s));
        }
        over = "the screenshot's " + std::to_string(samples.size()) + " pixels" +
               (stride > 1 ? " (every " + std::to_string(stride) + "th)" : std::string());
        return samples;
    }
    const int k = std::max(1, o.gridSubdivision);
    const int m = (kSmashLutSize - 1) * k + 1;
    samples.reserve(static_cast<std::size_t>(m) * m * m);
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / static_cast<double>(m - 1);
                samples.add(s, wanted(s));
            }
    over = "inputs on a " + std::to_string(m) + "^3 grid and its " + std::to_string(m - 1) +
           "^3 cell centres (" + std::to_string(k) + " per LUT cell)";
    return samples;
}

} // namespace

glm::dvec3 smashShownColour(const glm::dvec3& s, const Lut3D* gameLut, bool clip) {
    return StageModel(gameLut).shown(s, clip);
}

SmashAuthoringResult authorSmashLut(const WantedDisplay& wanted, const SmashAuthoringOptions& o) {
    SmashAuthoringResult res;
    const int n = kSmashLutSize;
    res.exact = Lut3D(n);
    res.lut = Lut3D(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / static_cast<double>(n - 1);
                const glm::dvec3 w = wanted(s);
                glm::vec3 entry, shipped;
                for (int c = 0; c < 3; ++c) {
                    const double l = detail::lutForShown(std::max(w[c], 0.0), s[c]);
                    const double lc = detail::clampUnit(l);
                    // The brighten step keeps 0.039% of s: black for a bright input needs L
                    // slightly below 0 (at most 0.1 8-bit steps); counted too.
                    if (std::fabs(l - lc) > 1e-6) {
                        ++res.clampedEntries;
                        res.clampedMax = std::max(res.clampedMax, std::fabs(l - lc));
                    }
                    entry[c] = static_cast<float>(l);
                    shipped[c] = static_cast<float>(lc);
                }
                res.exact.at(r, g, b) = entry;
                res.lut.at(r, g, b) = shipped;
            }
    if (!o.measure && !o.refine)
        return res;
    const StageModel stage(o.gameLut);
    const GameSamples samples = makeSamples(wanted, stage, o, res.measuredOver);
    std::optional<GameSamples> centres;
    if (!o.screenshot || o.screenshot->empty())
        centres = offsetGrid(wanted, std::max(1, o.gridSubdivision));
    const GameSamples* extra = centres ? &*centres : nullptr;
    const int m = (kSmashLutSize - 1) * std::max(1, o.gridSubdivision) + 1;
    auto report = [&](const Lut3D& lut) {
        GameError e = reportOver(samples, extra, lut, o.nthreads);
        if (extra) { // on a grid: what it can reach between its samples too
            std::vector<double> each;
            (void)detail::gameErrorOver(samples, lut, o.nthreads, &each);
            e.maxSteps = std::max(e.maxSteps, peakBetween(each, m));
        }
        return e;
    };
    res.exactError = report(quantized8(res.lut));
    if (o.refine) {
        Lut3D refined = detail::refineSmashLut(samples, res.exact, o.nthreads);
        GameError refinedError = report(refined);
        // a refinement that does not lower the mean error is no refinement: ship the exact one
        if (refinedError.meanSteps > res.exactError.meanSteps) {
            refined = quantized8(res.lut);
            refinedError = res.exactError;
        }
        res.lut = std::move(refined);
        res.refined = true;
        res.refinedError = refinedError;
    }
    return res;
}

SmashAuthoringResult authorSmashLutForEdit(const DisplayEdit& edit,
                                           const SmashAuthoringOptions& o) {
    const StageModel stage(o.gameLut);
    const bool clip = o.aboveWhite == AboveWhite::Clip;
    return authorSmashLut(
        [&](const glm::dvec3& s) {
            const glm::dvec3 d = stage.shown(s, false);
            glm::dvec3 dc;
            for (int c = 0; c < 3; ++c)
                dc[c] = detail::clampUnit(d[c]);
            const glm::dvec3 e(edit(glm::vec3(dc)));
            glm::dvec3 w;
            for (int c = 0; c < 3; ++c)
                w[c] = clip ? detail::clampUnit(e[c]) : e[c] + (d[c] - dc[c]);
            return w;
        },
        o);
}

SmashAuthoringResult authorSmashLutForEdit(const Lut3D& edit, Interpolation interp,
                                           const SmashAuthoringOptions& o) {
    if (edit.empty())
        throw Error("the edit LUT is empty");
    const StageModel stage(o.gameLut);
    const auto sampler = makeSampler(edit, interp);
    const glm::dvec3 lo(edit.domainMin()), hi(edit.domainMax());
    const bool clip = o.aboveWhite == AboveWhite::Clip;
    SmashAuthoringResult res = authorSmashLut(
        [&](const glm::dvec3& s) {
            const glm::dvec3 d = stage.shown(s, false);
            glm::dvec3 dc;
            for (int c = 0; c < 3; ++c)
                dc[c] = clip ? detail::clampUnit(d[c]) : std::clamp(d[c], lo[c], hi[c]);
            const glm::dvec3 e(sampler->sample(glm::vec3(dc)));
            glm::dvec3 w;
            for (int c = 0; c < 3; ++c)
                w[c] = clip ? detail::clampUnit(e[c]) : e[c] + (d[c] - dc[c]);
            return w;
        },
        o);
    const std::string title =
        !edit.title().empty() || !o.gameLut ? edit.title() : o.gameLut->title();
    res.exact.setTitle(title);
    res.lut.setTitle(title);
    return res;
}

} // namespace lut
