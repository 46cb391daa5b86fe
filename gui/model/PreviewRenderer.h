// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor's preview: the same lutlib pipeline `lutkit preview` runs (lut/pipeline/Pipeline.h),
// as plain C++ so the document model and tests can use it without widgets. The preview worker
// (PreviewController) calls these; everything here is re-entrant (no shared mutable state).
//
// Which chain runs, what is undone and which stages run is the library's one recipe
// (lut/pipeline/PreviewPlan.h, shared with `lutkit preview`): the export target's purpose picks
// the preset (smash: the game's chain; engine and cube: the engine chain chosen for a linear
// scene, else none), the picture's kind (lut::SceneKind) the rest:
//   Game        target Smash: the game's chain. A screenshot is first ungraded and gets no bloom
//               (it has the game's already); a linear scene runs the whole chain, bloom
//               switchable.
//   EncodedLut  targets Engine and Grading on a screenshot, or on a linear scene with the chain
//               "none" (display-encoded first): the LUT on the encoded values (lutkit apply).
//   EngineScene targets Engine and Grading on a linear scene with the filmic or cinematic chain.
// What the editor adds: the LUT switch (neutral export) and the brighten switch (an inspection
// view of the game's chain).
#include "ExportTarget.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/pipeline/SceneKind.h"

#include <memory>
#include <string>

namespace lut::gui {

// How the preview shows the document's LUT. What the LUT is made for (the export target) is the
// document's (Document::target), passed beside these options to every function below.
struct PreviewOptions {
    SceneKind input = SceneKind::Screenshot; // set from the image when it opens, switchable
    Preset preset = Preset::None; // the engine chain of a linear scene (Engine, Grading targets)
    bool bloom = true;            // linear scenes only: a screenshot has its bloom already
    bool lutEnabled = true;       // off: the neutral document's export (what "before" shows)
    bool brighten = true; // the game's brighten step (Game chain); off is an inspection view
    Interpolation interpolation = Interpolation::Trilinear;
    bool operator==(const PreviewOptions&) const = default;
};

// The library's recipe for these options, the target and a picture whose stored values are float or
// not.
PreviewPlan previewPlan(const PreviewOptions& options, ExportTarget target,
                        bool storedIsFloat = false);
PreviewChain previewChain(const PreviewOptions& options, ExportTarget target);
// The pipeline preset the chain runs (smash, none or the engine chain).
Preset effectivePreset(const PreviewOptions& options, ExportTarget target);

// Bloom: only a linear scene gets it, in the chains that have a bloom stage.
bool bloomSwitchable(const PreviewOptions& options, ExportTarget target);
bool bloomApplied(const PreviewOptions& options, ExportTarget target);
// Brighten: the Game chain has the step; off grades with lut::smashWithoutBrighten(lut), which
// shows the LUT with no brighten step (exact for trilinear and tetrahedral, within
// lut::smashWithoutBrightenError for nearest). Not what the game shows: an inspection view.
bool brightenSwitchable(const PreviewOptions& options, ExportTarget target);
bool brightenApplied(const PreviewOptions& options, ExportTarget target);
// Whether the options show what the target's export gives (no inspection switch is on).
bool showsTheExport(const PreviewOptions& options, ExportTarget target);

// The frame the pipeline starts from, made once per image and chain (see the chains above):
// storedIsFloat is the file's pixel type (lut::formats::ImageInfo::isFloat).
Image prepareScene(const Image& stored, bool storedIsFloat, const PreviewOptions& options,
                   ExportTarget target, int nthreads = 0);
// Options and targets with the same key give the same prepared scene.
int scenePreparationKey(const PreviewOptions& options, ExportTarget target);

// What a preview settings choice means for the pipeline; `lut` is the LUT to grade with (the
// target's export read back, lut::gui::TargetLut::shown).
PipelineSettings pipelineSettings(const PreviewOptions& options, ExportTarget target,
                                  std::shared_ptr<const Lut3D> lut);

struct PreviewResult {
    Image image;               // display-encoded RGBA float, what `lutkit preview` writes
    double milliseconds = 0.0; // wall time of the pipeline run
    std::string report;        // PipelineReport::str()
};

// Runs the pipeline on a copy of `scene` (the prepared frame).
PreviewResult renderPreview(const Image& scene, const PreviewOptions& options, ExportTarget target,
                            std::shared_ptr<const Lut3D> lut, int nthreads = 0);

// The same preview in the pipeline's two parts (lut::PipelinePart), so a LUT edit re-runs only
// what the LUT affects:
//   renderBeforeLut  the stages before the first LUT stage (sanitize, bloom, vignette...: what
//                    depends only on the image and the preset), run once and cached;
//   renderFromLut    the LUT stage and everything after it (grading, brighten, display).
// renderFromLut(renderBeforeLut(x)) == renderPreview(x) bit for bit (tested).
Image renderBeforeLut(const Image& scene, const PreviewOptions& options, ExportTarget target,
                      int nthreads = 0);
PreviewResult renderFromLut(const Image& beforeLut, const PreviewOptions& options,
                            ExportTarget target, std::shared_ptr<const Lut3D> lut,
                            int nthreads = 0);
// Whether a before-LUT frame made with options `a` for target `ta` is valid for options `b` and
// target `tb` (lut::Pipeline::sameBeforeLut of the two pipelines).
bool sameBeforeLut(const PreviewOptions& a, ExportTarget ta, const PreviewOptions& b,
                   ExportTarget tb);

// The "before" picture: the input as the user knows it. A screenshot as stored; a linear scene
// through the same chain with the neutral document's export (`neutralLut`), so a neutral LUT
// shows no difference across the divider.
Image renderBefore(const Image& stored, const Image& scene, const PreviewOptions& options,
                   ExportTarget target, std::shared_ptr<const Lut3D> neutralLut, int nthreads = 0);

} // namespace lut::gui
