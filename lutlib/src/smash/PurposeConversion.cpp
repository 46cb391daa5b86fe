// SPDX-License-Identifier: Apache-2.0
// A LUT made for one purpose turned into the LUT for another; see
// lut/smash/PurposeConversion.h.
#include "lut/smash/PurposeConversion.h"

#include "lut/Error.h"
#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/smash/GameDisplay.h"
#include "lut/smash/SmashConstants.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace lut {

namespace {

// The neutral game's input s for a display value d (per channel): the inverse of
// srgb(min(1, (s * 1.3703)^2.2)); white is taken where it starts.
double neutralInputFor(double d) {
    return lut::math::pow(detail::srgbDecodeUnit(d),
                          1.0 / static_cast<double>(kSmashDecodeExponent)) /
           static_cast<double>(kSmashBrightenScale);
}

// The display values where the edit of a game LUT of edge n has a kink: the neutral game's
// picture of its lattice planes s = i/(n-1) below white.
std::vector<double> kinks(int n) {
    std::vector<double> out;
    for (int i = 1; i < n - 1; ++i) {
        const double s = i / static_cast<double>(n - 1);
        const double d = detail::srgbEncodeUnit(
            detail::clampUnit(lut::math::pow(s * static_cast<double>(kSmashBrightenScale),
                                             static_cast<double>(kSmashDecodeExponent))));
        if (d < 1.0)
            out.push_back(d);
    }
    return out;
}

class GameEdit {
public:
    explicit GameEdit(const Lut3D& game) : m_sampler(makeSampler(game, Interpolation::Trilinear)) {}
    // E at the neutral inputs s (one per channel, from neutralInputFor).
    glm::dvec3 at(const glm::dvec3& s) const {
        const glm::vec3 l = m_sampler->sample(glm::vec3(s));
        glm::dvec3 e;
        for (int c = 0; c < 3; ++c)
            e[c] = detail::gameShown(static_cast<double>(l[c]), s[c]);
        return e;
    }

private:
    std::unique_ptr<Sampler> m_sampler;
};

// The authoring options of a raw -> smash conversion.
SmashAuthoringOptions authoringOptions(const PurposeOptions& o) {
    SmashAuthoringOptions a;
    a.gameLut = o.stageLut;
    // Only what is written is computed: the refinement with refine (shipped when it beats the
    // exact composition on colours it was not fitted on), the exact composition's error with
    // measure.
    a.refine = o.refine;
    a.measure = o.measure || o.refine;
    a.screenshot = o.screenshot;
    a.nthreads = o.nthreads;
    return a;
}

// The game's LUT to use: the refinement when it won on the held-out colours, else the exact
// composition clamped to what the file holds (SmashAuthoringResult::lut).
void finishGameLut(PurposeConversion& c) {
    c.lut = c.authoring.lut;
    c.measuredOver = c.authoring.measuredOver;
}

} // namespace

glm::dvec3 gameShownForDisplayed(const Sampler& game, const glm::dvec3& d) {
    const glm::dvec3 s(neutralInputFor(d.x), neutralInputFor(d.y), neutralInputFor(d.z));
    const glm::vec3 l = game.sample(glm::vec3(s));
    glm::dvec3 e;
    for (int c = 0; c < 3; ++c)
        e[c] = detail::gameShown(static_cast<double>(l[c]), s[c]);
    return e;
}

