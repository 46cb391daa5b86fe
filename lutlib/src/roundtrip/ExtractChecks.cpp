// SPDX-License-Identifier: Apache-2.0
// Checks on a read patch before extract builds a LUT; see ExtractChecks.h.
#include "roundtrip/ExtractChecks.h"

#include "lut/smash/GameDisplay.h"

#include "lut/Math.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/EditCause.h"
#include "roundtrip/MarkerFrame.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lut::detail {

void addWarning(ExtractResult& res, RoundtripWarning w, const std::string& message) {
    res.warnings.push_back(w);
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.message = message;
    res.diagnostics.push_back(std::move(d));
}

void addNote(ExtractResult& res, const std::string& message) {
    Diagnostic d;
    d.severity = Diagnostic::Severity::Info;
    d.message = message;
    res.diagnostics.push_back(std::move(d));
}

namespace {

// Entries that no smooth or piecewise-smooth (kinked) global edit explains: for each axis, the
// entry must agree with at least one of a centred cubic, a linear interpolation of its two
// neighbours, or a linear extrapolation from either side (the one-sided forms accept kinks such
// as gradient-map stops and clipping). Returns the count; thresholds in 8-bit steps.
std::size_t countSuspicious(const Lut3D& v, double thresholdSteps,
                            std::vector<std::array<int, 3>>& where) {
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
                if (bad) {
                    ++count;
                    where.push_back({r, g, b});
                }
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
            sxy += lut::math::log(a) * lut::math::log(y);
            sxx += lut::math::log(a) * lut::math::log(a);
        }
        if (sxx <= 0.0)
            return;
        gammas[c] = sxy / sxx;
        gammaSum += gammas[c];
        ++used;
        for (int i = 0; i < n; ++i) {
            const double a = patch.axis[i], y = patch.values.at(i, i, i)[c];
            worstPowerFit = std::max(worstPowerFit, std::fabs(lut::math::pow(a, gammas[c]) - y));
            worstSrgbTo22 = std::max(worstSrgbTo22,
                                     std::fabs(lut::math::pow(srgbDecodeUnit(a), 1.0 / 2.2) - y));
            worst22ToSrgb =
                std::max(worst22ToSrgb, std::fabs(srgbEncodeUnit(lut::math::pow(a, 2.2)) - y));
        }
    }
    if (used != 3)
        return;
    res.gamma = gammaSum / 3.0;
    const double spread =
        std::max({gammas[0], gammas[1], gammas[2]}) - std::min({gammas[0], gammas[1], gammas[2]});
    const double tol = 1.5 / 255.0;
    if (worstSrgbTo22 <= tol || worst22ToSrgb <= tol) {
        addWarning(res, RoundtripWarning::ProfileChange,
                   "the neutral greys of the patch changed exactly like a conversion between the "
                   "sRGB and a gamma 2.2 colour profile: the editor may have converted colour "
                   "profiles (assign or keep the profile instead of converting) -- the LUT "
                   "includes that conversion");
    } else if (worstPowerFit <= tol && spread <= 0.02 && std::fabs(res.gamma - 1.0) >= 0.05) {
        addWarning(res, RoundtripWarning::ProfileChange,
                   fmt("the neutral greys of the patch follow a pure gamma curve "
                       "(x^%.3f in all channels): this is what a colour-profile or "
                       "gamma conversion does (e.g. 2.2 <-> 1.8 gives 1.22); if you did "
                       "not apply a gamma edit, check the editor's colour management",
                       res.gamma));
    }
}

// The cells (in the patch's layout) that hold the given entries: their bounding box and the
// share of the patch it covers.
struct CellBox {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    double share = 1.0;
};
CellBox entryBox(const PatchPlacement& pl, const std::vector<std::array<int, 3>>& entries) {
    CellBox box;
    if (entries.empty())
        return box;
    int cw = 0, ch = 0;
    patchCells(pl.layout, pl.size, cw, ch);
    box.x0 = cw;
    box.y0 = ch;
    for (const auto& e : entries) {
        int x = 0, y = 0;
        layoutPixel(pl.layout, pl.size, e[0], e[1], e[2], x, y);
        box.x0 = std::min(box.x0, x);
        box.y0 = std::min(box.y0, y);
        box.x1 = std::max(box.x1, x);
        box.y1 = std::max(box.y1, y);
    }
    box.share = static_cast<double>(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1) /
                (static_cast<double>(cw) * ch);
    return box;
}

std::string pixelsOf(const PatchPlacement& pl, int x0, int y0, int x1, int y1) {
    return "pixels (" + std::to_string(pl.patchX() + x0 * pl.cell) + ", " +
           std::to_string(pl.patchY() + y0 * pl.cell) + ") to (" +
           std::to_string(pl.patchX() + (x1 + 1) * pl.cell - 1) + ", " +
           std::to_string(pl.patchY() + (y1 + 1) * pl.cell - 1) + ")";
}

