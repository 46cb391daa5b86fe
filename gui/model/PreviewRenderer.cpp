#include "PreviewRenderer.h"

#include "lut/pipeline/SmashCompensation.h"
#include "lut/pipeline/SmashGrading.h"
#include "lut/pipeline/Transfer.h"

#include <chrono>

namespace lut::gui {

PreviewChain previewChain(const PreviewOptions& o) {
    if (o.target == ExportTarget::Smash)
        return PreviewChain::Game;
    if (o.input == SceneKind::Screenshot || o.preset == Preset::None || o.preset == Preset::Smash)
        return PreviewChain::EncodedLut;
    return PreviewChain::EngineScene;
}

Preset effectivePreset(const PreviewOptions& o) {
    switch (previewChain(o)) {
    case PreviewChain::Game:
        return Preset::Smash;
    case PreviewChain::EncodedLut:
        return Preset::None;
    case PreviewChain::EngineScene:
        return o.preset;
    }
    return Preset::None;
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
    const bool screenshot = o.input == SceneKind::Screenshot;
    switch (previewChain(o)) {
    case PreviewChain::Game:
        return screenshot ? 1 : 2; // ungraded screenshot / linear scene
    case PreviewChain::EncodedLut:
        return screenshot ? 3 : 4; // stored values / display-encoded scene
    case PreviewChain::EngineScene:
        return 2;
    }
    return 0;
}

Image prepareScene(const Image& stored, bool storedIsFloat, const PreviewOptions& o, int nthreads) {
    Image scene = stored;
    if (scene.empty())
        return scene;
    const bool screenshot = o.input == SceneKind::Screenshot;
    // A screenshot holds display-encoded values whatever its pixel type (as lutkit preview).
    const bool storedIsLinear = storedIsFloat && !screenshot;
    switch (scenePreparationKey(o)) {
    case 1: // the game's picture: undo the display encoding and the neutral grading
        prepareSceneFrame(scene.view(), storedIsLinear, true, nullptr, Interpolation::Trilinear,
                          nthreads);
        break;
    case 2: // linear scene values
        prepareSceneFrame(scene.view(), storedIsLinear, false, nullptr, Interpolation::Trilinear,
                          nthreads);
        break;
    case 3: // the encoded values as stored: the LUT applies to them
        break;
    case 4: { // a linear scene as the none preset shows it, then the LUT on that
        prepareSceneFrame(scene.view(), storedIsLinear, false, nullptr, Interpolation::Trilinear,
                          nthreads);
        Pipeline none(Preset::None);
        RunOptions run;
        run.nthreads = nthreads;
        none.run(scene.view(), run);
        break;
    }
    }
    return scene;
}

PipelineSettings pipelineSettings(const PreviewOptions& o, std::shared_ptr<const Lut3D> lut) {
    PipelineSettings s;
    s.preset = effectivePreset(o);
    s.lut = std::move(lut);
    s.interpolation = o.interpolation;
    s.bloom = bloomApplied(o);
    switch (previewChain(o)) {
    case PreviewChain::Game:
        if (!o.brighten) // smash-grade always brightens: grade with the LUT that cancels it
            s.lut = std::make_shared<const Lut3D>(
                smashWithoutBrighten(s.lut ? *s.lut : Lut3D::identity(kSmashLutSize)));
        break;
    case PreviewChain::EncodedLut:
        // The LUT on the frame as it is (encoded values), nothing after it: lutkit apply.
        s.enable = {"lut"};
        s.disable = {"display"};
        break;
    case PreviewChain::EngineScene:
        break;
    }
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
