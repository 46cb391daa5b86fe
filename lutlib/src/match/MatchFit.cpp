// SPDX-License-Identifier: Apache-2.0
// Fitting the transfer by each method, and auto's choice: see lut/match/Match.h.
#include "core/Printf.h"
#include "lut/Error.h"
#include "lut/match/LutQuality.h"
#include "lut/match/Match.h"
#include "lut/match/MatchFinish.h"
#include "lut/match/WorkingSpace.h"
#include "match/CurveLook.h"
#include "match/MatchColours.h"
#include "match/MatchContext.h"
#include "match/MatchSamples.h"
#include "match/TransportFit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace lut {

namespace {

using detail::SampleSet;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

using detail::fmt;

void warn(Diagnostics& d, const std::string& path, const std::string& message) {
    Diagnostic w;
    w.severity = Diagnostic::Severity::Warning;
    w.path = path;
    w.message = message;
    d.push_back(std::move(w));
}

const char* channelName(int c) {
    return c == 0 ? "red" : c == 1 ? "green" : "blue";
}

// What the pictures are like, said before anything is fitted.
void pictureWarnings(const std::vector<detail::PictureFacts>& facts, bool isSource,
                     bool sourceLinear, bool stepsKept, Diagnostics& d) {
    for (const auto& f : facts) {
        const double share = static_cast<double>(f.outsideUnit) / (3.0 * f.used);
        if (!isSource && f.converted)
            warn(d, f.name,
                 std::string(sourceLinear ? "a display-encoded picture, decoded (sRGB) to match "
                                            "the source's scene-linear values"
                                          : "a scene-linear picture, sRGB-encoded to match the "
                                            "source's display values") +
                     (f.maxStored > 1.0 && !sourceLinear
                          ? fmt("; it holds values up to %.3g (HDR): %.3g%% of its values are "
                                "above 1, which the look takes as brighter than white and an "
                                "8-bit output clips",
                                f.maxStored, 100.0 * share)
                          : std::string()));
        else if (!isSource && !sourceLinear && share > 0.001)
            warn(d, f.name,
                 fmt("%.3g%% of its values are outside [0, 1] (colours beyond sRGB or brighter "
                     "than white, from %.3g to %.3g): the look asks for colours an 8-bit "
                     "output clips",
                     100.0 * share, f.minStored, f.maxStored));
        const double black = sourceLinear ? 1e-4 : 1.5 / 255.0;
        if (!isSource && f.maxStored < black)
            warn(d, f.name,
                 "the picture is black (every value below " +
                     std::string(sourceLinear ? "1e-4" : "1.5/255") +
                     "): the match makes everything nearly black");
        else if (f.distinct <= 16)
            warn(d, f.name,
                 stepsKept ? fmt("the picture has only %.0f distinct colours: a look with steps, "
                                 "which the gradient-map method keeps (the others make them into "
                                 "ramps, slopes limited)",
                                 static_cast<double>(f.distinct))
                           : fmt("the picture has only %.0f distinct colours: the match asks for "
                                 "steps, which the LUT makes into ramps (slopes limited)",
                                 static_cast<double>(f.distinct)));
        if (f.masked > 0 && f.used < 1000)
            warn(d, f.name,
                 fmt("only %.0f pixels are left after the mask: the statistics are thin",
                     static_cast<double>(f.used)));
    }
}

std::array<ChannelCurve, 3> matchChannels(const detail::ChannelStats& src,
                                          const detail::ChannelStats& ref, const MatchOptions& o,
                                          const char* stage, Diagnostics& d,
                                          double smoothingScale = 1.0, double atomOff = 0.0) {
    std::array<ChannelCurve, 3> curves;
    for (int c = 0; c < 3; ++c) {
        CurveLimits limits;
        limits.minSlope = o.minSlope;
        limits.maxSlope = o.maxSlope;
        limits.smoothing = src.smoothing[static_cast<std::size_t>(c)] * smoothingScale;
        if (atomOff > 0.0)
            limits.atomOff = atomOff;
        CurveNotes notes;
        curves[static_cast<std::size_t>(c)] =
            matchHistograms(src.histograms[static_cast<std::size_t>(c)],
                            ref.histograms[static_cast<std::size_t>(c)], limits, &notes);
        // Limits that bite on a visible share of the picture are worth a word; a few levels
        // next to a spike in a histogram are not.
        if (notes.slopeLimited && notes.limitedShare > 0.01)
            warn(d, "",
                 std::string(stage) + ", " + channelName(c) +
                     fmt(": the histogram match asks for slopes from %.3g to %.3g; limited to "
                         "[%.3g, %.3g] so the LUT stays smooth (%.3g%% of the source's pixels "
                         "are where it bites)",
                         notes.flattestAsked, notes.steepestAsked, o.minSlope, o.maxSlope,
                         100.0 * notes.limitedShare));
    }
    return curves;
}

// What keeps the transfer, tabulated (the size asked for, full strength), from being a LUT that
// never folds colours over and never goes down along a channel's own axis or along grey, as the
// report will measure it: "" when nothing does.
// greyDipOnly: the drop along grey when it is the only problem (else left as it was).
std::string shapeProblem(const LutFile& lut, const std::pair<glm::dvec3, glm::dvec3>& domain,
                         bool linear, double* greyDipOnly = nullptr) {
    const LutQuality shape =
        measureLutQuality(lut, linear, domain.first, domain.second, Interpolation::Tetrahedral);
    std::string problem;
    auto add = [&problem](const std::string& p) { problem += (problem.empty() ? "" : ", ") + p; };
    if (shape.foldedCells > 0)
        add(fmt("folds colours over in %zu of %zu cells", shape.foldedCells, shape.cells));
    if (shape.decreasingSteps > 0)
        add(fmt("goes down along a channel's own axis at %zu of %zu steps", shape.decreasingSteps,
                shape.steps));
    // Along grey, a drop of a quarter of an 8-bit step is invisible; more is a reversal.
    if (greyDipOnly && problem.empty())
        *greyDipOnly = shape.largestGreyDrop;
    if (shape.largestGreyDrop > 0.25)
        add(fmt("goes down along grey by %.3g 8-bit steps", shape.largestGreyDrop));
    return problem;
}

std::string shapeProblem(const MatchTransfer& t, const MatchOptions& o) {
    MatchOptions q;
    q.size = o.size;
    q.nthreads = o.nthreads;
    return shapeProblem(bakeMatch(t, q), {t.domainMin, t.domainMax}, t.linear);
}

// Folds or goes down along a channel's own axis: what auto's floor must not (a dip
// along grey is repaired on the table written, MatchLook.cpp).
bool foldsOrReverses(const LutFile& lut, const std::pair<glm::dvec3, glm::dvec3>& domain,
                     bool linear) {
    const LutQuality q =
        measureLutQuality(lut, linear, domain.first, domain.second, Interpolation::Tetrahedral);
    return q.foldedCells > 0 || q.decreasingSteps > 0;
}

bool cleanShape(const MatchTransfer& t, const MatchOptions& o) {
    return shapeProblem(t, o).empty();
}

// HM-MKL-HM's second histogram match is fitted twice: smoothed (the curve's Gaussian, as every
// curve) and sharp (no smoothing, the slope limits kept). The values after the MKL matrix are
// not 8-bit codes but 4096 bins over their range, where the smoothing spans 16 bins and rounds
// off the steps of the reference's distribution that a channel-mixing grade puts there: on such
// a grade (bench/match_looks.py, retina) the smoothed curve lands 1.49 / 6 8-bit steps from the
// truth, the sharp one 1.25 / 5, the plain numpy transfer 1.37 / 5. Taken everywhere, the sharp
// curve turned cells of the table over on 3 of the 12 pictures of that bench and moved p99 a
// step further on 2, sliced Wasserstein within 1-3% of the smoothed one's: it is kept only
// when its LUT neither folds nor goes down along a channel's axis and is at least 10% closer
// to the reference (kSharpCloser; retina: 16% closer).
constexpr double kSharpCloser = 0.9;

// The second match's atoms (CurveLimits::atomOff) moved when a tenth of an 8-bit step off: its
// output is the LUT's. Mix grade (bench/match_looks.py): letterbox 1.06 -> 0.81 mean, testsrc2
// 0.68 -> 0.47 mean; a fiftieth cost testsrc2 a step of p99; in the first match too, retina lost
// its sharp second match (1.25 / 5 -> 1.37 / 6).
constexpr double kSecondAtomOff = 0.1 / 255.0;

struct Fitted {
    MatchTransfer transfer;
    double seconds = 0.0;
};

} // namespace

