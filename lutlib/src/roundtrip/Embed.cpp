// Embed / find / extract a neutral LUT patch in a screenshot. Design notes in Embed.h and
// docs/roundtrip.md; the Smash compensation follows docs/specs/smash-pipeline.md.
#include "lut/roundtrip/Embed.h"

#include "lut/Limits.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/Resample.h"
#include "lut/pipeline/SmashGrading.h"

#include "interp/Tetrahedral.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

namespace lut {

namespace {

// --- Smash pipeline formulas (smash-pipeline.md section 2 and 3) -----------------------------
// Kept here in double precision: extract runs them once per lattice point, and they double as
// the reference the tests check the shared pipeline against.
constexpr double kBrightenMix = 0.99961;
constexpr double kBrightenScale = 1.3703;
constexpr double kGammaDecode = 2.2;

double srgbEnc(double x) {
    if (!(x > 0.0))
        return 0.0;
    if (x >= 1.0)
        return 1.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}
double srgbDec(double v) {
    if (!(v > 0.0))
        return 0.0;
    if (v >= 1.0)
        return 1.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double clamp01(double v) {
    return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
} // NaN -> 0

// What the game displays (display-encoded, clamped) for the gamma-space input s when its LUT
// returned lutOut at s.
double gameShown(double lutOut, double s) {
    const double r = ((lutOut - s) * kBrightenMix + s) * kBrightenScale;
    return srgbEnc(clamp01(std::pow(std::max(r, 0.0), kGammaDecode)));
}
// --- Header -----------------------------------------------------------------------------------
constexpr std::uint32_t kSync = 0xB2;
constexpr int kHeaderBits = 35;
constexpr int kGeometryBits = 22; // sync + lattice + depth + layout + size: enough to know the ring
constexpr int kPayloadBits = 27;  // everything before the CRC
constexpr int kMinHeaderRow = kGeometryBits + 2;

std::uint8_t crc8(std::uint32_t value, int bits) {
    std::uint8_t crc = 0;
    for (int i = bits - 1; i >= 0; --i) {
        const bool bit = ((value >> i) & 1u) != 0;
        const bool top = (crc & 0x80u) != 0;
        crc = static_cast<std::uint8_t>(crc << 1);
        if (bit != top)
            crc ^= 0x07u;
    }
    return crc;
}

int depthCode(int bitDepth) {
    return bitDepth == 8 ? 0 : bitDepth == 16 ? 1 : 2;
}
int depthFromCode(int code) {
    return code == 0 ? 8 : code == 1 ? 16 : 32;
}
int layoutCode(LutLayout l) {
    switch (l) {
    case LutLayout::Pilot:
        return 0;
    case LutLayout::Unity:
        return 1;
    case LutLayout::Smush:
        return 2;
    case LutLayout::Hald:
        return 3;
    }
    return 0;
}
LutLayout layoutFromCode(int c) {
    static const LutLayout ls[4] = {LutLayout::Pilot, LutLayout::Unity, LutLayout::Smush,
                                    LutLayout::Hald};
    return ls[c & 3];
}

std::array<int, kHeaderBits> headerBits(PatchLattice lattice, int bitDepth, LutLayout layout,
                                        int size, int scale) {
    std::uint32_t v = kSync;
    v = (v << 1) | (lattice == PatchLattice::Smash ? 1u : 0u);
    v = (v << 2) | static_cast<std::uint32_t>(depthCode(bitDepth));
    v = (v << 2) | static_cast<std::uint32_t>(layoutCode(layout));
    v = (v << 9) | static_cast<std::uint32_t>(size & 511);
    v = (v << 5) | static_cast<std::uint32_t>(scale & 31);
    const std::uint8_t crc = crc8(v, kPayloadBits);
    std::array<int, kHeaderBits> bits{};
    for (int i = 0; i < kPayloadBits; ++i)
        bits[i] = static_cast<int>((v >> (kPayloadBits - 1 - i)) & 1u);
    for (int i = 0; i < 8; ++i)
        bits[kPayloadBits + i] = (crc >> (7 - i)) & 1;
    return bits;
}

// Cells of the inner ring, clockwise from the top-left inner corner, in frame cell coordinates
// (the frame is fw x fh cells, the outer ring at 0 and fw-1 / fh-1).
std::vector<std::pair<int, int>> innerRing(int fw, int fh) {
    std::vector<std::pair<int, int>> cells;
    for (int x = 1; x <= fw - 2; ++x)
        cells.emplace_back(x, 1);
    for (int y = 2; y <= fh - 2; ++y)
        cells.emplace_back(fw - 2, y);
    for (int x = fw - 3; x >= 1; --x)
        cells.emplace_back(x, fh - 2);
    for (int y = fh - 3; y >= 2; --y)
        cells.emplace_back(1, y);
    return cells;
}

void patchCells(LutLayout layout, int size, int& cw, int& ch) {
    layoutImageSize(layout, size, cw, ch);
}

float maxDiff(const float* a, const float* b) {
    return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
}
float maxDiff(glm::vec3 a, glm::vec3 b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

// Per-channel tolerance for "the same colour": editors that dither when they convert 16 -> 8 bits
// move a value by a step or two; JPEG moves it more (the block average takes care of that).
constexpr float kSameTolerance = 2.5f / 255.0f;
// Smallest difference between the two symbols we accept (after an edit squeezed them together).
constexpr float kMinSeparation = 8.0f / 255.0f;

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
    std::array<int, kHeaderBits> bits{};
    for (int i = 0; i < kGeometryBits; ++i)
        if (!bitAt(1 + i, 1, bits[i]))
            return false;
    std::uint32_t v = 0;
    for (int i = 0; i < kGeometryBits; ++i)
        v = (v << 1) | static_cast<std::uint32_t>(bits[i]);
    if ((v >> 14) != kSync)
        return false;
    const PatchLattice lattice = ((v >> 13) & 1u) ? PatchLattice::Smash : PatchLattice::Uniform;
    const int depth = static_cast<int>((v >> 11) & 3u);
    const LutLayout layout = layoutFromCode(static_cast<int>((v >> 9) & 3u));
    const int size = static_cast<int>(v & 511u);
    if (depth == 3 || size < limits::kMin3DSize || size > limits::kMax3DSize)
        return false;
    if (lattice == PatchLattice::Smash && size != kSmashLatticeSize)
        return false;
    int cw = 0, ch = 0;
    try {
        patchCells(layout, size, cw, ch);
    } catch (const Error&) {
        return false;
    }
    const int fw = cw + 4, fh = ch + 4;
    if (fw - 2 < kMinHeaderRow)
        return false;
    if (static_cast<long long>(fx) + static_cast<long long>(fw) * cell > img.width ||
        static_cast<long long>(fy) + static_cast<long long>(fh) * cell > img.height || fx < 0 ||
        fy < 0)
        return false;
    const auto ring = innerRing(fw, fh);
    for (int i = kGeometryBits; i < kHeaderBits; ++i)
        if (!bitAt(ring[i].first, ring[i].second, bits[i]))
            return false;
    std::uint32_t all = 0;
    for (int i = 0; i < kPayloadBits; ++i)
        all = (all << 1) | static_cast<std::uint32_t>(bits[i]);
    std::uint32_t crc = 0;
    for (int i = kPayloadBits; i < kHeaderBits; ++i)
        crc = (crc << 1) | static_cast<std::uint32_t>(bits[i]);
    if (crc8(all, kPayloadBits) != crc)
        return false;
    const int scale = static_cast<int>(all & 31u);
    if (scale < 1)
        return false;
    out.lattice = lattice;
    out.layout = layout;
    out.size = size;
    out.scale = scale;
    out.cell = cell;
    out.bitDepth = depthFromCode(depth);
    out.frameX = fx;
    out.frameY = fy;
    out.frameWidth = fw * cell;
    out.frameHeight = fh * cell;
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
double edgeScan(const ImageView& img, PatchPlacement& out, bool& found) {
    found = false;
    double scaledPeriod = 0.0;
    std::vector<double> edges;
    std::vector<float> diffs;
    std::map<std::pair<int, int>, int> lastSeen;
    for (int y = 0; y < img.height; ++y) {
        edges.clear();
        // Edges are the local maxima of the change between neighbours (a plateau counts once, at
        // its middle): a blurred or resampled edge spreads over pixels but peaks where it was.
        diffs.assign(static_cast<std::size_t>(img.width), 0.0f);
        for (int x = 1; x < img.width; ++x)
            diffs[x] = maxDiff(img.pixel(x, y), img.pixel(x - 1, y));
        for (int x = 1; x < img.width; ++x) {
            if (diffs[x] <= 6.0f / 255.0f)
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
            // keep the part whose segment middles alternate between two colours
            auto mid = [&](std::size_t m) {
                return img.pixel(static_cast<int>((edges[m] + edges[m + 1]) * 0.5), y);
            };
            std::size_t end = i + 1;
            while (end + 1 <= j &&
                   (end < i + 2 || (maxDiff(mid(end), mid(end - 2)) <= 12.0f / 255.0f &&
                                    maxDiff(mid(end), mid(end - 1)) >= kMinSeparation)))
                ++end;
            const std::size_t count = end - i;
            if (count >= 20) {
                j = end;
                const bool alternates = true;
                if (alternates) {
                    const double period = (edges[j] - edges[i]) / static_cast<double>(count);
                    bool uniform = true;
                    for (std::size_t k = i; k < j; ++k)
                        if (std::fabs(edges[k + 1] - edges[k] - period) > 1e-9)
                            uniform = false;
                    const int cell = static_cast<int>(std::lround(period));
                    if (uniform && std::fabs(period - cell) < 1e-6) {
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
            }
            i = j;
        }
    }
    return scaledPeriod;
}

} // namespace

// ------------------------------------------------------------------------------------------------

const char* toString(PatchCorner c) {
    switch (c) {
    case PatchCorner::TopLeft:
        return "top-left";
    case PatchCorner::TopRight:
        return "top-right";
    case PatchCorner::BottomLeft:
        return "bottom-left";
    case PatchCorner::BottomRight:
        return "bottom-right";
    }
    return "?";
}

PatchCorner parseCorner(std::string_view name) {
    if (name == "top-left")
        return PatchCorner::TopLeft;
    if (name == "top-right")
        return PatchCorner::TopRight;
    if (name == "bottom-left")
        return PatchCorner::BottomLeft;
    if (name == "bottom-right")
        return PatchCorner::BottomRight;
    throw Error("unknown corner '" + std::string(name) +
                "' (expected top-left, top-right, bottom-left or bottom-right)");
}

const char* toString(PatchLattice l) {
    return l == PatchLattice::Smash ? "smash" : "uniform";
}
PatchLattice parseLattice(std::string_view name) {
    if (name == "smash")
        return PatchLattice::Smash;
    if (name == "uniform")
        return PatchLattice::Uniform;
    throw Error("unknown lattice '" + std::string(name) + "' (expected smash or uniform)");
}

const char* toString(ExtractTarget t) {
    return t == ExtractTarget::Raw ? "raw" : "smash";
}
ExtractTarget parseTarget(std::string_view name) {
    if (name == "raw")
        return ExtractTarget::Raw;
    if (name == "smash")
        return ExtractTarget::Smash;
    throw Error("unknown target '" + std::string(name) + "' (expected raw or smash)");
}

const char* toString(RoundtripWarning w) {
    switch (w) {
    case RoundtripWarning::NonGlobalEdit:
        return "non-global-edit";
    case RoundtripWarning::ProfileChange:
        return "profile-change";
    case RoundtripWarning::Clipping:
        return "clipping";
    case RoundtripWarning::Rescaled:
        return "rescaled";
    case RoundtripWarning::OutOfRange:
        return "out-of-range";
    case RoundtripWarning::LowCoverage:
        return "low-coverage";
    case RoundtripWarning::FewColours:
        return "few-colours";
    case RoundtripWarning::Outliers:
        return "outliers";
    }
    return "?";
}

bool ExtractResult::has(RoundtripWarning w) const {
    return std::find(warnings.begin(), warnings.end(), w) != warnings.end();
}

LutLayout defaultPatchLayout(int size) {
    const int level = static_cast<int>(std::lround(std::sqrt(static_cast<double>(size))));
    return level * level == size && level >= 3 ? LutLayout::Hald : LutLayout::Pilot;
}

void patchFrameSize(LutLayout layout, int size, int scale, int& width, int& height) {
    if (size < limits::kMin3DSize || size > limits::kMax3DSize)
        throw Error("patch size " + std::to_string(size) + " is out of range (" +
                    std::to_string(limits::kMin3DSize) + ".." + std::to_string(limits::kMax3DSize) +
                    ")");
    if (scale < 1 || scale > kMaxPatchScale)
        throw Error("patch scale " + std::to_string(scale) + " is out of range (1.." +
                    std::to_string(kMaxPatchScale) + ")");
    int cw = 0, ch = 0;
    patchCells(layout, size, cw, ch);
    if (cw + 2 < kMinHeaderRow)
        throw Error(
            std::string("a ") + std::to_string(size) + "^3 patch in the " + toString(layout) +
            " layout is too narrow for the marker header (use size >= 5, or >= 9 for hald)");
    width = (cw + 4) * scale;
    height = (ch + 4) * scale;
}

float smashLatticeValue(int index) {
    // The display value the unedited game shows for its lattice input i/15 with a neutral LUT:
    // brighten (x1.3703 in gamma space), decode with 2.2, clip, encode with the sRGB curve.
    if (index >= kSmashLatticeSize - 1)
        return 1.0f;
    const double s = index / 15.0;
    return static_cast<float>(srgbEnc(clamp01(std::pow(s * kBrightenScale, kGammaDecode))));
}

float patchInputValue(PatchLattice lattice, int index, int size, int bitDepth) {
    const float v = lattice == PatchLattice::Smash
                        ? smashLatticeValue(index)
                        : static_cast<float>(index) / static_cast<float>(size - 1);
    if (bitDepth == 8)
        return fromUnorm8(toUnorm8(v));
    if (bitDepth == 16)
        return fromUnorm16(toUnorm16(v));
    return v;
}

float patchInputValue(int index, int size, int bitDepth) {
    return patchInputValue(PatchLattice::Uniform, index, size, bitDepth);
}

PatchPlacement embedPatch(const ImageView& image, const EmbedOptions& o) {
    if (o.bitDepth != 8 && o.bitDepth != 16 && o.bitDepth != 32)
        throw Error("embed: bit depth must be 8, 16 or 32, not " + std::to_string(o.bitDepth));
    if (o.margin < 0)
        throw Error("embed: negative margin");
    const int size = o.lattice == PatchLattice::Smash ? kSmashLatticeSize : o.size;
    const LutLayout layout = o.layout ? *o.layout : defaultPatchLayout(size);
    int fwPx = 0, fhPx = 0;
    patchFrameSize(layout, size, o.scale, fwPx, fhPx);
    if (static_cast<long long>(fwPx) + o.margin > image.width ||
        static_cast<long long>(fhPx) + o.margin > image.height)
        throw Error("embed: the " + std::to_string(size) + "^3 " + toString(layout) +
                    " patch at scale " + std::to_string(o.scale) + " needs " +
                    std::to_string(fwPx + o.margin) + "x" + std::to_string(fhPx + o.margin) +
                    " pixels with its margin, the screenshot is " + std::to_string(image.width) +
                    "x" + std::to_string(image.height) + " (use a smaller --size or --scale)");
    PatchPlacement p;
    p.lattice = o.lattice;
    p.layout = layout;
    p.size = size;
    p.scale = o.scale;
    p.cell = o.scale;
    p.bitDepth = o.bitDepth;
    p.frameWidth = fwPx;
    p.frameHeight = fhPx;
    const bool right = o.corner == PatchCorner::TopRight || o.corner == PatchCorner::BottomRight;
    const bool bottom = o.corner == PatchCorner::BottomLeft || o.corner == PatchCorner::BottomRight;
    p.frameX = right ? image.width - o.margin - fwPx : o.margin;
    p.frameY = bottom ? image.height - o.margin - fhPx : o.margin;

    const int k = o.scale;
    int cw = 0, ch = 0;
    patchCells(layout, size, cw, ch);
    const int fw = cw + 4, fh = ch + 4;
    auto fillCell = [&](int cx, int cy, float v) {
        for (int y = 0; y < k; ++y)
            for (int x = 0; x < k; ++x) {
                float* px = image.pixel(p.frameX + cx * k + x, p.frameY + cy * k + y);
                px[0] = px[1] = px[2] = v;
                px[3] = 1.0f;
            }
    };
    for (int cy = 0; cy < fh; ++cy)
        for (int cx = 0; cx < fw; ++cx)
            if (cx == 0 || cy == 0 || cx == fw - 1 || cy == fh - 1)
                fillCell(cx, cy, ((cx + cy) & 1) ? 0.0f : 1.0f);
    const auto bits = headerBits(o.lattice, o.bitDepth, layout, size, o.scale);
    const auto ring = innerRing(fw, fh);
    for (std::size_t i = 0; i < ring.size(); ++i)
        fillCell(ring[i].first, ring[i].second, bits[i % kHeaderBits] ? 1.0f : 0.0f);

    Lut3D neutral(size);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r)
                neutral.at(r, g, b) = glm::vec3(patchInputValue(o.lattice, r, size, o.bitDepth),
                                                patchInputValue(o.lattice, g, size, o.bitDepth),
                                                patchInputValue(o.lattice, b, size, o.bitDepth));
    drawLut(neutral, layout, image, p.patchX(), p.patchY(), k);
    return p;
}

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
    if (!found)
        period = edgeScan(img, p, found);
    if (found) {
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
    result.message =
        "no LUT patch found: the marker frame is missing, cropped, painted over, or an "
        "edit mapped its black and white to the same colour";
    return result;
}

PatchReading readPatch(const ImageView& img, const PatchPlacement& pl) {
    PatchReading out;
    out.placement = pl;
    const int n = pl.size, cell = pl.cell;
    int cw = 0, ch = 0;
    patchCells(pl.layout, n, cw, ch);
    const int px0 = pl.patchX(), py0 = pl.patchY();
    if (px0 < 0 || py0 < 0 ||
        static_cast<long long>(px0) + static_cast<long long>(cw) * cell > img.width ||
        static_cast<long long>(py0) + static_cast<long long>(ch) * cell > img.height)
        throw Error("the LUT patch does not fit inside the image");
    out.values = Lut3D(n);
    out.axis.resize(n);
    for (int i = 0; i < n; ++i)
        out.axis[i] = patchInputValue(pl.lattice, i, n, pl.bitDepth);
    // Average the inner part of each block: its border pixels take the brunt of resampling,
    // JPEG ringing and a neighbour's bleed. Uniformity is judged on the whole block: a global
    // edit leaves a uniform block uniform, a blur or sharpen does not.
    const int inset = cell >= 3 ? 1 : 0;
    const int m = cell - 2 * inset;
    const double inv = 1.0 / (static_cast<double>(m) * m);
    const bool judgeBlocks = pl.cell % pl.scale == 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                int x = 0, y = 0;
                layoutPixel(pl.layout, n, r, g, b, x, y);
                const int bx = px0 + x * cell + inset, by = py0 + y * cell + inset;
                double acc[3] = {0, 0, 0};
                for (int dy = 0; dy < m; ++dy)
                    for (int dx = 0; dx < m; ++dx) {
                        const float* p = img.pixel(bx + dx, by + dy);
                        for (int c = 0; c < 3; ++c)
                            acc[c] += std::isfinite(p[c]) ? p[c] : 0.0f;
                    }
                const glm::vec3 mean(static_cast<float>(acc[0] * inv),
                                     static_cast<float>(acc[1] * inv),
                                     static_cast<float>(acc[2] * inv));
                double dev = 0.0;
                if (judgeBlocks)
                    for (int dy = 0; dy < cell; ++dy)
                        for (int dx = 0; dx < cell; ++dx) {
                            const float* p = img.pixel(px0 + x * cell + dx, py0 + y * cell + dy);
                            dev = std::max(dev, static_cast<double>(
                                                    maxDiff(glm::vec3(p[0], p[1], p[2]), mean)));
                        }
                dev *= 255.0;
                out.blockMaxDeviation = std::max(out.blockMaxDeviation, dev);
                if (dev > 2.5)
                    ++out.nonUniformBlocks;
                out.values.at(r, g, b) = mean;
            }
    return out;
}

// ------------------------------------------------------------------------------------------------

PatchFunction::PatchFunction(const Lut3D& values, std::vector<float> axis)
    : m_values(values), m_axis(std::move(axis)) {
    if (m_values.empty() || static_cast<int>(m_axis.size()) != m_values.size() || m_axis.size() < 2)
        throw Error("PatchFunction: axis and table sizes differ");
}

void PatchFunction::locate(float v, int& i, float& f) const {
    const int n = static_cast<int>(m_axis.size());
    if (!(v > m_axis[0])) { // also NaN
        i = 0;
        f = 0.0f;
        return;
    }
    if (v >= m_axis[n - 1]) {
        i = n - 2;
        f = 1.0f;
        return;
    }
    i = static_cast<int>(std::upper_bound(m_axis.begin(), m_axis.end(), v) - m_axis.begin()) - 1;
    i = std::clamp(i, 0, n - 2);
    const float span = m_axis[i + 1] - m_axis[i];
    f = span > 0.0f ? std::clamp((v - m_axis[i]) / span, 0.0f, 1.0f) : 0.0f;
}

glm::vec3 PatchFunction::operator()(glm::vec3 in) const {
    int ir, ig, ib;
    float fr, fg, fb;
    locate(in.x, ir, fr);
    locate(in.y, ig, fg);
    locate(in.z, ib, fb);
    return detail::tetrahedralBlend(
        [this](int r, int g, int b) -> const glm::vec3& { return m_values.at(r, g, b); }, ir, ig,
        ib, fr, fg, fb);
}

// ------------------------------------------------------------------------------------------------

namespace {

void warn(ExtractResult& res, RoundtripWarning w, const std::string& message) {
    res.warnings.push_back(w);
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.message = message;
    res.diagnostics.push_back(std::move(d));
}
void note(ExtractResult& res, const std::string& message) {
    Diagnostic d;
    d.severity = Diagnostic::Severity::Info;
    d.message = message;
    res.diagnostics.push_back(std::move(d));
}

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[512];
    std::snprintf(buf, sizeof buf, f, a, b, c, d);
    return buf;
}

// Entries that no smooth or piecewise-smooth (kinked) global edit explains: for each axis, the
// entry must agree with at least one of a centred cubic, a linear interpolation of its two
// neighbours, or a linear extrapolation from either side (the one-sided forms accept kinks such
// as gradient-map stops and clipping). Returns the count; thresholds in 8-bit steps.
std::size_t countSuspicious(const Lut3D& v, double thresholdSteps) {
    const int n = v.size();
    if (n < 4)
        return 0;
    const float thr = static_cast<float>(thresholdSteps / 255.0);
    std::size_t count = 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const int idx[3] = {r, g, b};
                bool bad = false;
                for (int axis = 0; axis < 3 && !bad; ++axis) {
                    const int i = idx[axis];
                    if (i < 1 || i + 1 >= n)
                        continue;
                    auto at = [&](int k) {
                        int q[3] = {r, g, b};
                        q[axis] = k;
                        return v.at(q[0], q[1], q[2]);
                    };
                    const glm::vec3 c = at(i), lo = at(i - 1), hi = at(i + 1);
                    for (int ch = 0; ch < 3 && !bad; ++ch) {
                        // only a spike (a local extremum standing out from both neighbours) can be
                        // a local edit; curvature and kinks of global edits are monotone here or
                        // explained by one side
                        const bool spike = c[ch] > std::max(lo[ch], hi[ch]) + thr ||
                                           c[ch] < std::min(lo[ch], hi[ch]) - thr;
                        if (!spike)
                            continue;
                        float best = std::fabs((lo[ch] + hi[ch]) * 0.5f - c[ch]);
                        if (i >= 2 && i + 2 < n)
                            best = std::min(best, std::fabs((-at(i - 2)[ch] + 4.0f * lo[ch] +
                                                             4.0f * hi[ch] - at(i + 2)[ch]) /
                                                                6.0f -
                                                            c[ch]));
                        if (i >= 2)
                            best = std::min(best, std::fabs(2.0f * lo[ch] - at(i - 2)[ch] - c[ch]));
                        if (i + 2 < n)
                            best = std::min(best, std::fabs(2.0f * hi[ch] - at(i + 2)[ch] - c[ch]));
                        if (best > thr)
                            bad = true;
                    }
                }
                if (bad)
                    ++count;
            }
    return count;
}

void checkGreys(const PatchReading& patch, ExtractResult& res) {
    const int n = patch.values.size();
    double gammaSum = 0.0;
    double gammas[3] = {1, 1, 1};
    double worstPowerFit = 0.0, worstSrgbTo22 = 0.0, worst22ToSrgb = 0.0;
    int used = 0;
    for (int c = 0; c < 3; ++c) {
        double sxy = 0.0, sxx = 0.0;
        for (int i = 0; i < n; ++i) {
            const double a = patch.axis[i], y = patch.values.at(i, i, i)[c];
            if (a < 0.1 || a > 0.95 || y < 0.01)
                continue;
            sxy += std::log(a) * std::log(y);
            sxx += std::log(a) * std::log(a);
        }
        if (sxx <= 0.0)
            return;
        gammas[c] = sxy / sxx;
        gammaSum += gammas[c];
        ++used;
        for (int i = 0; i < n; ++i) {
            const double a = patch.axis[i], y = patch.values.at(i, i, i)[c];
            worstPowerFit = std::max(worstPowerFit, std::fabs(std::pow(a, gammas[c]) - y));
            worstSrgbTo22 = std::max(worstSrgbTo22, std::fabs(std::pow(srgbDec(a), 1.0 / 2.2) - y));
            worst22ToSrgb = std::max(worst22ToSrgb, std::fabs(srgbEnc(std::pow(a, 2.2)) - y));
        }
    }
    if (used != 3)
        return;
    res.gamma = gammaSum / 3.0;
    const double spread =
        std::max({gammas[0], gammas[1], gammas[2]}) - std::min({gammas[0], gammas[1], gammas[2]});
    const double tol = 1.5 / 255.0;
    if (worstSrgbTo22 <= tol || worst22ToSrgb <= tol) {
        warn(res, RoundtripWarning::ProfileChange,
             "the neutral greys of the patch changed exactly like a conversion between the sRGB "
             "and a "
             "gamma 2.2 colour profile: the editor may have converted colour profiles (assign or "
             "keep "
             "the profile instead of converting) -- the LUT includes that conversion");
    } else if (worstPowerFit <= tol && spread <= 0.02 && std::fabs(res.gamma - 1.0) >= 0.05) {
        warn(res, RoundtripWarning::ProfileChange,
             fmt("the neutral greys of the patch follow a pure gamma curve (x^%.3f in all "
                 "channels): "
                 "this is what a colour-profile or gamma conversion does (e.g. 2.2 <-> 1.8 gives "
                 "1.22); if "
                 "you did not apply a gamma edit, check the editor's colour management",
                 res.gamma));
    }
}

ErrorStats subLatticeError(const PatchReading& patch) {
    const int n = patch.values.size();
    ErrorAccumulator acc;
    if (n < 3)
        return acc.result();
    std::vector<int> keep;
    for (int i = 0; i < n; i += 2)
        keep.push_back(i);
    if (keep.back() != n - 1)
        keep.push_back(n - 1);
    const int m = static_cast<int>(keep.size());
    Lut3D sub(m);
    std::vector<float> subAxis(m);
    for (int i = 0; i < m; ++i)
        subAxis[i] = patch.axis[keep[i]];
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r)
                sub.at(r, g, b) = patch.values.at(keep[r], keep[g], keep[b]);
    const PatchFunction coarse(sub, subAxis);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                if (r % 2 == 0 && g % 2 == 0 && b % 2 == 0)
                    continue;
                const glm::vec3 p = coarse(glm::vec3(patch.axis[r], patch.axis[g], patch.axis[b]));
                const glm::vec3 t = patch.values.at(r, g, b);
                for (int c = 0; c < 3; ++c)
                    acc.add(p[c], t[c]);
            }
    return acc.result();
}

} // namespace

