// SPDX-License-Identifier: Apache-2.0
// The LUT check's hue measures: constant-hue ramps (fixed Oklab hue and lightness, chroma from
// grey to the sRGB gamut's edge) and the skin line through the LUT, and the hue they come out
// with.
#include "check/CheckDetail.h"

#include "lut/ops/Oklab.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut::check {

namespace {

constexpr int kHues = 72; // every 5 degrees
constexpr double kHueStep = 360.0 / kHues;
constexpr double kLightness[] = {0.40, 0.55, 0.70, 0.85, 0.95};
constexpr double kSaturation[] = {0.25, 0.40, 0.55, 0.70, 0.85, 1.00};
constexpr double kMinChroma = 0.02;  // below this a colour has no hue to speak of
constexpr double kLostChroma = 0.01; // an output this grey has lost its hue

bool inGamut(glm::dvec3 lab) {
    const glm::dvec3 l = oklabToLinearSrgb(lab);
    constexpr double e = 1e-9;
    return l.x >= -e && l.y >= -e && l.z >= -e && l.x <= 1.0 + e && l.y <= 1.0 + e &&
           l.z <= 1.0 + e;
}

// The largest chroma of hue h at lightness L inside the sRGB cube.
double maxChroma(double lightness, double hue) {
    double lo = 0.0, hi = 0.5;
    if (!inGamut(oklabFromLch(lightness, 0.0, hue)))
        return 0.0;
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (inGamut(oklabFromLch(lightness, mid, hue)) ? lo : hi) = mid;
    }
    return lo;
}

struct Named {
    double hue;
    const char* name;
};
// Oklab hues of the sRGB primaries and secondaries and of orange and purple between them.
constexpr Named kNames[] = {{29.2, "reds"},     {55.0, "oranges"},  {109.8, "yellows"},
                            {142.5, "greens"},  {194.8, "cyans"},   {264.1, "blues"},
                            {300.0, "purples"}, {328.4, "magentas"}};

const char* hueName(double hue) {
    const char* best = kNames[0].name;
    double d = 360.0;
    for (const Named& n : kNames)
        if (std::fabs(hueDifference(hue, n.hue)) < d) {
            d = std::fabs(hueDifference(hue, n.hue));
            best = n.name;
        }
    return best;
}

struct Sample {
    int hue = 0; // bin
    double inHue = 0.0, inChroma = 0.0;
    glm::vec3 input{0.0f};
    double shift = 0.0;
    bool lost = false;
};

glm::vec3 toDomain(const Context& ctx, glm::dvec3 srgb) {
    return ctx.inputMin() + (ctx.inputMax() - ctx.inputMin()) * glm::vec3(srgb);
}

// Runs the samples' inputs through the LUT and measures each one's hue shift.
void measure(const Context& ctx, std::vector<Sample>& samples) {
    std::vector<glm::vec3> colours;
    colours.reserve(samples.size());
    for (const Sample& s : samples)
        colours.push_back(toDomain(ctx, glm::dvec3(s.input)));
    ctx.evaluate(colours);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const glm::dvec3 lab = srgbToOklab(glm::dvec3(colours[i]));
        samples[i].lost = oklabChroma(lab) < kLostChroma;
        samples[i].shift = samples[i].lost ? 0.0 : hueDifference(samples[i].inHue, oklabHue(lab));
    }
}

std::string degrees(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.1f", v);
    return buf;
}