Lut3D editOfGameLut(const Lut3D& game, int size, GameError* error, int nthreads,
                    std::string* measuredOver) {
    if (game.empty())
        throw Error("the game LUT is empty");
    Lut3D out(size); // throws for a size out of range
    out.setTitle(game.title());
    const GameEdit edit(game);
    std::vector<double> s(static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i)
        s[static_cast<std::size_t>(i)] = neutralInputFor(i / static_cast<double>(size - 1));
    parallelFor(size, nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r)
                    out.at(r, g, b) = glm::vec3(edit.at(glm::dvec3(s[r], s[g], s[b])));
    });
    if (!error && !measuredOver)
        return out;

    // Where sampling can cost the most: the cell centres, the lattice points (edge and face
    // midpoints come from combining them with centres) and the kinks, on every axis; and finely
    // in the first cells, where the neutral input s(d) ~ d^(1/2.2) has no bounded slope at 0, so
    // the edit bends most (its worst point in the first cell is about a quarter of the way in).
    std::vector<double> axis;
    std::vector<bool> onLattice;
    for (int i = 0; i < size; ++i) {
        axis.push_back(i / static_cast<double>(size - 1));
        const int parts = i == 0 ? 16 : i == 1 ? 8 : 2;
        if (i + 1 < size)
            for (int k = 1; k < parts; ++k)
                axis.push_back((i + k / static_cast<double>(parts)) / (size - 1));
    }
    for (double k : kinks(game.size()))
        axis.push_back(k);
    std::sort(axis.begin(), axis.end());
    axis.erase(std::unique(axis.begin(), axis.end()), axis.end());
    for (double v : axis) {
        const double x = v * (size - 1);
        onLattice.push_back(std::fabs(x - std::round(x)) < 1e-12);
    }
    const int m = static_cast<int>(axis.size());
    std::vector<double> sa(axis.size());
    for (std::size_t i = 0; i < axis.size(); ++i)
        sa[i] = neutralInputFor(axis[i]);
    const auto table = makeSampler(out, Interpolation::Tetrahedral);
    // The error at every probe (red fastest), per channel.
    const std::size_t mm = static_cast<std::size_t>(m);
    std::vector<double> err(mm * mm * mm * 3);
    auto at = [&](int r, int g, int b, int c) -> double& {
        return err[3 * (static_cast<std::size_t>(r) +
                        mm * (static_cast<std::size_t>(g) + mm * static_cast<std::size_t>(b))) +
                   static_cast<std::size_t>(c)];
    };
    parallelFor(m, nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < m; ++g)
                for (int r = 0; r < m; ++r) {
                    const glm::dvec3 want = edit.at(glm::dvec3(sa[r], sa[g], sa[b]));
                    const glm::vec3 got = table->sample(glm::vec3(static_cast<float>(axis[r]),
                                                                  static_cast<float>(axis[g]),
                                                                  static_cast<float>(axis[b])));
                    for (int c = 0; c < 3; ++c)
                        at(r, g, b, c) = std::fabs(static_cast<double>(got[c]) - want[c]) * 255.0;
                }
    });
    // Between two neighbouring probes a and b along an axis the error can peak (a kink of the
    // edit, the seams of the tetrahedra): at most their mean plus half the steeper of the slopes
    // just outside them times the spacing, the bound a function with that slope can reach.
    double peak = 0.0;
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r)
                for (int ax = 0; ax < 3; ++ax) {
                    const int q[3] = {r, g, b};
                    if (q[ax] + 1 >= m)
                        continue;
                    auto e = [&](int offset, int c) {
                        int t[3] = {r, g, b};
                        t[ax] = std::clamp(q[ax] + offset, 0, m - 1);
                        return at(t[0], t[1], t[2], c);
                    };
                    auto h = [&](int from) { // spacing from probe q+from to q+from+1
                        const int i0 = std::clamp(q[ax] + from, 0, m - 2);
                        return axis[static_cast<std::size_t>(i0) + 1] -
                               axis[static_cast<std::size_t>(i0)];
                    };
                    for (int c = 0; c < 3; ++c) {
                        const double ea = e(0, c), eb = e(1, c);
                        const double before = q[ax] > 0 ? std::fabs(ea - e(-1, c)) / h(-1) : 0.0;
                        const double after = q[ax] + 2 < m ? std::fabs(e(2, c) - eb) / h(1) : 0.0;
                        peak =
                            std::max(peak, 0.5 * (ea + eb) + 0.5 * std::max(before, after) * h(0));
                    }
                }
    std::vector<double> all;
    all.reserve(err.size());
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r)
                if (!(onLattice[static_cast<std::size_t>(r)] &&
                      onLattice[static_cast<std::size_t>(g)] &&
                      onLattice[static_cast<std::size_t>(b)])) // the table holds E there
                    for (int c = 0; c < 3; ++c)
                        all.push_back(at(r, g, b, c));
    const std::size_t points = all.size() / 3;
    if (error) {
        *error = summariseSteps(all);
        error->maxSteps = std::max(error->maxSteps, peak);
    }
    if (measuredOver)
        *measuredOver = std::to_string(points) + " colours between the " + std::to_string(size) +
                        "^3 lattice points (cell centres, edge and face midpoints, the game "
                        "LUT's kinks, finely near black; the max bounds the peaks between them)";
    return out;
}

