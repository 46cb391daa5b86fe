#include "PreviewRenderer.h"

#include "lut/pipeline/Transfer.h"
#include "lut/smash/SmashCompensation.h"
#include "lut/smash/SmashGrading.h"

#include <chrono>

namespace lut::gui {

PreviewPlan previewPlan(const PreviewOptions& o, bool storedIsFloat) {
    PreviewRequest q;
    q.evidence.storedIsFloat = storedIsFloat;
    q.evidence.bitDepth = storedIsFloat ? 32 : 8;
    q.forced = o.input;
    // The target's purpose picks the chain: the game's for its LUT, else the engine chain.
    q.preset = exportTargetInfo(o.target).purpose == LutPurpose::Smash ? Preset::Smash
               : o.preset == Preset::Smash                             ? Preset::None
                                                                       : o.preset;
    q.bloom = o.bloom;
    q.interpolation = o.interpolation;
    return planPreview(q);
}

PreviewChain previewChain(const PreviewOptions& o) {
    return previewPlan(o).chain;
}

Preset effectivePreset(const PreviewOptions& o) {
    return previewPlan(o).settings.preset;
}

bool bloomSwitchable(const PreviewOptions& o) {
    return o.input == SceneKind::Scene && previewChain(o) != PreviewChain::EncodedLut;
}

bool bloomApplied(const PreviewOptions& o) {
    return bloomSwitchable(o) && o.bloom;
}

bool brightenSwitchable(const PreviewOptions& o) {
    return previewChain(o) == PreviewChain::Game;
}

bool brightenApplied(const PreviewOptions& o) {
    return brightenSwitchable(o) && o.brighten;
}

bool showsTheExport(const PreviewOptions& o) {
    return o.lutEnabled && (!brightenSwitchable(o) || o.brighten);
}

int scenePreparationKey(const PreviewOptions& o) {
    // The stored values' type does not change between option changes of one picture; the key
    // compares preparations of the same picture.
    return preparationKey(previewPlan(o, o.input == SceneKind::Scene));
}

Image prepareScene(const Image& stored, bool storedIsFloat, const PreviewOptions& o, int nthreads) {
    Image scene = stored;
    if (scene.empty())
        return scene;
    (void)preparePreviewFrame(previewPlan(o, storedIsFloat), scene.view(), nullptr, false,
                              nthreads);
    return scene;
}

PipelineSettings pipelineSettings(const PreviewOptions& o, std::shared_ptr<const Lut3D> lut) {
    PipelineSettings s = previewPlan(o).settings;
    s.lut = std::move(lut);
    if (previewChain(o) == PreviewChain::Game && !o.brighten)
        // smash-grade always brightens: grade with the LUT that cancels it (an inspection view)
        s.lut = std::make_shared<const Lut3D>(
            smashWithoutBrighten(s.lut ? *s.lut : Lut3D::identity(kSmashLutSize)));
    return s;
}

namespace {

PreviewResult runPart(const Image& frame, const PreviewOptions& options,
                      std::shared_ptr<const Lut3D> lut, PipelinePart part, int nthreads) {
    const auto start = std::chrono::steady_clock::now();
    Pipeline pipeline(pipelineSettings(options, std::move(lut)));
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

PreviewResult renderPreview(const Image& scene, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads) {
    return runPart(scene, options, std::move(lut), PipelinePart::Whole, nthreads);
}

Image renderBeforeLut(const Image& scene, const PreviewOptions& options, int nthreads) {
    return runPart(scene, options, nullptr, PipelinePart::BeforeLut, nthreads).image;
}

PreviewResult renderFromLut(const Image& beforeLut, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads) {
    return runPart(beforeLut, options, std::move(lut), PipelinePart::FromLut, nthreads);
}

bool sameBeforeLut(const PreviewOptions& a, const PreviewOptions& b) {
    return scenePreparationKey(a) == scenePreparationKey(b) &&
           Pipeline(pipelineSettings(a, nullptr))
               .sameBeforeLut(Pipeline(pipelineSettings(b, nullptr)));
}

Image renderBefore(const Image& stored, const Image& scene, const PreviewOptions& options,
                   std::shared_ptr<const Lut3D> neutralLut, int nthreads) {
    if (options.input == SceneKind::Screenshot)
        return stored;
    PreviewOptions o = options;
    o.lutEnabled = true;
    o.brighten = true;
    return renderPreview(scene, o, std::move(neutralLut), nthreads).image;
}

} // namespace lut::gui