void skinDrift(const Context& ctx, std::vector<CheckFinding>& findings, CheckFigures& figures) {
    const Ray& skin = rays()[kSkinRay];
    std::vector<Sample> samples;
    constexpr int kPoints = 33;
    for (int i = 0; i < kPoints; ++i) {
        Sample s;
        s.input = skin.from + (skin.to - skin.from) * (static_cast<float>(i) / (kPoints - 1));
        const glm::dvec3 lab = srgbToOklab(glm::dvec3(s.input));
        s.inHue = oklabHue(lab);
        s.inChroma = oklabChroma(lab);
        samples.push_back(s);
    }
    measure(ctx, samples);
    double sum = 0.0, weight = 0.0, hueSum = 0.0;
    const Sample* worst = &samples.front();
    for (const Sample& s : samples) {
        if (s.lost)
            continue;
        sum += s.inChroma * s.shift;
        weight += s.inChroma;
        hueSum += s.inChroma * s.inHue;
        if (std::fabs(s.shift) > std::fabs(worst->shift))
            worst = &s;
    }
    if (weight <= 0.0)
        return;
    figures.skinDrift = sum / weight;
    const CheckStatus severity = grade(std::fabs(figures.skinDrift), ctx.thresholds().skinDrift);
    const double centre = hueSum / weight;
    double share = 0.0;
    for (int b = 0; b < kHues; ++b)
        if (std::fabs(hueDifference(centre, (b + 0.5) * kHueStep)) <= 15.0)
            share += ctx.hueWeights()[static_cast<std::size_t>(b)];
    if (severity == CheckStatus::Pass || (ctx.image() && share <= 0.0))
        return;
    CheckFinding f;
    f.kind = FindingKind::SkinDrift;
    f.severity = severity;
    f.where = "on the skin line";
    f.input = toDomain(ctx, glm::dvec3(worst->input));
    f.output = ctx.evaluate(f.input);
    f.size = std::fabs(figures.skinDrift);
    f.unit = SizeUnit::Degrees;
    f.share = share;
    f.detail = "skin tones turn " + degrees(figures.skinDrift) + " degrees on average (" +
               degrees(worst->shift) + " at worst)";
    f.region.type = FindingRegion::Type::Hue;
    f.region.hueCentre = centre;
    f.region.hueHalfWidth = 15.0;
    f.region.minChroma = kMinChroma;
    f.region.inputMin = ctx.inputMin();
    f.region.inputMax = ctx.inputMax();
    findings.push_back(std::move(f));
}

} // namespace