PurposeConversion convertPurpose(const Lut3D& lut, LutPurpose from, LutPurpose to,
                                 const PurposeOptions& o) {
    if (lut.empty())
        throw Error("the LUT is empty");
    PurposeConversion c;
    c.from = from;
    c.to = to;
    if (from == to) {
        c.lut = lut;
        return c;
    }
    if (to == LutPurpose::Raw) {
        c.lut = editOfGameLut(lut, o.rawSize, &c.sampling, o.nthreads, &c.measuredOver);
        return c;
    }
    c.authoring = authorSmashLutForEdit(lut, o.editInterpolation, authoringOptions(o));
    c.onStage = o.stageLut != nullptr;
    finishGameLut(c);
    return c;
}

namespace {

// The edit a file holds in integers is known to half a storage step: what the game shows is at
// most that much farther from the edit the user made than from the file's values (the triangle
// inequality at every colour), so the printed error includes it.
void addInputStorage(PurposeConversion& c, int bits) {
    if (bits <= 0 || bits > 16 || !c.converted() || c.to != LutPurpose::Smash)
        return;
    const double half = 0.5 * 255.0 / static_cast<double>((1u << bits) - 1u);
    for (GameError* e : {&c.authoring.exactError, &c.authoring.refinedError}) {
        if (e->count == 0)
            continue;
        e->maxSteps += half;
        e->meanSteps += half;
        e->p99Steps += half;
    }
    if (c.authoring.exactError.count == 0)
        return;
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "; the file holds the edit in %d-bit integers: its half step of storage, %.3g "
                  "8-bit steps, included",
                  bits, half);
    c.authoring.measuredOver += buf;
    c.measuredOver = c.authoring.measuredOver;
}

} // namespace

PurposeConversion convertPurpose(const LutFile& file, LutPurpose from, LutPurpose to,
                                 const PurposeOptions& o) {
    if (!file.cube && !file.shaper)
        throw Error("the LUT file holds no table");
    if (!file.shaper || from == to || to == LutPurpose::Raw) {
        PurposeConversion c = convertPurpose(file.toLut3D(), from, to, o);
        addInputStorage(c, file.sourceBitDepth);
        return c;
    }
    // The shaper, then the table, at every colour the authoring evaluates.
    // Its title, else the stage's (as authorSmashLutForEdit names a table).
    std::string title = file.cube ? file.cube->title() : file.shaper->title();
    if (title.empty() && o.stageLut)
        title = o.stageLut->title();
    const std::shared_ptr<const Sampler> exact = makeSampler(file, o.editInterpolation);
    PurposeConversion c;
    c.from = from;
    c.to = to;
    c.authoring = authorSmashLutForEdit([exact](glm::vec3 v) { return exact->sample(v); },
                                        authoringOptions(o));
    c.authoring.exact.setTitle(title);
    c.authoring.lut.setTitle(title);
    c.onStage = o.stageLut != nullptr;
    finishGameLut(c);
    addInputStorage(c, file.sourceBitDepth);
    return c;
}

} // namespace lut