// Local: what is wrong lies in one part of the patch.
constexpr double kLocalShare = 0.35;

// Names the likely cause of blocks that are not uniform, with its fix.
void diagnoseBlocks(const PatchReading& patch, bool lossyFile, ExtractResult& res) {
    const BlockEvidence& ev = patch.blocks;
    const PatchPlacement& pl = patch.placement;
    const std::string count = fmt("%g of %g patch blocks are not uniform (up to %.3g "
                                  "8-bit steps inside a block)",
                                  double(patch.nonUniformBlocks), double(patch.values.entryCount()),
                                  patch.blockMaxDeviation);
    if (ev.blocks == 0) {
        res.cause = EditCause::Unknown;
        addWarning(res, RoundtripWarning::NonGlobalEdit,
                   count + ": the patch was blurred, sharpened, noised, painted on or saved "
                           "lossily (its blocks are too small to tell which); a LUT can only "
                           "reproduce global colour edits");
        return;
    }
    const bool chromaOnly = ev.chromaShare > 0.85 && (lossyFile || ev.chromaShare > 0.95);
    if (chromaOnly) {
        res.cause = EditCause::Lossy;
        addNote(res, count + fmt(", in colour only (%.0f%% of the deviation is chroma): "
                                 "a lossy save (JPEG); the blocks' averages were read "
                                 "and the expected error includes what is left",
                                 100.0 * ev.chromaShare));
        return;
    }
    if (ev.boxShare < kLocalShare && ev.nonUniform * 4 < ev.blocks) {
        res.cause = EditCause::LocalEdit;
        addWarning(res, RoundtripWarning::NonGlobalEdit,
                   count + ", all in one part of the patch (" +
                       pixelsOf(pl, ev.boxX0, ev.boxY0, ev.boxX1, ev.boxY1) +
                       "): a brush stroke or a local adjustment touched it. A LUT holds only "
                       "global colour edits: undo the local edit over the patch (or keep local "
                       "edits off it) and extract again");
        return;
    }
    if (ev.interiorSteps > 1.0 && ev.interiorSteps >= 0.5 * ev.borderSteps) {
        res.cause = EditCause::Noise;
        addWarning(res, RoundtripWarning::NonGlobalEdit,
                   count + fmt(": every pixel scatters, the middles of the blocks as "
                               "much as their edges (%.2g steps RMS): noise or film "
                               "grain was added over the patch. The blocks' averages "
                               "take most of it out (the expected error includes the "
                               "rest); add grain after extracting, or keep it off the "
                               "patch",
                               ev.interiorSteps));
        return;
    }
    if (ev.towards > 0.08) {
        res.cause = EditCause::Blur;
        addWarning(res, RoundtripWarning::NonGlobalEdit,
                   count + fmt(": their edges run into the neighbouring blocks' "
                               "colours (%.0f%% of the way on average) while their "
                               "middles stay: a blur or soften filter (or a smooth "
                               "resize) went over the patch. The blocks' middles were "
                               "read; blur after extracting, or keep the blur off the "
                               "patch",
                               100.0 * ev.towards));
        return;
    }
    if (ev.towards < -0.08) {
        res.cause = EditCause::Sharpen;
        addWarning(res, RoundtripWarning::NonGlobalEdit,
                   count + fmt(": their edges overshoot away from the neighbouring "
                               "blocks' colours (%.0f%% of the way) while their middles "
                               "stay: a sharpen (unsharp mask, clarity) went over the "
                               "patch. The blocks' middles were read; sharpen after "
                               "extracting, or keep it off the patch",
                               -100.0 * ev.towards));
        return;
    }
    res.cause = EditCause::Unknown;
    addWarning(res, RoundtripWarning::NonGlobalEdit,
               count + ": the patch was blurred, sharpened, noised, painted on or saved lossily; "
                       "a LUT can only reproduce global colour edits");
}

} // namespace

