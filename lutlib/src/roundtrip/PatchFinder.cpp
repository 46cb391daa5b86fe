// SPDX-License-Identifier: Apache-2.0
// Finding the patch by its marker frame: an exact run-length detector (lossless edits keep equal
// pixels equal), the same with noise tolerance, then an edge detector for softened or resized
// frames. Each candidate is confirmed by decoding the frame's header (MarkerFrame.h).
#include "lut/roundtrip/PatchFinder.h"

#include "lut/Error.h"
#include "roundtrip/ColourDistance.h"
#include "roundtrip/MarkerComb.h"
#include "roundtrip/MarkerFrame.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace lut {

namespace {

using detail::maxDiff;

// Per-channel tolerance for "the same colour": editors that dither when they convert 16 -> 8 bits
// move a value by a step or two; JPEG moves it more (the block average takes care of that).
constexpr float kSameTolerance = 2.5f / 255.0f;
// Smallest difference between the two symbols we accept (after an edit squeezed them together).
constexpr float kMinSeparation = 8.0f / 255.0f;
// Pixels either side in which the edge scan looks for a larger change (an edge's own ringing).
constexpr int kEdgeWindow = 12;
// A marker period at most this close to a whole number is whole (edge peaks jitter under JPEG;
// longer combs must come closer).
constexpr double kWholePeriod = 0.1;

glm::vec3 cellMean(const ImageView& img, int fx, int fy, int cell, int cx, int cy, bool& ok) {
    const int inset = cell >= 3 ? 1 : 0;
    const int x0 = fx + cx * cell + inset, y0 = fy + cy * cell + inset;
    const int n = cell - 2 * inset;
    if (x0 < 0 || y0 < 0 || x0 + n > img.width || y0 + n > img.height) {
        ok = false;
        return glm::vec3(0.0f);
    }
    double acc[3] = {0, 0, 0};
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float* p = img.pixel(x0 + x, y0 + y);
            for (int c = 0; c < 3; ++c)
                acc[c] += std::isfinite(p[c]) ? p[c] : 0.0f;
        }
    const double inv = 1.0 / (static_cast<double>(n) * n);
    return glm::vec3(static_cast<float>(acc[0] * inv), static_cast<float>(acc[1] * inv),
                     static_cast<float>(acc[2] * inv));
}

// Tries to read a frame whose top-left pixel is (fx, fy) with cells of `cell` pixels.
bool decodeFrame(const ImageView& img, int fx, int fy, int cell, float sameTol, float minSep,
                 PatchPlacement& out, double* score = nullptr) {
    double spread = 0.0; // how far the cells sit from their symbol, relative to the separation
    bool ok = true;
    // The two symbols, from the first cells of the outer top row.
    glm::vec3 sum[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};
    constexpr int kProbe = 20;
    std::array<glm::vec3, kProbe> top{};
    for (int cx = 0; cx < kProbe; ++cx) {
        top[cx] = cellMean(img, fx, fy, cell, cx, 0, ok);
        if (!ok)
            return false;
        sum[cx & 1] += top[cx];
    }
    const glm::vec3 a = sum[0] / float(kProbe / 2), b = sum[1] / float(kProbe / 2);
    const float sep = maxDiff(a, b);
    if (sep < minSep)
        return false;
    for (int cx = 0; cx < kProbe; ++cx)
        if (maxDiff(top[cx], (cx & 1) ? b : a) > std::max(sameTol, 0.2f * sep))
            return false;
    // 1 = the even-cell symbol (white when embedded), 0 = the odd one.
    auto bitAt = [&](int cx, int cy, int& bit) {
        const glm::vec3 v = cellMean(img, fx, fy, cell, cx, cy, ok);
        if (!ok)
            return false;
        const float da = maxDiff(v, a), db = maxDiff(v, b);
        if (std::min(da, db) > 0.25f * sep)
            return false;
        spread += std::min(da, db) / sep;
        bit = da < db ? 1 : 0;
        return true;
    };
    // The geometry bits sit on the inner ring's top row; they say how long the ring is. The sync
    // byte says which header version follows.
    detail::HeaderBits bits{};
    for (int i = 0; i < detail::kSyncBits; ++i)
        if (!bitAt(1 + i, 1, bits[i]))
            return false;
    const int version = detail::versionFromSync(bits);
    if (version == 0)
        return false;
    const int geometryBits = detail::geometryBitCount(version);
    const int totalBits = detail::headerBitCount(version);
    for (int i = detail::kSyncBits; i < geometryBits; ++i)
        if (!bitAt(1 + i, 1, bits[i]))
            return false;
    detail::MarkerHeader header;
    if (!detail::decodeGeometry(bits, header))
        return false;
    int cw = 0, ch = 0;
    try {
        detail::patchCells(header.layout, header.size, cw, ch);
    } catch (const Error&) {
        return false;
    }
    const int fw = cw + 4, fh = ch + 4;
    if (fw - 2 < geometryBits + 2)
        return false;
    if (static_cast<long long>(fx) + static_cast<long long>(fw) * cell > img.width ||
        static_cast<long long>(fy) + static_cast<long long>(fh) * cell > img.height || fx < 0 ||
        fy < 0)
        return false;
    const auto ring = detail::innerRing(fw, fh);
    if (static_cast<int>(ring.size()) < totalBits)
        return false;
    for (int i = geometryBits; i < totalBits; ++i)
        if (!bitAt(ring[i].first, ring[i].second, bits[i]))
            return false;
    if (!detail::decodeHeader(bits, header))
        return false;
    out.lattice = header.lattice;
    out.layout = header.layout;
    out.size = header.size;
    out.scale = header.scale;
    out.cell = cell;
    out.bitDepth = header.bitDepth;
    out.frameX = fx;
    out.frameY = fy;
    out.frameWidth = fw * cell;
    out.frameHeight = fh * cell;
    out.headerVersion = header.version;
    out.target = header.target;
    out.stageDigest = header.stageDigest;
    if (score)
        *score = spread;
    return true;
}