int matchSampleStep(int width, int height, bool source, std::size_t references) {
    const double pixels = static_cast<double>(std::max(width, 0)) * std::max(height, 0);
    return detail::sampleStep(pixels, detail::maxSamples(source, references));
}

MatchFitResult fitMatch(const MatchPicture& source, const std::vector<MatchPicture>& references,
                        const MatchOptions& o, const Progress* progress) {
    return detail::fitMatch(source, references, o, nullptr, progress);
}

MatchFitResult detail::fitMatch(const MatchPicture& source,
                                const std::vector<MatchPicture>& references, const MatchOptions& o,
                                MatchContext* context, const Progress* progress) {
    const auto start = Clock::now();
    // Between steps: the fraction done, and a cancel stops the fit (the results never depend on
    // it).
    auto step = [progress](double fraction) {
        checkCancelled(progress, "match");
        reportProgress(progress, fraction);
    };
    if (references.empty())
        throw Error("match: no reference picture");
    if (o.size < 2 || o.size > 129)
        throw Error("match: the LUT size must be 2..129, not " + std::to_string(o.size));
    MatchFinish::fromOptions(o, source.linear).check();
    if (!(o.minSlope > 0.0) || !(o.maxSlope >= 1.0) || !(o.maxGain >= 1.0))
        throw Error("match: the slope and gain limits must be positive (max >= 1)");

    MatchFitResult res;
    MatchReport& rep = res.report;
    rep.asked = o.method;
    rep.linear = source.linear;
    rep.references = static_cast<int>(references.size());
    const bool linear = source.linear;
    std::vector<detail::PictureFacts> srcFacts, refFacts;
    SampleSet src = detail::collectSamples({&source}, linear, detail::maxSamples(true, 1), srcFacts,
                                           o.nthreads);
    step(0.1);
    std::vector<const MatchPicture*> refPtrs;
    for (const auto& r : references)
        refPtrs.push_back(&r);
    const SampleSet ref = detail::collectSamples(
        refPtrs, linear, detail::maxSamples(false, references.size()), refFacts, o.nthreads);
    step(0.2);
    rep.sourcePixels = srcFacts[0].pixels;
    rep.sourceUsed = srcFacts[0].used;
    for (const auto& f : refFacts) {
        rep.referencePixels += f.pixels;
        rep.referenceUsed += f.used;
    }
    // A reference that is a colour per luma (palette, gradient map, duotone, sepia): its steps
    // and its curve are the look (match/CurveLook.h).
    std::size_t refDistinct = 0;
    for (const auto& f : refFacts)
        refDistinct += f.distinct;
    const detail::CurveLook look = detail::detectCurveLook(ref, refDistinct);
    rep.look = look.onCurve ? look.kind : std::string();
    rep.lookRmsSteps = look.rmsSteps;
    const bool curveFit =
        o.method == MatchMethod::GradientMap || (o.method == MatchMethod::Auto && look.onCurve);
    pictureWarnings(srcFacts, true, linear, false, res.diagnostics);
    pictureWarnings(refFacts, false, linear, curveFit, res.diagnostics);

    // The domain: the source's range and at least [0, 1]; a scene-linear source gets a stop of
    // headroom above its brightest value.
    MatchTransfer shape;
    shape.linear = linear;
    for (int c = 0; c < 3; ++c) {
        double lo = 0.0, hi = 1.0;
        for (const auto& v : src.values) {
            lo = std::min(lo, decodeWorking(v[c], linear));
            hi = std::max(hi, decodeWorking(v[c], linear));
        }
        shape.domainMin[c] = lo;
        shape.domainMax[c] = linear && hi > 1.0 ? 2.0 * hi : hi;
    }

    const detail::ChannelStats srcStats =
        detail::channelStats(src.values, src.weights, src.codeAligned, o.nthreads);
    const detail::ChannelStats refStats =
        detail::channelStats(ref.values, ref.weights, ref.codeAligned, o.nthreads);
    const ColourMoments refMoments = detail::colourMoments(ref.values, ref.weights, o.nthreads);

    step(0.3);
    const bool all = o.method == MatchMethod::Auto;
    auto wants = [&](MatchMethod m) {
        return all || o.method == m ||
               (o.method == MatchMethod::Regularised && m == MatchMethod::HmMklHm);
    };
    std::vector<Fitted> fitted;
    Diagnostics hmNotes, mklNotes, hmmklNotes, regNotes;
    std::array<ChannelCurve, 3> h1;
    if (wants(MatchMethod::Hm) || wants(MatchMethod::HmMklHm)) {
        const auto t = Clock::now();
        h1 = matchChannels(srcStats, refStats, o, "HM", hmNotes);
        if (wants(MatchMethod::Hm)) {
            Fitted f{shape, 0.0};
            f.transfer.method = MatchMethod::Hm;
            f.transfer.pre = h1;
            f.seconds = secondsSince(t);
            fitted.push_back(std::move(f));
        }
    }
    auto mklWarning = [&](const MklNotes& n, Diagnostics& d) {
        if (n.gainLimited)
            warn(d, n.sourceSpread * 255.0 < 2.0 ? source.name : "",
                 fmt("the MKL map asks for colour gains from %.3g to %.3g; limited to [1/%.3g, "
                     "%.3g]",
                     n.smallestGain, n.largestGain, o.maxGain, o.maxGain) +
                     (n.sourceSpread * 255.0 < 2.0
                          ? fmt(" (the source is almost flat in some colour direction: spread "
                                "%.2g 8-bit steps; its noise would become colour)",
                                n.sourceSpread * 255.0)
                          : std::string()));
    };
    step(0.35);
    if (wants(MatchMethod::Mkl)) {
        const auto t = Clock::now();
        MklNotes notes;
        Fitted f{shape, 0.0};
        f.transfer.method = MatchMethod::Mkl;
        f.transfer.affine =
            mongeKantorovich(detail::colourMoments(src.values, src.weights, o.nthreads), refMoments,
                             o.maxGain, 1e-10, &notes);
        mklWarning(notes, mklNotes);
        f.seconds = secondsSince(t);
        fitted.push_back(std::move(f));
    }
    std::vector<glm::vec3> lattice;                       // u = h1(w) of the source samples
    std::optional<std::array<ChannelCurve, 3>> sharpPost; // HM-MKL-HM's sharp second match
    std::optional<Diagnostics> sharpNotes;
    step(0.4);
    if (wants(MatchMethod::HmMklHm)) {
        const auto t = Clock::now();
        Fitted f{shape, 0.0};
        f.transfer.method = MatchMethod::HmMklHm;
        f.transfer.pre = h1;
        lattice = detail::mapValues(
            src.values,
            [&h1](const glm::dvec3& w) { return glm::dvec3(h1[0](w.x), h1[1](w.y), h1[2](w.z)); },
            o.nthreads);
        MklNotes notes;
        f.transfer.affine =
            mongeKantorovich(detail::colourMoments(lattice, src.weights, o.nthreads), refMoments,
                             o.maxGain, 1e-10, &notes);
        mklWarning(notes, hmmklNotes);
        const AffineColourMap a = f.transfer.affine;
        const std::vector<glm::vec3> mixed = detail::mapValues(
            lattice, [&a](const glm::dvec3& u) { return a(u); }, o.nthreads);
        const detail::ChannelStats mixedStats =
            detail::channelStats(mixed, src.weights, false, o.nthreads);
        if (!look.onCurve) {
            sharpNotes = hmmklNotes;
            sharpPost = matchChannels(mixedStats, refStats, o, "HM after MKL", *sharpNotes, 0.0,
                                      kSecondAtomOff);
        }
        f.transfer.post =
            matchChannels(mixedStats, refStats, o, "HM after MKL", hmmklNotes, 1.0, kSecondAtomOff);
        f.seconds = secondsSince(t) + (fitted.empty() ? 0.0 : fitted.front().seconds);
        fitted.push_back(std::move(f));
    }
    step(0.5);
    if (curveFit) {
        const auto t = Clock::now();
        Fitted f{shape, 0.0};
        f.transfer.method = MatchMethod::GradientMap;
        detail::fitGradientMap(src, ref, f.transfer);
        f.seconds = secondsSince(t);
        fitted.push_back(std::move(f));
    }
    if (wants(MatchMethod::Regularised) && !(all && look.onCurve)) {
        const auto t = Clock::now();
        const MatchTransfer& baseTransfer =
            std::find_if(fitted.begin(), fitted.end(), [](const Fitted& x) {
                return x.transfer.method == MatchMethod::HmMklHm;
            })->transfer;
        Fitted f{baseTransfer, 0.0};
        f.transfer.method = MatchMethod::Regularised;
        detail::TransportFitOptions to;
        to.size = std::min(o.size, 17);
        to.minSlope = o.minSlope;
        to.nthreads = o.nthreads;
        SampleSet thin;
        thin.values = lattice;
        thin.weights = src.weights;
        thin = detail::thinSamples(thin, 1 << 16);
        const SampleSet refThin = detail::thinSamples(ref, 1 << 16);
        const std::vector<glm::vec3> startValues = detail::mapValues(
            thin.values, [&](const glm::dvec3& u) { return baseTransfer.workingOutput(u); },
            o.nthreads);
        f.transfer.residualMin = baseTransfer.toLattice(shape.domainMin);
        f.transfer.residualMax = baseTransfer.toLattice(shape.domainMax);
        const auto r = detail::fitTransport(
            thin.values, thin.weights, startValues, refThin, f.transfer.residualMin,
            f.transfer.residualMax,
            [&](const glm::dvec3& u) { return baseTransfer.workingOutput(u); }, to);
        f.transfer.residualSize = r.size;
        f.transfer.residual = r.residual;
        // The correction may bend the table where the base map is steep; it is scaled down until
        // the LUT neither folds nor goes down along a channel's axis or grey (0 = HM-MKL-HM).
        double scale = 1.0;
        while (scale > 0.0 && !cleanShape(f.transfer, o)) {
            scale = scale > 0.1 ? scale * 0.5 : 0.0;
            for (std::size_t i = 0; i < r.residual.size(); ++i)
                f.transfer.residual[i] = r.residual[i] * static_cast<float>(scale);
        }
        if (scale < 1.0)
            warn(regNotes, "",
                 fmt("the regularised correction is scaled to %.3g%% so the LUT does not fold "
                     "colours over",
                     100.0 * scale));
        f.seconds = secondsSince(t);
        fitted.push_back(std::move(f));
    }

    step(0.8);
    // Every candidate judged by what the user will see: its LUT (the size asked for, full
    // strength, shaper and table, tetrahedral) applied to SOURCE, against the reference, and
    // the LUT's shape.
    const SampleSet srcThin = detail::thinSamples(src, 1 << 15);
    const SampleSet refThin = detail::thinSamples(ref, 1 << 15);
    const ColourDistribution refDist(detail::labOfWorking(refThin.values, linear, o.nthreads),
                                     refThin.weights, o.nthreads);
    const ColourDistribution srcDist(detail::labOfWorking(srcThin.values, linear, o.nthreads),
                                     srcThin.weights, o.nthreads);
    std::vector<glm::vec3> thinStored(srcThin.values.size());
    for (std::size_t i = 0; i < thinStored.size(); ++i)
        for (int c = 0; c < 3; ++c)
            thinStored[i][c] = static_cast<float>(decodeWorking(srcThin.values[i][c], linear));
    rep.before = distributionDistance(srcDist, refDist);
    std::vector<std::size_t> candidateOf; // rep.candidates[k] is fitted[candidateOf[k]]
    std::vector<double> floorDip;
    // A transfer's LUT (the size asked for, full strength) and its distance to the reference.
    auto judge = [&](const MatchTransfer& t, DistributionDistance& after) {
        MatchOptions q;
        q.size = o.size;
        q.nthreads = o.nthreads;
        LutFile lut = bakeMatch(t, q);
        const LutFileSampler sampler(lut, Interpolation::Tetrahedral);
        const std::vector<glm::vec3> out = detail::mapValues(
            thinStored, [&](const glm::dvec3& x) { return glm::dvec3(sampler(glm::vec3(x))); },
            o.nthreads);
        after =
            distributionDistance(ColourDistribution(detail::labOfStored(out, linear, o.nthreads),
                                                    srcThin.weights, o.nthreads),
                                 refDist);
        return lut;
    };
    for (std::size_t i = 0; i < fitted.size(); ++i) {
        Fitted& f = fitted[i];
        if (!all && f.transfer.method != o.method)
            continue;
        step(0.85 + 0.15 * static_cast<double>(i) / static_cast<double>(fitted.size()));
        MatchCandidate c;
        c.method = f.transfer.method;
        c.seconds = f.seconds;
        LutFile lut = judge(f.transfer, c.after);
        // HM-MKL-HM's sharp second match (kSharpCloser): kept when its LUT is clean and closer.
        if (c.method == MatchMethod::HmMklHm && sharpPost) {
            MatchTransfer sharp = f.transfer;
            sharp.post = *sharpPost;
            DistributionDistance after;
            LutFile sharpLut = judge(sharp, after);
            if (after.slicedWasserstein < kSharpCloser * c.after.slicedWasserstein &&
                !foldsOrReverses(sharpLut, {shape.domainMin, shape.domainMax}, linear)) {
                f.transfer = std::move(sharp);
                c.after = after;
                lut = std::move(sharpLut);
                hmmklNotes = std::move(*sharpNotes);
                rep.sharpSecondMatch = true;
            }
        }
        // A gradient map is a colour per luma: flat across hue by design, its steps the look.
        double dip = INFINITY; // the floor's grey dip when it is its only problem
        if (all && c.method != MatchMethod::GradientMap)
            c.shapeProblem = shapeProblem(lut, {shape.domainMin, shape.domainMax}, linear, &dip);
        floorDip.push_back(dip);
        rep.candidates.push_back(c);
        candidateOf.push_back(i);
    }
    // The choice. HM-MKL-HM is the floor: eligible with a dip along grey (reported: a dip is no
    // reason to fall back to a method 2-3x further from the reference, as measured on outside
    // looks, bench/match_looks.py); a LUT that folds or goes down along a channel's axis is not.
    // Another candidate replaces it only when its LUT is clean (or a gradient map) and closer to
    // the reference by a margin (kCloser): the distance is a sampled measure of the distributions,
    // and a method that only ties it is not worth the risk. When nothing is eligible, every
    // candidate is.
    constexpr double kCloser = 0.9;
    std::size_t chosen = 0;
    if (all) {
        bool any = false;
        for (std::size_t i = 0; i < rep.candidates.size(); ++i) {
            auto& c = rep.candidates[i];
            c.eligible = c.shapeProblem.empty() ||
                         (c.method == MatchMethod::HmMklHm && std::isfinite(floorDip[i]));
            any = any || c.eligible;
        }
        if (!any)
            for (auto& c : rep.candidates)
                c.eligible = true;
        // hm and mkl are special cases of HM-MKL-HM (identity curves, identity matrix): a
        // sampled distance that favours them over an eligible floor is not worth its risk
        // (measured: mkl 10% closer by the distance, p99 twice the floor's from the truth).
        bool floorEligible = false;
        for (const auto& c : rep.candidates)
            floorEligible = floorEligible || (c.method == MatchMethod::HmMklHm && c.eligible);
        double best = INFINITY;
        for (std::size_t i = 0; i < rep.candidates.size(); ++i) {
            const auto& c = rep.candidates[i];
            if (floorEligible && (c.method == MatchMethod::Hm || c.method == MatchMethod::Mkl))
                continue;
            const double d = c.method == MatchMethod::HmMklHm ? c.after.slicedWasserstein * kCloser
                                                              : c.after.slicedWasserstein;
            if (c.eligible && d < best) {
                best = d;
                chosen = i;
            }
        }
        rep.choice = fmt("auto: hm-mkl-hm (the floor) unless the regularised or gradient-map "
                         "LUT is clean and at least %.0f%% closer to the reference; chosen at "
                         "sliced Wasserstein %.3g",
                         100.0 * (1.0 - kCloser), rep.candidates[chosen].after.slicedWasserstein);
    } else {
        rep.choice = "asked for";
    }
    const MatchMethod m = rep.candidates[chosen].method;
    res.transfer = fitted[candidateOf[chosen]].transfer;
    rep.method = m;
    // The warnings of the parts the chosen method uses.
    const Diagnostics* parts[3] = {&hmNotes, &mklNotes, &hmmklNotes};
    const bool use[3] = {
        m == MatchMethod::Hm || m == MatchMethod::HmMklHm || m == MatchMethod::Regularised,
        m == MatchMethod::Mkl, m == MatchMethod::HmMklHm || m == MatchMethod::Regularised};
    for (int i = 0; i < 3; ++i)
        if (use[i])
            res.diagnostics.insert(res.diagnostics.end(), parts[i]->begin(), parts[i]->end());
    rep.secondsFit = secondsSince(start);
    if (context) {
        context->reference = refDist;
        context->source = std::move(src);
    }
    return res;
}

} // namespace lut
