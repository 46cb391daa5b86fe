// SPDX-License-Identifier: Apache-2.0
// Extract: the LUT from a read patch, for a raw engine (the edit itself) or for the game (the
// edit composed with what the game does to its LUT's output, lut/smash/SmashAuthoring.h); see
// lut/roundtrip/Extract.h, docs/roundtrip.md and, for the game's side,
// docs/specs/smash-pipeline.md.
#include "lut/roundtrip/Extract.h"

#include "lut/interp/Sampler.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/LutDigest.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/smash/GameDisplay.h"
#include "lut/smash/SmashAuthoring.h"
#include "lut/smash/SmashConstants.h"
#include "roundtrip/ExtractBounds.h"
#include "roundtrip/ExtractChecks.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace lut {

using detail::addNote;
using detail::addWarning;
using detail::fmt;

const char* toString(TargetSource s) {
    switch (s) {
    case TargetSource::Option:
        return "given";
    case TargetSource::Patch:
        return "recorded in the patch";
    case TargetSource::Lattice:
        return "the patch's lattice";
    }
    return "?";
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

std::string patchText(const PatchPlacement& pl) {
    std::string s = std::to_string(pl.size) + "^3 " + toString(pl.lattice) + " lattice";
    if (pl.lattice == PatchLattice::SmashStage)
        s += " for the stage LUT " + digestText(pl.stageDigest.value_or(0));
    s += ", " + std::string(toString(pl.layout)) + " layout at scale " + std::to_string(pl.scale) +
         ", " + std::to_string(pl.bitDepth) + "-bit";
    if (pl.target)
        s += std::string(", made for ") + toString(*pl.target);
    if (pl.headerVersion == 1)
        s += " (an older patch: no target recorded)";
    return s + ", frame at (" + std::to_string(pl.frameX) + ", " + std::to_string(pl.frameY) + ")";
}

void resolveTarget(const PatchPlacement& pl, const ExtractOptions& o, ExtractResult& res) {
    if (o.target) {
        res.target = *o.target;
        res.targetSource = TargetSource::Option;
    } else if (pl.target) {
        res.target = *pl.target;
        res.targetSource = TargetSource::Patch;
    } else {
        res.target = isGameDisplayLattice(pl.lattice) ? LutPurpose::Smash : LutPurpose::Raw;
        res.targetSource = TargetSource::Lattice;
    }
}

// The stage LUT the caller gave against the digest the patch recorded.
void checkStage(const PatchReading& patch, const ExtractOptions& o, ExtractResult& res) {
    const PatchPlacement& pl = patch.placement;
    if (!o.originalLut)
        return;
    const std::uint16_t given = lutDigest(*o.originalLut);
    if (pl.stageDigest && *pl.stageDigest != given)
        addWarning(res, RoundtripWarning::StageMismatch,
                   "the patch was embedded for the stage LUT " + digestText(*pl.stageDigest) +
                       " but the original LUT given is " + digestText(given) +
                       ": the patch's colours are that LUT's picture, the given one is ignored");
    else if (!pl.stageDigest && pl.headerVersion >= 2 && isGameDisplayLattice(pl.lattice))
        addNote(res, "the patch was embedded for a neutral stage; the original LUT " +
                         digestText(given) +
                         " is applied by interpolating the patch (embed --original-lut reads the "
                         "edit at exactly its colours)");
}

// Chroma subsampling from the file's metadata and the patch's pixels: said, and a warning when
// the patch's blocks do not line up with the subsampling grid.
void checkChromaSubsampling(const PatchReading& patch, const ExtractOptions& o,
                            ExtractResult& res) {
    const PatchPlacement& pl = patch.placement;
    const std::string& meta = o.fileChromaSubsampling;
    const std::string seen = patch.chroma.scheme();
    const bool metaSubsampled = !meta.empty() && meta != "4:4:4";
    const bool seenSubsampled = !seen.empty() && seen != "4:4:4";
    if (!metaSubsampled && !seenSubsampled) {
        if (!meta.empty())
            addNote(res, "the file stores chroma at full resolution (" + meta + ")");
        return;
    }
    std::string how;
    if (!meta.empty())
        how = "the file's metadata says " + meta;
    if (!seen.empty())
        how += std::string(how.empty() ? "" : "; ") + "the patch's pixels show " + seen +
               fmt(" (colour edges %.0f%% as sharp as brightness edges)",
                   100.0 * std::min(patch.chroma.chromaSharpness[0] /
                                        std::max(patch.chroma.lumaSharpness[0], 1e-9),
                                    patch.chroma.chromaSharpness[1] /
                                        std::max(patch.chroma.lumaSharpness[1], 1e-9)));
    const bool aligned = pl.cell >= kDefaultPatchScale && pl.patchX() % kJpegGrid == 0 &&
                         pl.patchY() % kJpegGrid == 0 && pl.cell % 8 == 0;
    if (aligned) {
        addNote(res, "chroma subsampling: " + how +
                         "; the patch's blocks line up with the JPEG grid, so colours blend only "
                         "inside them (the expected error includes what is left)");
        return;
    }
    addWarning(res, RoundtripWarning::ChromaSubsampling,
               "chroma subsampling: " + how +
                   ": the colour of each entry blended with its neighbours' (the patch's " +
                   std::to_string(pl.cell) + "-pixel blocks at (" + std::to_string(pl.patchX()) +
                   ", " + std::to_string(pl.patchY()) +
                   ") are not on the 16-pixel JPEG grid). Save the graded image as PNG or TIFF "
                   "(or JPEG with 4:4:4 chroma), or embed again with the default --scale 8 and "
                   "do not crop before saving");
}

// --strength: every entry of the edit moved back towards what it was before the edit (a stage
// patch's colours before the edit, else its lattice inputs).
void blendEdit(PatchReading& patch, bool stage, const StrengthOptions& strength,
               ExtractResult& res) {
    if (stage && !patch.inputs)
        throw Error("a partial strength needs the colours this patch held before the edit: name "
                    "the stage's LUT it was embedded with (--original-lut)");
    const StrengthAmounts a = strengthAmounts(strength);
    const int n = patch.values.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 before = stage ? patch.inputs->at(r, g, b)
                                               : glm::vec3(patch.axis[static_cast<std::size_t>(r)],
                                                           patch.axis[static_cast<std::size_t>(g)],
                                                           patch.axis[static_cast<std::size_t>(b)]);
                patch.values.at(r, g, b) = glm::vec3(
                    blendStrength(glm::dvec3(before), glm::dvec3(patch.values.at(r, g, b)), a));
            }
    addNote(res, fmt("strength: the edit blended with the picture before it, lightness "
                     "%g, chroma %g (Oklab)",
                     a.luma, a.chroma));
}

} // namespace

