#include "PreviewRenderer.h"

#include "lut/pipeline/SmashCompensation.h"
#include "lut/pipeline/SmashGrading.h"

#include <chrono>

namespace lut::gui {

Image prepareScene(const Image& stored, bool storedIsLinear, bool fromScreenshot, int nthreads) {
    Image scene = stored;
    if (!scene.empty())
        prepareSceneFrame(scene.view(), storedIsLinear, fromScreenshot, nullptr,
                          Interpolation::Trilinear, nthreads);
    return scene;
}

bool brightenSwitchable(const PreviewOptions& options) {
    return options.preset == Preset::Smash;
}

bool brightenApplied(const PreviewOptions& options) {
    return options.preset == Preset::Smash && options.brighten;
}

PipelineSettings pipelineSettings(const PreviewOptions& options, std::shared_ptr<const Lut3D> lut) {
    PipelineSettings s;
    s.preset = options.preset;
    s.lut = options.lutEnabled ? std::move(lut) : nullptr;
    s.interpolation = options.interpolation;
    s.bloom = options.bloom;
    if (brightenSwitchable(options) && !brightenApplied(options)) {
        // smash-grade always brightens: grade with the LUT whose brighten step cancels out.
        s.lut = std::make_shared<const Lut3D>(
            smashWithoutBrighten(s.lut ? *s.lut : Lut3D::identity(kSmashLutSize)));
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
    return Pipeline(pipelineSettings(a, nullptr))
        .sameBeforeLut(Pipeline(pipelineSettings(b, nullptr)));
}

Image renderBefore(const Image& scene, int nthreads) {
    PreviewOptions none;
    none.preset = Preset::None;
    none.lutEnabled = false;
    none.bloom = false;
    return renderPreview(scene, none, nullptr, nthreads).image;
}

} // namespace lut::gui