void checkPatch(const PatchReading& patch, ExtractResult& res, bool lossyFile) {
    const int n = patch.values.size();
    const PatchPlacement& pl = patch.placement;
    const std::size_t blocks = static_cast<std::size_t>(n) * n * n;
    const bool blocksBad =
        pl.cell >= 2 && patch.nonUniformBlocks > std::max<std::size_t>(2, blocks / 200);
    if (blocksBad)
        diagnoseBlocks(patch, lossyFile, res);
    std::vector<std::array<int, 3>> where;
    res.suspiciousEntries = countSuspicious(patch.values, 3.0, where);
    if (res.suspiciousEntries > std::max<std::size_t>(3, blocks / 400) &&
        !res.has(RoundtripWarning::NonGlobalEdit)) {
        const CellBox box = entryBox(pl, where);
        const std::string count =
            fmt("%g of %g patch entries disagree with their neighbours by more than 3 "
                "8-bit steps in a way no smooth global edit gives",
                double(res.suspiciousEntries), double(blocks));
        if (box.share < kLocalShare) {
            res.cause = EditCause::LocalEdit;
            addWarning(res, RoundtripWarning::NonGlobalEdit,
                       count + ", all in one part of the patch (" +
                           pixelsOf(pl, box.x0, box.y0, box.x1, box.y1) +
                           "): a brush stroke or a local adjustment painted over it. A LUT "
                           "holds only global colour edits: undo it there (or keep local edits "
                           "off the patch) and extract again");
        } else if (lossyFile) {
            // spread over the patch in a lossy file: compression noise, counted in the expected
            // error
            addNote(res, count + ", spread over the patch: compression noise of the lossy file "
                                 "(the expected error includes it)");
        } else {
            if (res.cause == EditCause::None)
                res.cause = EditCause::Unknown;
            addWarning(res, RoundtripWarning::NonGlobalEdit,
                       count + ": a local edit (brush, blur, sharpen, noise) touched the patch, "
                               "or the edit is not a per-pixel colour function");
        }
    }
    // A stage patch's inputs are the stage LUT's picture: known only when the LUT was given.
    const bool stage = pl.lattice == PatchLattice::SmashStage;
    if (stage && !patch.inputs)
        return;
    std::size_t clipped = 0, total = 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 v = patch.values.at(r, g, b);
                const glm::vec3 inputs =
                    stage ? patch.inputs->at(r, g, b)
                          : glm::vec3(patch.axis[r], patch.axis[g], patch.axis[b]);
                const float in[3] = {inputs.x, inputs.y, inputs.z};
                for (int c = 0; c < 3; ++c) {
                    ++total;
                    const bool lo = v[c] <= 0.5f / 255.0f, hi = v[c] >= 1.0f - 0.5f / 255.0f;
                    if ((lo && in[c] > 0.0f) || (hi && in[c] < 1.0f))
                        ++clipped;
                }
            }
    res.clippedValues = clipped;
    if (clipped * 100 > total * 3)
        addWarning(res, RoundtripWarning::Clipping,
                   fmt("%.3g%% of the patch values are clipped at 0 or 1 (%g of %g): "
                       "the edit throws those colour differences away and no LUT can "
                       "bring them back",
                       100.0 * double(clipped) / double(total), double(clipped), double(total)));
    if (!stage)
        checkGreys(patch, res);
}

SubLattice subLatticeCheck(const PatchReading& patch) {
    const int n = patch.values.size();
    SubLattice out;
    out.residual = Lut3D(n);
    if (n < 3)
        return out;
    std::vector<int> keep;
    std::vector<char> kept(n, 0);
    for (int i = 0; i < n; i += 2)
        keep.push_back(i);
    if (keep.back() != n - 1)
        keep.push_back(n - 1);
    for (int i : keep)
        kept[i] = 1;
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
    std::vector<double> steps;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                if (kept[r] && kept[g] && kept[b])
                    continue;
                const glm::vec3 p = coarse(glm::vec3(patch.axis[r], patch.axis[g], patch.axis[b]));
                const glm::vec3 t = patch.values.at(r, g, b);
                glm::vec3 res;
                for (int c = 0; c < 3; ++c) {
                    res[c] = std::fabs(p[c] - t[c]) * 255.0f;
                    steps.push_back(res[c]);
                }
                out.residual.at(r, g, b) = res;
            }
    out.stats = summariseSteps(steps);
    // kept entries: the largest residual among their neighbours
    Lut3D spread = out.residual;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                if (!(kept[r] && kept[g] && kept[b]))
                    continue;
                glm::vec3 v(0.0f);
                for (int db = -1; db <= 1; ++db)
                    for (int dg = -1; dg <= 1; ++dg)
                        for (int dr = -1; dr <= 1; ++dr) {
                            const int rr = r + dr, gg = g + dg, bb = b + db;
                            if (rr < 0 || gg < 0 || bb < 0 || rr >= n || gg >= n || bb >= n)
                                continue;
                            const glm::vec3 o = out.residual.at(rr, gg, bb);
                            for (int c = 0; c < 3; ++c)
                                v[c] = std::max(v[c], o[c]);
                        }
                spread.at(r, g, b) = v;
            }
    out.residual = std::move(spread);
    return out;
}

} // namespace lut::detail