ExtractResult extractLut(const ImageView& edited, const ExtractOptions& options) {
    const FindResult found = findPatch(edited);
    if (found.status != FindStatus::Found)
        throw Error(found.message);
    const PatchReading patch = readPatch(edited, found.placement);
    return extractLut(patch, options);
}

ExtractResult extractLut(const PatchReading& reading, const ExtractOptions& options) {
    ExtractResult res;
    res.placement = reading.placement;
    const PatchPlacement& pl = reading.placement;
    const int n = reading.values.size();
    resolveTarget(pl, options, res);
    checkStage(reading, options, res);
    const bool stage = pl.lattice == PatchLattice::SmashStage;
    const bool stageMatches =
        stage && options.originalLut && pl.stageDigest == lutDigest(*options.originalLut);
    PatchReading patch = reading;
    if (stageMatches)
        patch.inputs = stagePatchInputs(*options.originalLut, n, pl.bitDepth);

    if (pl.cell != pl.scale) {
        const bool whole = pl.cell % pl.scale == 0;
        addWarning(res, RoundtripWarning::Rescaled,
                   fmt(whole ? "the image was scaled by %g after embedding (cells of %g "
                               "pixels, embedded at %g); read at the new size"
                             : "the image was scaled by %g after embedding (cells of %g "
                               "pixels, embedded at %g), not a whole number: only the "
                               "block centres were read and may be blended; undo the "
                               "resize",
                       double(pl.cell) / pl.scale, double(pl.cell), double(pl.scale)));
    }
    const bool lossyFile = !options.fileChromaSubsampling.empty() ||
                           (patch.chroma.measured && patch.chroma.scheme() != "4:4:4");
    detail::checkPatch(patch, res, lossyFile);
    checkChromaSubsampling(patch, options, res);

    const detail::SubLattice sub = detail::subLatticeCheck(patch);
    res.subLattice = sub.stats;
    const detail::ReadNoise noise = detail::estimateReadNoise(patch);
    double noiseSum = 0.0;
    for (std::size_t i = 0; i < noise.max.entryCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            res.readNoiseMax = std::max(res.readNoiseMax, double(noise.max.entries()[i][c]));
            noiseSum += noise.mean.entries()[i][c];
        }
    res.readNoiseMean = noiseSum / (3.0 * static_cast<double>(noise.max.entryCount()));

    if (!isFullStrength(options.strength))
        blendEdit(patch, stage, options.strength, res);
    const PatchFunction edit(patch.values, patch.axis);
    if (res.target == LutPurpose::Raw) {
        if (stage)
            throw Error("this patch was embedded for the game with a stage LUT: its colours are "
                        "that LUT's picture, not a lattice a raw LUT can be read from; extract it "
                        "with --target smash, or embed again with --target raw");
        // the game-display lattice is not uniform: its raw LUT defaults to the game's 16^3
        const int m = options.outputSize > 0             ? options.outputSize
                      : isGameDisplayLattice(pl.lattice) ? kSmashLutSize
                                                         : n;
        res.lut = rawLut(edit, m);
        res.expected = detail::rawExpectedError(patch, sub, noise, res.lut, edit, res.modelError,
                                                options.nthreads);
    } else if (pl.lattice == PatchLattice::SmushLegacy) {
        // Smush-LUT's model: the strip's edited values are the game's LUT (the screenshot was
        // darkened to the LUT's own values before grading); nothing to compensate.
        if (options.outputSize > 0 && options.outputSize != kSmashLutSize)
            throw Error("the game's LUT is " + std::to_string(kSmashLutSize) + "^3; --size " +
                        std::to_string(options.outputSize) + " does not apply to --target smash");
        res.lut = patch.values;
        for (auto& e : res.lut.entries())
            for (int c = 0; c < 3; ++c)
                e[c] = static_cast<float>(detail::clampUnit(e[c]));
        GameError at, all;
        at.maxSteps = res.readNoiseMax;
        at.meanSteps = res.readNoiseMean;
        at.p99Steps = res.readNoiseMax;
        // between the strip's points: all of the sub-lattice residual for the largest values
        // (as for every patch, ExtractBounds.cpp), half for the mean
        all.maxSteps = res.readNoiseMax + res.subLattice.maxSteps;
        all.meanSteps = res.readNoiseMean + 0.5 * res.subLattice.meanSteps;
        all.p99Steps = res.readNoiseMax + res.subLattice.p99Steps;
        res.expected.atLattice = at;
        res.expected.overall = all;
        res.expected.covers = "the LUT's values against Smush-LUT's model (the strip's edit is an "
                              "edit of the LUT's own values), 8-bit steps";
    } else {
        if (options.outputSize > 0 && options.outputSize != kSmashLutSize)
            throw Error("the game's LUT is " + std::to_string(kSmashLutSize) + "^3; --size " +
                        std::to_string(options.outputSize) + " does not apply to --target smash");
        std::unique_ptr<Sampler> original;
        if (options.originalLut && !stage)
            original = makeSampler(*options.originalLut, Interpolation::Trilinear);
        // What the modder wants the game to show for its LUT input s: a stage patch holds it on
        // the game's own lattice (interpolated in s between entries); other patches hold the
        // edit, read at the colour the unedited game showed for s.
        const std::function<glm::dvec3(const glm::dvec3&)> wanted = [&](const glm::dvec3& s) {
            if (stage)
                return glm::dvec3(edit(glm::vec3(s)));
            const glm::vec3 l0 = original ? original->sample(glm::vec3(s)) : glm::vec3(s);
            glm::vec3 shot;
            for (int c = 0; c < 3; ++c)
                shot[c] = static_cast<float>(detail::gameShown(l0[c], s[c]));
            return glm::dvec3(edit(shot));
        };
        // The same from the display's table (within 0.0003 8-bit steps) for the expected error,
        // which evaluates it at ~700k inputs: the authoring above keeps the exact display.
        const std::function<glm::dvec3(const glm::dvec3&)> wantedFast = [&](const glm::dvec3& s) {
            if (stage)
                return glm::dvec3(edit(glm::vec3(s)));
            const glm::vec3 l0 = original ? original->sample(glm::vec3(s)) : glm::vec3(s);
            glm::vec3 shot;
            for (int c = 0; c < 3; ++c)
                shot[c] = static_cast<float>(detail::gameShownTabulated(l0[c], s[c]));
            return glm::dvec3(edit(shot));
        };
        SmashAuthoringOptions ao;
        ao.gameLut = stage ? nullptr : options.originalLut;
        ao.refine = options.refine;
        ao.measure = options.refine;
        ao.nthreads = options.nthreads;
        SmashAuthoringResult authored = authorSmashLut(wanted, ao);
        res.clampedEntries = authored.clampedEntries;
        res.clampedMax = authored.clampedMax;
        res.refined = authored.refined;
        res.exactModelError = authored.exactError;
        res.refineDecision = authored.refinementComputed ? "fitted on " + authored.fittedOn +
                                                               "; written: " + authored.decision
                                                         : std::string();
        res.lut = std::move(authored.lut);
        // Below half an 8-bit step the clamp cannot change a stored entry: no warning (the CLI
        // still says how many were clamped).
        if (res.clampedEntries > 0 && res.clampedMax * 255.0 >= 0.5)
            addWarning(res, RoundtripWarning::OutOfRange,
                       fmt("%g LUT values would need to leave [0,1] (by up to %.3g, "
                           "%.3g 8-bit steps) to show the edited colours in game; they "
                           "were clamped: the game cannot show those colours",
                           double(res.clampedEntries), res.clampedMax, res.clampedMax * 255.0));
        res.expected = detail::smashExpectedError(patch, sub, noise, quantized8(res.lut),
                                                  wantedFast, stage ? nullptr : options.originalLut,
                                                  res.modelError, options.nthreads);
    }
    res.lut.setTitle(std::string("extracted from a ") + std::to_string(n) + "^3 patch (" +
                     toString(res.target) + ")");
    addNote(res, "patch: " + patchText(pl));
    addNote(res, std::string("target: ") + toString(res.target) + " (" +
                     (res.targetSource == TargetSource::Option && !options.targetReason.empty()
                          ? options.targetReason
                          : std::string(toString(res.targetSource))) +
                     ")");
    addNote(res, "expected error, an upper estimate from the patch's own redundancy (" +
                     res.expected.covers + "):");
    addNote(res, "  at the LUT's lattice points: " + res.expected.atLattice.str());
    addNote(res,
            "  over all inputs, between the lattice points too: " + res.expected.overall.str());
    addNote(res, fmt("  made of: read error of the entries up to %.2f steps (storage, "
                     "blocks, neighbouring entries, marker cells), interpolation "
                     "between patch entries up to %.2f (sub-lattice check and each "
                     "entry against its neighbours), the LUT itself up to %.2f at "
                     "the points measured",
                     res.readNoiseMax, res.expected.interpolationSteps, res.modelError.maxSteps));
    if (!res.refineDecision.empty())
        addNote(res, "least-squares refinement: " + res.refineDecision);
    return res;
}

} // namespace lut
