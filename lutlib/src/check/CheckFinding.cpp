// SPDX-License-Identifier: Apache-2.0
#include "lut/check/CheckFinding.h"

#include "lut/Parallel.h"
#include "lut/ops/Oklab.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut {

const char* toString(CheckKind kind) {
    switch (kind) {
    case CheckKind::Monotonicity:
        return "monotonicity";
    case CheckKind::Banding:
        return "banding";
    case CheckKind::Hue:
        return "hue";
    case CheckKind::Range:
        return "range";
    case CheckKind::Smoothness:
        return "smoothness";
    case CheckKind::Invertibility:
        return "invertibility";
    case CheckKind::Neutral:
        return "neutral";
    }
    return "?";
}

const char* toString(CheckStatus status) {
    switch (status) {
    case CheckStatus::Pass:
        return "pass";
    case CheckStatus::Warn:
        return "warn";
    case CheckStatus::Fail:
        return "fail";
    }
    return "?";
}

const char* toString(FindingKind kind) {
    switch (kind) {
    case FindingKind::FoldOver:
        return "fold-over";
    case FindingKind::Flat:
        return "flat";
    case FindingKind::Step:
        return "step";
    case FindingKind::Steep:
        return "steep";
    case FindingKind::HueShift:
        return "hue-shift";
    case FindingKind::SkinDrift:
        return "skin-drift";
    case FindingKind::NonFinite:
        return "non-finite";
    case FindingKind::OutOfRange:
        return "out-of-range";
    case FindingKind::Clip:
        return "clip";
    case FindingKind::Rough:
        return "rough";
    }
    return "?";
}

CheckKind checkOf(FindingKind kind) {
    switch (kind) {
    case FindingKind::FoldOver:
        return CheckKind::Monotonicity;
    case FindingKind::Flat:
    case FindingKind::Step:
    case FindingKind::Steep:
        return CheckKind::Banding;
    case FindingKind::HueShift:
    case FindingKind::SkinDrift:
        return CheckKind::Hue;
    case FindingKind::NonFinite:
    case FindingKind::OutOfRange:
    case FindingKind::Clip:
        return CheckKind::Range;
    case FindingKind::Rough:
        return CheckKind::Smoothness;
    }
    return CheckKind::Range;
}

const char* toString(SizeUnit unit) {
    switch (unit) {
    case SizeUnit::Steps8:
        return "8-bit steps";
    case SizeUnit::Slope:
        return "steps per input step";
    case SizeUnit::Degrees:
        return "degrees";
    case SizeUnit::Entries:
        return "entries";
    }
    return "";
}

bool FindingRegion::contains(glm::vec3 input) const {
    switch (type) {
    case Type::None:
        return false;
    case Type::Cells: {
        if (latticeSize < 2 || cells.empty())
            return false;
        const glm::vec3 x = shaper ? shaper->apply(input) : input;
        const int n = latticeSize - 1;
        int idx[3];
        for (int c = 0; c < 3; ++c) {
            const float u = (x[c] - domainMin[c]) / (domainMax[c] - domainMin[c]);
            idx[c] = std::isnan(u) ? 0 : std::clamp(static_cast<int>(u * n), 0, n - 1);
        }
        const auto cell = static_cast<std::uint32_t>(idx[0] + n * (idx[1] + n * idx[2]));
        return std::binary_search(cells.begin(), cells.end(), cell);
    }
    case Type::Hue: {
        const glm::vec3 v = (input - inputMin) / (inputMax - inputMin);
        const glm::dvec3 lab = srgbToOklab(glm::dvec3(v));
        return oklabChroma(lab) >= minChroma &&
               std::fabs(hueDifference(hueCentre, oklabHue(lab))) <= hueHalfWidth;
    }
    case Type::ChannelRange: {
        const float v = input[std::clamp(channel, 0, 2)];
        return v >= lo && v <= hi;
    }
    }
    return false;
}

std::vector<std::uint8_t> regionMask(const FindingRegion& region, const ImageView& image,
                                     int nthreads) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(std::max(0, image.width)) *
                                       static_cast<std::size_t>(std::max(0, image.height)),
                                   0);
    if (image.empty())
        return mask;
    parallelFor(image.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < image.width; ++x) {
                const float* p = image.pixel(x, y);
                mask[static_cast<std::size_t>(y) * image.width + x] =
                    region.contains(glm::vec3(p[0], p[1], p[2])) ? 1 : 0;
            }
    });
    return mask;
}

std::string CheckFinding::text(bool imageShare) const {
    char buf[512];
    const char* unitText = toString(unit);
    std::snprintf(buf, sizeof buf,
                  "%s %.3g %s%s%s at RGB (%.3f, %.3f, %.3f) -> (%.3f, %.3f, %.3f), %.2f%% of %s",
                  toString(kind), size, unitText, where.empty() ? "" : " ", where.c_str(), input.x,
                  input.y, input.z, output.x, output.y, output.z, 100.0 * share,
                  imageShare                  ? "the picture"
                  : unit == SizeUnit::Degrees ? "the hues"
                                              : "the cube");
    std::string s = buf;
    if (!detail.empty())
        s += ": " + detail;
    return s;
}

} // namespace lut
