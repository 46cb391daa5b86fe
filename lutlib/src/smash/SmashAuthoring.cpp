// SPDX-License-Identifier: Apache-2.0
// The exact Smash composition, the colours it is measured over, the refinement; see
// lut/smash/SmashAuthoring.h.
#include "lut/smash/SmashAuthoring.h"

#include "lut/Error.h"
#include "lut/ErrorStats.h"
#include "lut/Math.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/smash/GameDisplay.h"
#include "lut/smash/SmashConstants.h"
#include "lut/smash/SmashGrading.h"
#include "smash/GameMeasure.h"
#include "smash/GameSamples.h"
#include "smash/SmashRefinement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace lut {

namespace {

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

// A wanted channel at or above this is white (float edits of white give 1 within 1e-7).
constexpr double kWhite = 1.0 - 1e-6;

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
                s[c] = lut::math::pow(detail::srgbDecodeUnit(d[c]), 1.0 / kSmashDecodeExponent) /
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

// Whether the refinement beats the exact composition on colours it was not fitted on: a lower
// mean (what it minimises) by at least the thousandth of a step the decision prints (a tie
// within rounding is no win, and would otherwise go either way with the compiler's rounding:
// -O1 and -O3 chose differently), no higher 99th percentile and no worse maximum (half a step
// of slack: both maxima are bounds). "" when it does, else why not (`where`: which colours).
constexpr double kMaxSlackSteps = 0.5;
constexpr double kMeanMarginSteps = 0.001;
std::string decide(const GameError& exact, const GameError& refined, const std::string& where) {
    char buf[240];
    if (!(refined.meanSteps <= exact.meanSteps - kMeanMarginSteps))
        std::snprintf(buf, sizeof buf, "its %s mean is not lower: %.3f vs %.3f", where.c_str(),
                      refined.meanSteps, exact.meanSteps);
    else if (refined.p99Steps > exact.p99Steps)
        std::snprintf(buf, sizeof buf, "its %s 99th percentile is higher: %.2f vs %.2f",
                      where.c_str(), roundUpDecimals(refined.p99Steps, 2),
                      roundUpDecimals(exact.p99Steps, 2));
    else if (refined.maxSteps > exact.maxSteps + kMaxSlackSteps)
        std::snprintf(buf, sizeof buf, "its %s maximum is higher: %.2f vs %.2f", where.c_str(),
                      roundUpDecimals(refined.maxSteps, 2), roundUpDecimals(exact.maxSteps, 2));
    else
        return {};
    return std::string("the exact composition: the refinement does not beat it (") + buf +
           " 8-bit steps)";
}

} // namespace

glm::dvec3 smashShownColour(const glm::dvec3& s, const Lut3D* gameLut, bool clip) {
    return StageModel(gameLut).shown(s, clip);
}

