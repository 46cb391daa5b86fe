// Extract: the LUT from a read patch, for a raw engine (the edit itself) or for the game (the
// edit composed with what the game does to its LUT's output); see lut/roundtrip/Extract.h,
// docs/roundtrip.md and, for the game's side, docs/specs/smash-pipeline.md.
#include "lut/roundtrip/Extract.h"

#include "lut/interp/Sampler.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/pipeline/SmashGrading.h"
#include "lut/roundtrip/PatchFinder.h"
#include "roundtrip/ExtractChecks.h"
#include "roundtrip/GameDisplay.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace lut {

using detail::addNote;
using detail::addWarning;
using detail::clampUnit;
using detail::formatMessage;
using detail::gameShown;

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

bool ExtractResult::has(RoundtripWarning w) const {
    return std::find(warnings.begin(), warnings.end(), w) != warnings.end();
}

namespace {

// Raw: entry (r,g,b) of an m^3 LUT is the edit at (r,g,b)/(m-1).
Lut3D rawLut(const PatchFunction& edit, int m) {
    Lut3D out(m);
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r)
                out.at(r, g, b) = edit(glm::vec3(r, g, b) / static_cast<float>(m - 1));
    return out;
}

// Smash: the m^3 LUT that makes the game show the edited look, the values it had to clamp, and
// the error the game shows with it once it is stored in 8 bits.
void smashLut(const PatchFunction& edit, int m, const Lut3D* originalLut, ExtractResult& res) {
    std::unique_ptr<Sampler> original;
    if (originalLut)
        original = makeSampler(*originalLut, Interpolation::Trilinear);
    // What the modder wants the game to show for the gamma-space input s: the edit applied to
    // what the unedited screenshot showed there. With the game-display lattice and a neutral
    // stage LUT, every lattice input lands (up to the patch's storage rounding) on a patch node;
    // otherwise the patch is interpolated.
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
                    targetLinear[c] =
                        static_cast<float>(detail::srgbDecodeUnit(clampUnit(want[c])));
                // the shared inverse of the game's grading (lut/pipeline/SmashGrading.h)
                const glm::vec3 exact = smashLutEntryForTarget(targetLinear, s);
                glm::vec3 entry;
                for (int c = 0; c < 3; ++c) {
                    const double l = exact[c];
                    const double lc = clampUnit(l);
                    // The brighten step keeps 0.039% of s: a black target for a bright input
                    // needs L slightly below 0 (at most 0.1 8-bit steps); counted too.
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
        addWarning(res, RoundtripWarning::OutOfRange,
                   formatMessage("%g LUT values would need to leave [0,1] (by up to %.3g, %.3g "
                                 "8-bit steps) to show the edited colours in game; they were "
                                 "clamped: the game cannot show those colours",
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
                    acc.add(gameShown(l[c], s[c]), clampUnit(want[c]));
            }
    res.gameError = acc.result();
    res.lut = std::move(out);
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
        addWarning(res, RoundtripWarning::Rescaled,
                   formatMessage(whole ? "the image was scaled by %g after embedding (cells of %g "
                                         "pixels, embedded at %g); read at the new size"
                                       : "the image was scaled by %g after embedding (cells of %g "
                                         "pixels, embedded at %g), not a whole number: only the "
                                         "block centres were read and may be blended; undo the "
                                         "resize",
                                 double(pl.cell) / pl.scale, pl.cell, pl.scale));
    }
    detail::checkPatch(patch, res);

    // How well the patch predicts the edit between its lattice points.
    res.subLatticeError = detail::subLatticeError(patch);
    res.expectedError = res.subLatticeError;
    res.expectedError.maxAbs /= 4.0;
    res.expectedError.meanAbs /= 4.0;

    const PatchFunction edit(patch.values, patch.axis);
    if (options.target == ExtractTarget::Raw) {
        // the smash lattice is not uniform: its raw LUT defaults to the game's 16^3
        const int m = options.outputSize > 0              ? options.outputSize
                      : pl.lattice == PatchLattice::Smash ? kSmashLutSize
                                                          : n;
        res.lut = rawLut(edit, m);
    } else {
        smashLut(edit, options.outputSize > 0 ? options.outputSize : kSmashLutSize,
                 options.originalLut, res);
    }
    res.lut.setTitle(std::string("extracted from a ") + std::to_string(n) + "^3 patch (" +
                     toString(options.target) + ")");
    addNote(res, std::string("patch: ") + std::to_string(n) + "^3 " + toString(pl.lattice) +
                     " lattice, " + toString(pl.layout) + " layout at scale " +
                     std::to_string(pl.scale) + ", frame at (" + std::to_string(pl.frameX) + ", " +
                     std::to_string(pl.frameY) + ")");
    addNote(res, "expected error between patch lattice points: " + res.expectedError.str() +
                     " (sub-lattice check at twice the spacing: " + res.subLatticeError.str() +
                     ")");
    if (options.target == ExtractTarget::Smash)
        addNote(res, "expected in-game error (8-bit LUT, trilinear, display-encoded): " +
                         res.gameError.str());
    return res;
}

} // namespace lut