struct Run {
    int x;
    int len;
    glm::vec3 colour; // mean colour of the run
};

// Splits a row into runs of "the same colour": each pixel within `tol` of the run's mean so far
// (the mean, not the first pixel, so that noise does not end a run early).
void rowRuns(const ImageView& img, int y, float tol, std::vector<Run>& runs) {
    runs.clear();
    int x = 0;
    while (x < img.width) {
        const float* p0 = img.pixel(x, y);
        glm::dvec3 sum(p0[0], p0[1], p0[2]);
        int e = x + 1;
        while (e < img.width) {
            const float* p = img.pixel(e, y);
            const glm::vec3 mean(sum / double(e - x));
            if (maxDiff(glm::vec3(p[0], p[1], p[2]), mean) > tol)
                break;
            sum += glm::dvec3(p[0], p[1], p[2]);
            ++e;
        }
        runs.push_back({x, e - x, glm::vec3(sum / double(e - x))});
        x = e;
    }
}

// One pass of the exact detector: rows whose runs alternate between two colours with equal
// lengths (the outer ring's top row), then a header decode to confirm.
bool runScan(const ImageView& img, float tol, float minSep, PatchPlacement& out) {
    std::vector<Run> runs;
    std::map<std::pair<int, int>, int> lastSeen; // (x, cell) -> last row a candidate was seen
    for (int y = 0; y < img.height; ++y) {
        rowRuns(img, y, tol, runs);
        std::size_t i = 0;
        while (i < runs.size()) {
            const int k = runs[i].len;
            std::size_t j = i;
            while (j + 1 < runs.size() && runs[j + 1].len == k &&
                   maxDiff(runs[j + 1].colour, runs[j].colour) >= minSep &&
                   (j == i || maxDiff(runs[j + 1].colour, runs[j - 1].colour) <= 2 * tol))
                ++j;
            const std::size_t count = j - i + 1;
            if (count >= 16) {
                const auto key = std::make_pair(runs[i].x, k);
                auto it = lastSeen.find(key);
                const bool continuation = it != lastSeen.end() && it->second == y - 1;
                lastSeen[key] = y;
                // the first cell may have merged with a background of the same colour
                if (!continuation)
                    for (int fx : {runs[i].x, runs[i].x - k})
                        if (decodeFrame(img, fx, y, k, tol, minSep, out))
                            return true;
            }
            // a broken alternation may be where the real one starts
            i = j > i ? j : i + 1;
        }
    }
    return false;
}

