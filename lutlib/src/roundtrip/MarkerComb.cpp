// SPDX-License-Identifier: Apache-2.0
// Why a comb of marker-like edges did not decode; see MarkerComb.h.
#include "roundtrip/MarkerComb.h"

#include "roundtrip/ColourDistance.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut::detail {

namespace {
// Smallest difference between the two symbols (as in PatchFinder.cpp).
constexpr float kMinSeparation = 8.0f / 255.0f;
} // namespace

// Why a comb of marker-like edges did not decode: soft edges (a blur) or noisy cells. Fills the
// result's message and cause; false when neither explains it.
bool diagnoseComb(const ImageView& img, const Comb& comb, FindResult& result) {
    const int cell = comb.cell, y = comb.y;
    auto px = [&](int x) {
        const float* p = img.pixel(std::clamp(x, 0, img.width - 1), y);
        return glm::dvec3(p[0], p[1], p[2]);
    };
    auto middle = [&](double a, double b, double& noise) {
        const double q = 0.25 * (b - a);
        const int x0 = static_cast<int>(std::ceil(a + q)),
                  x1 = std::max(x0, static_cast<int>(std::floor(b - q)));
        glm::dvec3 acc(0.0);
        for (int x = x0; x <= x1; ++x)
            acc += px(x);
        const glm::dvec3 m = acc / static_cast<double>(x1 - x0 + 1);
        double d2 = 0.0;
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec3 d = px(x) - m;
            d2 += (d.x * d.x + d.y * d.y + d.z * d.z) / 3.0;
        }
        noise = std::sqrt(d2 / static_cast<double>(x1 - x0 + 1)) * 255.0;
        return m;
    };
    std::vector<double> widths, noises;
    std::vector<glm::dvec3> middles;
    for (std::size_t k = 1; k < comb.edges.size(); ++k) {
        double n = 0.0;
        middles.push_back(middle(comb.edges[k - 1], comb.edges[k], n));
        noises.push_back(n);
    }
    for (std::size_t k = 1; k + 1 < comb.edges.size(); ++k) {
        const glm::dvec3 a = middles[k - 1], b = middles[k];
        const glm::dvec3 dir = b - a;
        const double dd = dir.x * dir.x + dir.y * dir.y + dir.z * dir.z;
        if (std::sqrt(dd / 3.0) < kMinSeparation / 2.0)
            continue;
        int w = 0;
        const int lo = static_cast<int>(std::floor(comb.edges[k] - cell / 2.0)),
                  hi = static_cast<int>(std::ceil(comb.edges[k] + cell / 2.0));
        for (int x = lo; x <= hi; ++x) {
            const glm::dvec3 d = px(x) - a;
            const double t = (d.x * dir.x + d.y * dir.y + d.z * dir.z) / dd;
            if (t > 0.1 && t < 0.9)
                ++w;
        }
        widths.push_back(w);
    }
    if (noises.empty())
        return false;
    // The two symbols' colours, and how many cells of the ring next to the comb (a cell above or
    // below) show one of them: nearly all on a sharp frame (the header's bits are the same two
    // colours), few once a blur has mixed the cells.
    glm::dvec3 sym[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
    int symN[2] = {0, 0};
    for (std::size_t k = 0; k < middles.size(); ++k) {
        sym[k & 1] += middles[k];
        ++symN[k & 1];
    }
    for (int i = 0; i < 2; ++i)
        sym[i] /= std::max(symN[i], 1);
    const double sep = maxDiff(glm::vec3(sym[0]), glm::vec3(sym[1]));
    double sharpShare = 0.0;
    for (int dir : {-1, 1}) {
        const int yy = y + dir * cell;
        if (yy < 0 || yy >= img.height)
            continue;
        int onSymbol = 0, cells = 0;
        for (std::size_t k = 1; k < comb.edges.size(); ++k, ++cells) {
            const int x = static_cast<int>(std::lround(0.5 * (comb.edges[k - 1] + comb.edges[k])));
            const float* q = img.pixel(std::clamp(x, 0, img.width - 1), yy);
            const glm::vec3 p(q[0], q[1], q[2]);
            if (std::min(maxDiff(p, glm::vec3(sym[0])), maxDiff(p, glm::vec3(sym[1]))) <= 0.2 * sep)
                ++onSymbol;
        }
        if (cells > 0)
            sharpShare = std::max(sharpShare, static_cast<double>(onSymbol) / cells);
    }
    auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    const double noise = cell >= 4 ? median(noises) : 0.0;
    const double width = widths.empty() ? 0.0 : median(widths);
    const int x0 = static_cast<int>(std::lround(comb.edges.front()));
    char where[160];
    std::snprintf(where, sizeof where, "a row of marker-like cells %d pixels wide at (%d, %d)",
                  cell, x0, y);
    char buf[700];
    if (noise > 4.0) {
        result.cause = EditCause::Noise;
        std::snprintf(buf, sizeof buf,
                      "no readable LUT patch: %s could not be decoded: its cells are noisy "
                      "(%.1f 8-bit steps RMS inside a cell): noise or film grain went over the "
                      "patch. Remove it there (add grain after extracting), or embed again at the "
                      "default --scale 8, whose cells average noise away",
                      where, noise);
    } else if (sharpShare < 0.6 || (cell >= 3 && width >= 2.0)) {
        result.cause = EditCause::Blur;
        std::snprintf(buf, sizeof buf,
                      "no readable LUT patch: %s could not be decoded: its cells are soft (%.0f%% "
                      "of the cells next to it are neither marker colour): the patch was "
                      "blurred, softened or resized with a smooth filter. Undo that over the "
                      "patch, or embed again at the default --scale 8, whose cells survive a "
                      "blur of 2 pixels",
                      where, 100.0 * (1.0 - sharpShare));
    } else {
        result.cause = EditCause::Unknown;
        std::snprintf(buf, sizeof buf,
                      "no LUT patch found: %s is sharp but its header does not read: the marker "
                      "frame was painted over or cut off, or an edit mapped its black and white "
                      "to the same colour",
                      where);
    }
    result.message = buf;
    return true;
}

} // namespace lut::detail