void checkHue(const Context& ctx, std::vector<CheckFinding>& findings, CheckFigures& figures) {
    std::vector<Sample> samples;
    for (int h = 0; h < kHues; ++h)
        for (double lightness : kLightness) {
            const double hue = (h + 0.5) * kHueStep; // the bin's centre
            const double cmax = maxChroma(lightness, hue);
            if (cmax < 1.5 * kMinChroma)
                continue;
            for (double sat : kSaturation) {
                Sample s;
                s.hue = h;
                const glm::dvec3 rgb =
                    glm::clamp(oklabToSrgb(oklabFromLch(lightness, sat * cmax, hue)), 0.0, 1.0);
                s.input = glm::vec3(rgb);
                const glm::dvec3 lab = srgbToOklab(glm::dvec3(s.input));
                s.inHue = oklabHue(lab);
                s.inChroma = oklabChroma(lab);
                if (s.inChroma >= kMinChroma)
                    samples.push_back(s);
            }
        }
    measure(ctx, samples);
    std::array<double, kHues> shift{}, weight{};
    std::array<const Sample*, kHues> worst{};
    for (const Sample& s : samples) {
        const auto b = static_cast<std::size_t>(s.hue);
        if (s.lost)
            continue;
        shift[b] += s.inChroma * s.shift;
        weight[b] += s.inChroma;
        if (!worst[b] || std::fabs(s.shift) > std::fabs(worst[b]->shift))
            worst[b] = &s;
    }
    double meanAbs = 0.0, meanWeight = 0.0;
    int worstBin = -1;
    for (int b = 0; b < kHues; ++b) {
        const auto k = static_cast<std::size_t>(b);
        if (weight[k] <= 0.0)
            continue;
        shift[k] /= weight[k];
        meanAbs += ctx.hueWeights()[k] * std::fabs(shift[k]);
        meanWeight += ctx.hueWeights()[k];
        if (ctx.image() && ctx.hueWeights()[k] <= 0.0)
            continue;
        if (worstBin < 0 ||
            std::fabs(shift[k]) > std::fabs(shift[static_cast<std::size_t>(worstBin)]))
            worstBin = b;
    }
    figures.meanHueShift = meanWeight > 0.0 ? meanAbs / meanWeight : 0.0;
    if (worstBin >= 0) {
        figures.worstHueShift = shift[static_cast<std::size_t>(worstBin)];
        figures.worstHue = (worstBin + 0.5) * kHueStep;
    }
    // Runs of neighbouring hues over the threshold, around the circle: one finding each.
    const Threshold& t = ctx.thresholds().hueShift;
    auto over = [&](int b) {
        const auto k = static_cast<std::size_t>((b % kHues + kHues) % kHues);
        return weight[k] > 0.0 && std::fabs(shift[k]) >= t.warn &&
               (!ctx.image() || ctx.hueWeights()[k] > 0.0);
    };
    int start = 0;
    while (start < kHues && over(start))
        ++start; // a run crossing 0 degrees starts after the first bin below the threshold
    if (start == kHues)
        start = 0;
    for (int i = 0; i < kHues;) {
        const int b0 = start + i;
        if (!over(b0)) {
            ++i;
            continue;
        }
        int len = 0;
        while (i < kHues && over(start + i)) {
            ++i;
            ++len;
        }
        int peak = b0;
        double share = 0.0;
        for (int k = 0; k < len; ++k) {
            const int b = (b0 + k) % kHues;
            share += ctx.hueWeights()[static_cast<std::size_t>(b)];
            if (std::fabs(shift[static_cast<std::size_t>(b)]) >
                std::fabs(shift[static_cast<std::size_t>(peak % kHues)]))
                peak = b;
        }
        peak %= kHues;
        const auto pk = static_cast<std::size_t>(peak);
        CheckFinding f;
        f.kind = FindingKind::HueShift;
        f.severity = grade(std::fabs(shift[pk]), t);
        const double from = (b0 % kHues + 0.5) * kHueStep;
        const double to = ((b0 + len - 1) % kHues + 0.5) * kHueStep;
        char where[96];
        std::snprintf(where, sizeof where, "%s (Oklab hue %.0f-%.0f)",
                      hueName((peak + 0.5) * kHueStep), from, to);
        f.where = where;
        // Where: the peak between the bins (a parabola through the three around it), on the
        // most colourful ramp of that hue at mid saturation, away from the gamut's edge.
        const double y0 = std::fabs(shift[static_cast<std::size_t>((peak + kHues - 1) % kHues)]);
        const double y1 = std::fabs(shift[pk]);
        const double y2 = std::fabs(shift[static_cast<std::size_t>((peak + 1) % kHues)]);
        const double curve = y0 - 2.0 * y1 + y2;
        const double offset = curve < 0.0 ? std::clamp(0.5 * (y0 - y2) / curve, -0.5, 0.5) : 0.0;
        const double peakHue = std::fmod((peak + 0.5 + offset) * kHueStep + 360.0, 360.0);
        double bestL = kLightness[0], bestC = 0.0;
        for (double lightness : kLightness)
            if (const double c = maxChroma(lightness, peakHue); c > bestC) {
                bestC = c;
                bestL = lightness;
            }
        f.input = toDomain(
            ctx, glm::clamp(oklabToSrgb(oklabFromLch(bestL, 0.55 * bestC, peakHue)), 0.0, 1.0));
        f.output = ctx.evaluate(f.input);
        f.size = std::fabs(shift[pk]);
        f.unit = SizeUnit::Degrees;
        f.share = share;
        char detail[128];
        std::snprintf(detail, sizeof detail,
                      "hue %.1f turns %s degrees on average over its ramps (%s at worst)", peakHue,
                      degrees(shift[pk]).c_str(), degrees(worst[pk]->shift).c_str());
        f.detail = detail;
        f.region.type = FindingRegion::Type::Hue;
        f.region.hueCentre = from + 0.5 * (len - 1) * kHueStep;
        f.region.hueHalfWidth = 0.5 * len * kHueStep;
        f.region.minChroma = kMinChroma;
        f.region.inputMin = ctx.inputMin();
        f.region.inputMax = ctx.inputMax();
        findings.push_back(std::move(f));
    }
    skinDrift(ctx, findings, figures);
}

} // namespace lut::check