// The tolerant detector, for frames whose cell edges were softened (blur, resampling): rows with
// >= 20 strong edges at nearly constant spacing whose middles alternate between two colours.
// A whole-number spacing is tried as a frame (cell centres survive a small blur); otherwise the
// spacing is returned as evidence that the image was resized.
double edgeScan(const ImageView& img, PatchPlacement& out, bool& found, detail::Comb& comb) {
    found = false;
    double scaledPeriod = 0.0;
    std::vector<double> edges;
    std::vector<float> diffs, localMax;
    std::map<std::pair<int, int>, int> lastSeen;
    for (int y = 0; y < img.height; ++y) {
        edges.clear();
        // Edges are the local maxima of the change between neighbours (a plateau counts once, at
        // its middle): a blurred or resampled edge spreads over pixels but peaks where it was.
        diffs.assign(static_cast<std::size_t>(img.width), 0.0f);
        for (int x = 1; x < img.width; ++x)
            diffs[x] = maxDiff(img.pixel(x, y), img.pixel(x - 1, y));
        // Only changes of at least 45% of the largest one nearby count: JPEG rings and blocks
        // around a marker edge, a much smaller change next to the edge's own.
        localMax.assign(diffs.size(), 0.0f);
        for (int x = 1; x < img.width; ++x) {
            float m = 0.0f;
            for (int k = std::max(1, x - kEdgeWindow);
                 k <= std::min(img.width - 1, x + kEdgeWindow); ++k)
                m = std::max(m, diffs[k]);
            localMax[x] = m;
        }
        for (int x = 1; x < img.width; ++x) {
            if (diffs[x] <= 6.0f / 255.0f || diffs[x] < 0.45f * localMax[x])
                continue;
            // values are quantised: "equal" changes may differ by float rounding
            constexpr float kPlateau = 1.0f / 255.0f;
            int e = x;
            while (e + 1 < img.width && std::fabs(diffs[e + 1] - diffs[x]) <= kPlateau)
                ++e;
            if (diffs[x - 1] < diffs[x] - kPlateau &&
                (e + 1 == img.width || diffs[e + 1] < diffs[x] - kPlateau))
                edges.push_back(0.5 * (x + e));
            x = e;
        }
        std::size_t i = 0;
        while (i + 2 < edges.size()) {
            const double g0 = edges[i + 1] - edges[i];
            if (g0 < 1.5) {
                ++i;
                continue;
            }
            std::size_t j = i + 1;
            while (j + 1 < edges.size() && std::fabs((edges[j + 1] - edges[j]) - g0) <= 1.01)
                ++j;
            if (!comb.seen && j - i >= 20) {
                const double p = (edges[j] - edges[i]) / static_cast<double>(j - i);
                if (std::fabs(p - std::round(p)) < kWholePeriod) {
                    comb.seen = true;
                    comb.y = y;
                    comb.cell = static_cast<int>(std::lround(p));
                    comb.edges.assign(edges.begin() + static_cast<std::ptrdiff_t>(i),
                                      edges.begin() + static_cast<std::ptrdiff_t>(j) + 1);
                }
            }
            // keep the part whose segment middles alternate between two colours (the middle half
            // of a segment, averaged: JPEG leaves noise on single pixels)
            auto mid = [&](std::size_t m) {
                const double a = edges[m], b = edges[m + 1], q = 0.25 * (b - a);
                const int x0 = static_cast<int>(std::ceil(a + q)),
                          x1 = std::max(x0, static_cast<int>(std::floor(b - q)));
                glm::dvec3 acc(0.0);
                for (int x = x0; x <= x1; ++x)
                    acc += glm::dvec3(img.pixel(x, y)[0], img.pixel(x, y)[1], img.pixel(x, y)[2]);
                return glm::vec3(acc / static_cast<double>(x1 - x0 + 1));
            };
            std::size_t end = i + 1;
            while (end + 1 <= j) {
                if (end >= i + 2) {
                    const float sep = maxDiff(mid(end), mid(end - 1));
                    if (sep < kMinSeparation ||
                        maxDiff(mid(end), mid(end - 2)) > std::max(12.0f / 255.0f, 0.25f * sep))
                        break;
                }
                ++end;
            }
            const std::size_t count = end - i;
            if (count >= 20) {
                j = end;
                const double period = (edges[j] - edges[i]) / static_cast<double>(count);
                // every gap within a pixel of a whole-number cell (JPEG moves an edge's peak by
                // a pixel); a resize leaves a fractional mean (3, 4, 3, 4: 3.5)
                const int cell = static_cast<int>(std::lround(period));
                // the comb's ends may each be a pixel off: over `count` cells that moves the
                // mean period by up to 1.5/count
                bool uniform = std::fabs(period - cell) <
                               std::min(kWholePeriod, std::max(0.02, 1.5 / double(count)));
                for (std::size_t k = i; k < j && uniform; ++k)
                    if (std::fabs(edges[k + 1] - edges[k] - cell) > 1.01)
                        uniform = false;
                if (uniform) {
                    const int e0 = static_cast<int>(std::lround(edges[i]));
                    const auto key = std::make_pair(e0, cell);
                    auto it = lastSeen.find(key);
                    const bool continuation = it != lastSeen.end() && it->second == y - 1;
                    lastSeen[key] = y;
                    // a soft edge leaves the cell phase uncertain by a pixel: keep the offset
                    // whose cells sit closest to their symbols
                    double bestScore = 1e30;
                    if (!continuation)
                        for (int dy = 0; dy <= std::min(cell, 2); ++dy)
                            for (int fx = e0 - 2 * cell - 1; fx <= e0 + 1; ++fx) {
                                PatchPlacement p;
                                double score = 0.0;
                                if (decodeFrame(img, fx, y - dy, cell, 12.0f / 255.0f,
                                                kMinSeparation, p, &score) &&
                                    score < bestScore) {
                                    bestScore = score;
                                    out = p;
                                    found = true;
                                }
                            }
                    if (found)
                        return period;
                } else if (scaledPeriod == 0.0) {
                    scaledPeriod = period;
                }
            }
            i = j;
        }
    }
    return scaledPeriod;
}