SmashAuthoringResult authorSmashLut(const WantedDisplay& wantedAsGiven,
                                    const SmashAuthoringOptions& o) {
    // What the game can show: the display clips at white (and shows nothing below black).
    const WantedDisplay wanted = [&wantedAsGiven](const glm::dvec3& s) {
        const glm::dvec3 w = wantedAsGiven(s);
        return glm::dvec3(detail::clampUnit(w.x), detail::clampUnit(w.y), detail::clampUnit(w.z));
    };
    const StageModel stage(o.gameLut);
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
                    double l = detail::lutForShown(w[c], s[c]);
                    // The rule above white (SmashAuthoring.h): every entry from l up shows white;
                    // the stage's own entry when it does (kept as it is: the file clamps it, and
                    // the game shows white either way).
                    bool kept = false;
                    if (w[c] >= kWhite) {
                        const double own = stage.lutOut(s)[c];
                        kept = own > l;
                        l = kept ? own : l;
                    }
                    const double lc = detail::clampUnit(l);
                    // The brighten step keeps 0.039% of s: black for a bright input needs L
                    // slightly below 0 (at most 0.1 8-bit steps); counted too.
                    if (!kept && std::fabs(l - lc) > 1e-6) {
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
    const Lut3D exact8 = quantized8(res.lut);
    const int k = std::max(1, o.gridSubdivision);
    Lut3D refined;
    if (o.screenshot && !o.screenshot->empty()) {
        const double clipS = o.gameLut ? 0.0 : 1.0 / static_cast<double>(kSmashBrightenScale);
        const detail::ShotColours colours(
            *o.screenshot, wanted,
            [&](const glm::dvec3& d, std::size_t p) { return inputForShown(d, stage, p); }, clipS);
        res.measuredOver = "the screenshot's " + std::to_string(colours.pixels()) + " pixels (" +
                           std::to_string(colours.distinct()) + " distinct colours" +
                           (clipS > 0.0 ? "; a channel shown white at every input that shows "
                                          "white"
                                        : "") +
                           ")";
        res.exactError = colours.error(exact8, false, o.nthreads);
        if (!o.refine)
            return res;
        res.refinementComputed = true;
        const detail::GameSamples train = colours.training(o.maxSamples, false);
        refined = detail::refineSmashLut(train, res.exact, o.nthreads);
        res.heldOutExact = colours.error(exact8, true, o.nthreads);
        res.heldOutRefined = colours.error(refined, true, o.nthreads);
        res.fittedOn = std::to_string(train.size()) + " pixels of " +
                       std::to_string(colours.distinct() - colours.heldOutColours()) +
                       " colours, checked on the other " +
                       std::to_string(colours.heldOutColours()) + " colours";
        res.decision = decide(res.heldOutExact, res.heldOutRefined, "held-out");
        if (res.decision.empty()) {
            // the held-out colours occur too: the LUT written is fitted on every colour, and
            // checked again over all of them
            refined =
                detail::refineSmashLut(colours.training(o.maxSamples, true), res.exact, o.nthreads);
            res.fittedOn += ", then refitted on all of them";
            res.refinedError = colours.error(refined, false, o.nthreads);
            res.decision = decide(res.exactError, res.refinedError, "refitted (over every pixel)");
        } else {
            res.refinedError = colours.error(refined, false, o.nthreads);
        }
    } else {
        res.exactError = detail::gameErrorEverywhere(wanted, exact8, k, o.nthreads);
        const int m = (kSmashLutSize - 1) * k;
        res.measuredOver = "every input (a bound from " + std::to_string(m * m * m) +
                           " held-out inputs between the points of a " + std::to_string(m + 1) +
                           "^3 grid, plus the slope between them; mean and p99 over those inputs)";
        if (!o.refine)
            return res;
        res.refinementComputed = true;
        refined = detail::refineSmashLut(detail::gridPoints(wanted, k), res.exact, o.nthreads);
        // the grid's cell centres are held out: mean and p99 there, the maximum over every input
        res.heldOutExact = res.exactError;
        res.heldOutRefined = detail::gameErrorEverywhere(wanted, refined, k, o.nthreads);
        res.refinedError = res.heldOutRefined;
        res.fittedOn = "the " + std::to_string(m + 1) + "^3 grid's points, checked on the " +
                       std::to_string(m * m * m) + " centres between them and every input";
        res.decision = decide(res.heldOutExact, res.heldOutRefined, "held-out");
    }
    res.refined = res.decision.empty();
    if (res.refined) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "mean %.3f -> %.3f, p99 %.2f -> %.2f, max %.2f -> %.2f",
                      res.heldOutExact.meanSteps, res.heldOutRefined.meanSteps,
                      roundUpDecimals(res.heldOutExact.p99Steps, 2),
                      roundUpDecimals(res.heldOutRefined.p99Steps, 2),
                      roundUpDecimals(res.heldOutExact.maxSteps, 2),
                      roundUpDecimals(res.heldOutRefined.maxSteps, 2));
        res.decision = std::string("the refinement: it beats the exact composition where it was "
                                   "not fitted (held-out ") +
                       buf + " 8-bit steps)";
        res.lut = std::move(refined);
    }
    return res;
}

SmashAuthoringResult authorSmashLutForEdit(const DisplayEdit& edit,
                                           const SmashAuthoringOptions& o) {
    const StageModel stage(o.gameLut);
    return authorSmashLut(
        [&](const glm::dvec3& s) { return glm::dvec3(edit(glm::vec3(stage.shown(s, true)))); }, o);
}

SmashAuthoringResult authorSmashLutForEdit(const Lut3D& edit, Interpolation interp,
                                           const SmashAuthoringOptions& o) {
    if (edit.empty())
        throw Error("the edit LUT is empty");
    const StageModel stage(o.gameLut);
    const auto sampler = makeSampler(edit, interp);
    SmashAuthoringResult res = authorSmashLut(
        [&](const glm::dvec3& s) {
            return glm::dvec3(sampler->sample(glm::vec3(stage.shown(s, true))));
        },
        o);
    const std::string title =
        !edit.title().empty() || !o.gameLut ? edit.title() : o.gameLut->title();
    res.exact.setTitle(title);
    res.lut.setTitle(title);
    return res;
}

} // namespace lut