ExtractResult extractLut(const ImageView& edited, const ExtractOptions& options) {
    const FindResult found = findPatch(edited);
    if (found.status != FindStatus::Found)
        throw Error(found.message);
    const PatchReading patch = readPatch(edited, found.placement);
    return extractLut(patch, options);
}

ExtractResult extractLut(const PatchReading& patch, const ExtractOptions& options) {
    ExtractResult res;
    res.placement = patch.placement;
    const int n = patch.values.size();
    const PatchPlacement& pl = patch.placement;

    if (pl.cell != pl.scale) {
        const bool whole = pl.cell % pl.scale == 0;
        warn(res, RoundtripWarning::Rescaled,
             fmt(whole ? "the image was scaled by %g after embedding (cells of %g pixels, embedded "
                         "at %g); "
                         "read at the new size"
                       : "the image was scaled by %g after embedding (cells of %g pixels, embedded "
                         "at %g), not "
                         "a whole number: only the block centres were read and may be blended; "
                         "undo the resize",
                 double(pl.cell) / pl.scale, pl.cell, pl.scale));
    }

    // --- checks on the patch itself ---
    const std::size_t blocks = static_cast<std::size_t>(n) * n * n;
    if (pl.cell >= 2 && patch.nonUniformBlocks > std::max<std::size_t>(2, blocks / 200)) {
        warn(
            res, RoundtripWarning::NonGlobalEdit,
            fmt("%g of %g patch blocks are not uniform (up to %.3g 8-bit steps inside a block): "
                "the "
                "patch was blurred, sharpened, noised, painted on or saved lossily; a LUT can only "
                "reproduce global colour edits",
                double(patch.nonUniformBlocks), double(blocks), patch.blockMaxDeviation));
    }
    res.suspiciousEntries = countSuspicious(patch.values, 3.0);
    if (res.suspiciousEntries > std::max<std::size_t>(3, blocks / 400) &&
        !res.has(RoundtripWarning::NonGlobalEdit)) {
        warn(res, RoundtripWarning::NonGlobalEdit,
             fmt("%g of %g patch entries disagree with their neighbours by more than 3 8-bit steps "
                 "in a "
                 "way no smooth global edit gives: a local edit (brush, blur, sharpen, noise) "
                 "touched "
                 "the patch, or the edit is not a per-pixel colour function",
                 double(res.suspiciousEntries), double(blocks)));
    }
    {
        std::size_t clipped = 0, total = 0;
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::vec3 v = patch.values.at(r, g, b);
                    const float in[3] = {patch.axis[r], patch.axis[g], patch.axis[b]};
                    for (int c = 0; c < 3; ++c) {
                        ++total;
                        const bool lo = v[c] <= 0.5f / 255.0f, hi = v[c] >= 1.0f - 0.5f / 255.0f;
                        if ((lo && in[c] > 0.0f) || (hi && in[c] < 1.0f))
                            ++clipped;
                    }
                }
        res.clippedValues = clipped;
        if (clipped * 100 > total * 3)
            warn(res, RoundtripWarning::Clipping,
                 fmt("%.3g%% of the patch values are clipped at 0 or 1 (%g of %g): the edit throws "
                     "those colour differences away and no LUT can bring them back",
                     100.0 * double(clipped) / double(total), double(clipped), double(total)));
    }
    checkGreys(patch, res);

    // --- how well the patch predicts the edit between its lattice points ---
    res.subLatticeError = subLatticeError(patch);
    res.expectedError = res.subLatticeError;
    res.expectedError.maxAbs /= 4.0;
    res.expectedError.meanAbs /= 4.0;

    const PatchFunction edit(patch.values, patch.axis);

    if (options.target == ExtractTarget::Raw) {
        // the smash lattice is not uniform: its raw LUT defaults to the game's 16^3
        const int m = options.outputSize > 0              ? options.outputSize
                      : pl.lattice == PatchLattice::Smash ? 16
                                                          : n;
        Lut3D out(m);
        for (int b = 0; b < m; ++b)
            for (int g = 0; g < m; ++g)
                for (int r = 0; r < m; ++r)
                    out.at(r, g, b) = edit(glm::vec3(r, g, b) / static_cast<float>(m - 1));
        res.lut = std::move(out);
    } else {
        const int m = options.outputSize > 0 ? options.outputSize : 16;
        std::unique_ptr<Sampler> original;
        if (options.originalLut)
            original = makeSampler(*options.originalLut, Interpolation::Trilinear);
        // What the unedited screenshot showed for the gamma-space input s, and what the modder
        // wants With the smash lattice and a neutral stage LUT every lattice input lands (up to the
        // patch's storage rounding) on a patch node; otherwise the patch is interpolated.
        auto wanted = [&](glm::vec3 s) {
            const glm::vec3 l0 = original ? original->sample(s) : s;
            glm::vec3 shot;
            for (int c = 0; c < 3; ++c)
                shot[c] = static_cast<float>(gameShown(l0[c], s[c]));
            return edit(shot);
        };
        Lut3D out(m);
        std::size_t clamped = 0;
        double farthest = 0.0;
        for (int b = 0; b < m; ++b)
            for (int g = 0; g < m; ++g)
                for (int r = 0; r < m; ++r) {
                    const glm::vec3 s = glm::vec3(r, g, b) / static_cast<float>(m - 1);
                    const glm::vec3 want = wanted(s);
                    glm::vec3 targetLinear;
                    for (int c = 0; c < 3; ++c)
                        targetLinear[c] = static_cast<float>(srgbDec(clamp01(want[c])));
                    // the shared inverse of the game's grading (lut/pipeline/SmashGrading.h)
                    const glm::vec3 exact = smashLutEntryForTarget(targetLinear, s);
                    glm::vec3 entry;
                    for (int c = 0; c < 3; ++c) {
                        const double l = exact[c];
                        const double lc = clamp01(l);
                        // The brighten step keeps 0.039% of s: a black target for a bright
                        // input needs L slightly below 0 (at most 0.1 8-bit steps); counted too.
                        if (std::fabs(l - lc) > 1e-6) {
                            ++clamped;
                            farthest = std::max(farthest, std::fabs(l - lc));
                        }
                        entry[c] = static_cast<float>(lc);
                    }
                    out.at(r, g, b) = entry;
                }
        res.clampedEntries = clamped;
        res.clampedMax = farthest;
        if (clamped > 0)
            warn(res, RoundtripWarning::OutOfRange,
                 fmt("%g LUT values would need to leave [0,1] (by up to %.3g, %.3g 8-bit steps) to "
                     "show "
                     "the edited colours in game; they were clamped: the game cannot show those "
                     "colours",
                     double(clamped), farthest, farthest * 255.0));
        // The in-game error: the 8-bit LUT the game receives, sampled trilinearly between lattice
        // points, against the edited look, on probes at quarter lattice steps.
        Lut3D shipped = out;
        quantize8(shipped);
        const auto game = makeSampler(shipped, Interpolation::Trilinear);
        ErrorAccumulator acc;
        const int probes = 4 * (m - 1) + 1;
        for (int b = 0; b < probes; ++b)
            for (int g = 0; g < probes; ++g)
                for (int r = 0; r < probes; ++r) {
                    const glm::vec3 s = glm::vec3(r, g, b) / static_cast<float>(probes - 1);
                    const glm::vec3 want = wanted(s);
                    const glm::vec3 l = game->sample(s);
                    for (int c = 0; c < 3; ++c)
                        acc.add(gameShown(l[c], s[c]), clamp01(want[c]));
                }
        res.gameError = acc.result();
        res.lut = std::move(out);
    }
    res.lut.setTitle(std::string("extracted from a ") + std::to_string(n) + "^3 patch (" +
                     toString(options.target) + ")");
    note(res, std::string("patch: ") + std::to_string(n) + "^3 " + toString(pl.lattice) +
                  " lattice, " + toString(pl.layout) + " layout at scale " +
                  std::to_string(pl.scale) + ", frame at (" + std::to_string(pl.frameX) + ", " +
                  std::to_string(pl.frameY) + ")");
    note(res, "expected error between patch lattice points: " + res.expectedError.str() +
                  " (sub-lattice check at twice the spacing: " + res.subLatticeError.str() + ")");
    if (options.target == ExtractTarget::Smash)
        note(res, "expected in-game error (8-bit LUT, trilinear, display-encoded): " +
                      res.gameError.str());
    return res;
}

} // namespace lut