// How sharply the outer ring's checkerboard changes at the cell boundaries a frame at (fx, fy)
// would have: summed across the top row's cells (vertical boundaries) and down the left column
// (horizontal ones), each at the cells' middle line.
double boundaryEnergy(const ImageView& img, int fx, int fy, int cell, int fw, int fh) {
    double e = 0.0;
    auto diff = [&](int x0, int y0, int x1, int y1) {
        if (x0 < 0 || y0 < 0 || x1 < 0 || y1 < 0 || x0 >= img.width || x1 >= img.width ||
            y0 >= img.height || y1 >= img.height)
            return 0.0;
        return static_cast<double>(maxDiff(img.pixel(x0, y0), img.pixel(x1, y1)));
    };
    const int mid = cell / 2;
    for (int k = 1; k < fw; ++k)
        e += diff(fx + k * cell - 1, fy + mid, fx + k * cell, fy + mid);
    for (int k = 1; k < fh; ++k)
        e += diff(fx + mid, fy + k * cell - 1, fx + mid, fy + k * cell);
    return e;
}

// A frame found on a softened image (JPEG, blur) may be read a pixel off: the cells' middles
// still decode. Move it to where the checkerboard's boundaries are sharpest, if it decodes there.
void refinePhase(const ImageView& img, PatchPlacement& p) {
    const int cell = p.cell, fw = p.frameWidth / cell, fh = p.frameHeight / cell;
    if (cell < 3)
        return;
    double best = boundaryEnergy(img, p.frameX, p.frameY, cell, fw, fh);
    int bx = p.frameX, by = p.frameY;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const double e = boundaryEnergy(img, p.frameX + dx, p.frameY + dy, cell, fw, fh);
            if (e > best * 1.02) {
                best = e;
                bx = p.frameX + dx;
                by = p.frameY + dy;
            }
        }
    if (bx == p.frameX && by == p.frameY)
        return;
    PatchPlacement moved;
    if (decodeFrame(img, bx, by, cell, 12.0f / 255.0f, kMinSeparation, moved) &&
        moved.size == p.size && moved.layout == p.layout)
        p = moved;
}

} // namespace

FindResult findPatch(const ImageView& img) {
    FindResult result;
    if (img.empty()) {
        result.message = "the image is empty";
        return result;
    }
    PatchPlacement p;
    // Exact first (lossless edits keep equal pixels equal), then tolerant of noise and dither.
    bool found = runScan(img, kSameTolerance, kMinSeparation, p) ||
                 runScan(img, 10.0f / 255.0f, 30.0f / 255.0f, p);
    double period = 0.0;
    detail::Comb comb;
    if (!found)
        period = edgeScan(img, p, found, comb);
    if (found) {
        refinePhase(img, p);
        result.status = FindStatus::Found;
        result.placement = p;
        result.observedPeriod = static_cast<double>(p.cell);
        return result;
    }
    if (period > 0.0) {
        result.status = FindStatus::Scaled;
        result.observedPeriod = period;
        char buf[320];
        std::snprintf(
            buf, sizeof buf,
            "the patch markers were found with cells %.3g pixels wide, not a whole number: "
            "the image was resized after embedding. Undo the resize (or resize by a whole "
            "factor with nearest-neighbour) and extract again",
            period);
        result.message = buf;
        return result;
    }
    if (comb.seen && detail::diagnoseComb(img, comb, result))
        return result;
    result.message =
        "no LUT patch found: the marker frame is missing, cropped, painted over, blurred or "
        "resized past reading, or an edit mapped its black and white to the same colour";
    return result;
}

} // namespace lut
