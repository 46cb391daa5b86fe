// SPDX-License-Identifier: Apache-2.0
#pragma once
// The preview recipe, composed once for `lutkit preview` and the editor (docs/architecture.md,
// "Why one plan"): whether the picture is an in-game screenshot or a linear scene (SceneKind.h's
// rule, or what the user said), which chain runs, what is undone before it, which stages run,
// the bloom rule, and what the chain's LUT must be for (lut/LutPurpose.h).
//
//   Game         preset smash: the game's chain with the game's LUT (smash). A screenshot is
//                sRGB-decoded and the game's grading with the stage LUT undone first; it gets no
//                bloom (it has the game's already) unless a bloom stage is asked for by name. A
//                scene runs the whole chain, bloom switchable.
//   EncodedLut   another preset on a screenshot (an engine's picture, its post-processing done),
//                and preset none on a scene: the LUT on the stored, display-encoded values and
//                nothing after it (lutkit apply); a scene is display-encoded first by the none
//                preset. The LUT is an edit (raw).
//   EngineScene  preset filmic or cinematic on a linear scene: that chain with the LUT (raw).
#include "lut/Error.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/LutPurpose.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/SceneKind.h"

#include <optional>
#include <string>
#include <vector>

namespace lut {

enum class PreviewChain { Game, EncodedLut, EngineScene };
const char* toString(PreviewChain chain); // "game", "encoded", "engine"

struct PreviewRequest {
    SceneEvidence evidence;               // what the file is (pixel type, tag, format)
    std::optional<SceneKind> forced;      // --from-screenshot / --scene, the editor's switch
    bool storedEncoded = false;           // the values were converted to sRGB first (--from)
    Preset preset = Preset::Smash;        // the chain asked for
    bool bloom = true;                    // false: no bloom stage (--no-bloom)
    std::vector<std::string> enable;      // stages switched on by name (--enable)
    std::vector<std::string> disable;     // ... off (--disable)
    std::vector<std::string> assignments; // "stage.param=value" (--stage)
    Interpolation interpolation = Interpolation::Trilinear; // the LUT's (the game's GPU: trilinear)
};

struct PreviewPlan {
    PreviewChain chain = PreviewChain::Game;
    SceneDecision scene;                       // screenshot or scene, and why
    bool decode = false;                       // sRGB-decode the stored values first
    bool undoGrading = false;                  // then undo the game's grading (with the stage LUT)
    bool displayEncode = false;                // EncodedLut on a scene: run the none preset first
    LutPurpose lutPurpose = LutPurpose::Smash; // what the chain's LUT must be
    PipelineSettings settings;                 // the chain (settings.lut left for the caller)
    bool bloomAdded = false;                   // a bloom stage runs
    // A screenshot gets no bloom because it has the game's (not because bloom was switched off):
    // the reason says so and the undo's "bloom cannot be undone" note is not repeated.
    bool bloomLeftToTheScreenshot = false;
    // What to say about the input (one line each: the scene decision, the bloom rule, an
    // --original-lut that a scene ignores, the LUT on stored values).
    Diagnostics notes;
};

// The plan for one picture; `stageLutGiven` says whether a stage LUT was named (a scene ignores
// it, with a note). Throws lut::Error for a stage or setting the pipeline does not know.
PreviewPlan planPreview(const PreviewRequest& request, bool stageLutGiven = false);

// What a chain's LUT is for, whatever the picture: smash for the game's chain, else raw (the same
// for every picture of a batch).
LutPurpose previewLutPurpose(Preset preset);

// The frame the chain starts from, in place, from the stored values as read (float RGBA: 8/16-bit
// values v/255, v/65535): decoded, the game's grading undone with `stageLut` (null: neutral), or
// display-encoded by the none preset, as the plan says. `stored8Bit` says the values are exactly
// k/255 (an 8-bit file): the decode then goes by table, bit-identical and faster. Returns the
// notes of the undo (bloom cannot be undone).
Diagnostics preparePreviewFrame(const PreviewPlan& plan, const ImageView& frame,
                                const Lut3D* stageLut, bool stored8Bit = false, int nthreads = 0);

// Plans with the same key start from the same prepared frame (the editor caches it).
int preparationKey(const PreviewPlan& plan);

} // namespace lut
