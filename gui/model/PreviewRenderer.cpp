// SPDX-License-Identifier: Apache-2.0
#include "PreviewRenderer.h"

#include "lut/pipeline/Transfer.h"
#include "lut/smash/SmashCompensation.h"
#include "lut/smash/SmashGrading.h"

#include <chrono>

namespace lut::gui {

PreviewPlan previewPlan(const PreviewOptions& o, ExportTarget target, bool storedIsFloat) {
    PreviewRequest q;
    q.evidence.storedIsFloat = storedIsFloat;
    q.evidence.bitDepth = storedIsFloat ? 32 : 8;
    q.forced = o.input;
    // The target's purpose picks the chain: the game's for its LUT, else the engine chain.
    q.preset = exportTargetInfo(target).purpose == LutPurpose::Smash ? Preset::Smash
               : o.preset == Preset::Smash                           ? Preset::None
                                                                     : o.preset;
    q.bloom = o.bloom;
    q.interpolation = o.interpolation;
    return planPreview(q);
}

PreviewChain previewChain(const PreviewOptions& o, ExportTarget target) {
    return previewPlan(o, target).chain;
}

Preset effectivePreset(const PreviewOptions& o, ExportTarget target) {
    return previewPlan(o, target).settings.preset;
}

bool bloomSwitchable(const PreviewOptions& o, ExportTarget target) {
    return o.input == SceneKind::Scene && previewChain(o, target) != PreviewChain::EncodedLut;
}

bool bloomApplied(const PreviewOptions& o, ExportTarget target) {
    return bloomSwitchable(o, target) && o.bloom;
}

bool brightenSwitchable(const PreviewOptions& o, ExportTarget target) {
    return previewChain(o, target) == PreviewChain::Game;
}

bool brightenApplied(const PreviewOptions& o, ExportTarget target) {
    return brightenSwitchable(o, target) && o.brighten;
}

bool showsTheExport(const PreviewOptions& o, ExportTarget target) {
    return o.lutEnabled && (!brightenSwitchable(o, target) || o.brighten);
}

int scenePreparationKey(const PreviewOptions& o, ExportTarget target) {
    // The stored values' type does not change between option changes of one picture; the key
    // compares preparations of the same picture.
    return preparationKey(previewPlan(o, target, o.input == SceneKind::Scene));
}

Image prepareScene(const Image& stored, bool storedIsFloat, const PreviewOptions& o,
                   ExportTarget target, int nthreads) {
    Image scene = stored;
    if (scene.empty())
        return scene;
    (void)preparePreviewFrame(previewPlan(o, target, storedIsFloat), scene.view(), nullptr, false,
                              nthreads);
    return scene;
}

PipelineSettings pipelineSettings(const PreviewOptions& o, ExportTarget target,
                                  std::shared_ptr<const Lut3D> lut) {
    PipelineSettings s = previewPlan(o, target).settings;
    s.lut = std::move(lut);
    if (previewChain(o, target) == PreviewChain::Game && !o.brighten)
        // smash-grade always brightens: grade with the LUT that cancels it (an inspection view)
        s.lut = std::make_shared<const Lut3D>(
            smashWithoutBrighten(s.lut ? *s.lut : Lut3D::identity(kSmashLutSize)));
    return s;
}

namespace {

PreviewResult runPart(const Image& frame, const PreviewOptions& options, ExportTarget target,
                      std::shared_ptr<const Lut3D> lut, PipelinePart part, int nthreads) {
    const auto start = std::chrono::steady_clock::now();
    Pipeline pipeline(pipelineSettings(options, target, std::move(lut)));
    RunOptions run;
    run.nthreads = nthreads;
    run.part = part;
    PipelineReport report;
    PreviewResult result;
    result.image = pipeline.run(frame, run, &report);
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.report = report.str();
    return result;
}

} // namespace

PreviewResult renderPreview(const Image& scene, const PreviewOptions& options, ExportTarget target,
                            std::shared_ptr<const Lut3D> lut, int nthreads) {
    return runPart(scene, options, target, std::move(lut), PipelinePart::Whole, nthreads);
}

Image renderBeforeLut(const Image& scene, const PreviewOptions& options, ExportTarget target,
                      int nthreads) {
    return runPart(scene, options, target, nullptr, PipelinePart::BeforeLut, nthreads).image;
}

PreviewResult renderFromLut(const Image& beforeLut, const PreviewOptions& options,
                            ExportTarget target, std::shared_ptr<const Lut3D> lut, int nthreads) {
    return runPart(beforeLut, options, target, std::move(lut), PipelinePart::FromLut, nthreads);
}

bool sameBeforeLut(const PreviewOptions& a, ExportTarget ta, const PreviewOptions& b,
                   ExportTarget tb) {
    return scenePreparationKey(a, ta) == scenePreparationKey(b, tb) &&
           Pipeline(pipelineSettings(a, ta, nullptr))
               .sameBeforeLut(Pipeline(pipelineSettings(b, tb, nullptr)));
}

Image renderBefore(const Image& stored, const Image& scene, const PreviewOptions& options,
                   ExportTarget target, std::shared_ptr<const Lut3D> neutralLut, int nthreads) {
    if (options.input == SceneKind::Screenshot)
        return stored;
    PreviewOptions o = options;
    o.lutEnabled = true;
    o.brighten = true;
    return renderPreview(scene, o, target, std::move(neutralLut), nthreads).image;
}

} // namespace lut::gui
