#include "PreviewRenderer.h"

#include "lut/Parallel.h"
#include "lut/io/Format.h"
#include "lut/pipeline/SmashGrading.h"

#include <algorithm>
#include <chrono>

namespace lut::gui {

Image prepareScene(const Image& stored, bool storedIsLinear, bool fromScreenshot, int nthreads) {
    Image scene = stored;
    if (!scene.empty())
        prepareSceneFrame(scene.view(), storedIsLinear, fromScreenshot, nullptr,
                          Interpolation::Trilinear, nthreads);
    return scene;
}

bool brightenToggleAvailable() {
    static const bool available = [] {
        try {
            const auto stage = makeStage("smash-grade");
            for (const auto& p : stage->params())
                if (p.name == "brighten")
                    return true;
        } catch (const std::exception&) {
        }
        return false;
    }();
    return available;
}

bool brightenToggleWorks(Interpolation method) {
    return brightenToggleAvailable() || method != Interpolation::Nearest;
}

Lut3D withoutBrighten(const Lut3D& lut) {
    Lut3D out = lut;
    for (int b = 0; b < lut.size(); ++b)
        for (int g = 0; g < lut.size(); ++g)
            for (int r = 0; r < lut.size(); ++r)
                out.at(r, g, b) = smashBrightenInverse(lut.at(r, g, b), lut.latticeInput(r, g, b));
    return out;
}

PipelineSettings pipelineSettings(const PreviewOptions& options, std::shared_ptr<const Lut3D> lut) {
    PipelineSettings s;
    s.preset = options.preset;
    s.lut = options.lutEnabled ? std::move(lut) : nullptr;
    s.interpolation = options.interpolation;
    s.bloom = options.bloom;
    if (!options.brighten && options.preset == Preset::Smash) {
        if (brightenToggleAvailable()) {
            s.assignments.push_back("smash-grade.brighten=0");
        } else if (options.interpolation != Interpolation::Nearest) {
            // The stage has no switch: grade with the LUT whose brighten cancels out.
            s.lut = std::make_shared<const Lut3D>(
                withoutBrighten(s.lut ? *s.lut : Lut3D::identity(kSmashLutSize)));
        }
    }
    return s;
}

PreviewResult renderPreview(const Image& scene, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads) {
    const auto start = std::chrono::steady_clock::now();
    Pipeline pipeline(pipelineSettings(options, std::move(lut)));
    RunOptions run;
    run.nthreads = nthreads;
    PipelineReport report;
    PreviewResult result;
    result.image = pipeline.run(scene, run, &report);
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.report = report.str();
    return result;
}

namespace {

bool isLutStage(const std::string& name) {
    return name == "smash-grade" || name == "lut";
}

// Enables only the stages before (before = true) or from (false) the first LUT stage, keeping
// the preset's choice for the rest.
void keepPart(Pipeline& pipeline, bool before) {
    bool reached = false;
    for (const auto& stage : pipeline.stages()) {
        reached = reached || isLutStage(stage->name());
        if (reached == before)
            stage->setEnabled(false);
    }
}

} // namespace

bool sameBeforeLut(const PreviewOptions& a, const PreviewOptions& b) {
    return a.preset == b.preset && a.bloom == b.bloom;
}

Image renderBeforeLut(const Image& scene, const PreviewOptions& options, int nthreads) {
    Pipeline pipeline(pipelineSettings(options, nullptr));
    keepPart(pipeline, true);
    RunOptions run;
    run.nthreads = nthreads;
    return pipeline.run(scene, run);
}

PreviewResult renderFromLut(const Image& beforeLut, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads) {
    const auto start = std::chrono::steady_clock::now();
    Pipeline pipeline(pipelineSettings(options, std::move(lut)));
    keepPart(pipeline, false);
    RunOptions run;
    run.nthreads = nthreads;
    PipelineReport report;
    PreviewResult result;
    result.image = pipeline.run(beforeLut, run, &report);
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.report = report.str();
    return result;
}

Image downscale(const Image& image, int factor) {
    if (factor <= 1 || image.empty())
        return image;
    const int w = std::max(1, image.width() / factor);
    const int h = std::max(1, image.height() / factor);
    Image out(w, h);
    parallelFor(h, 0, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                float acc[4] = {0, 0, 0, 0};
                int n = 0;
                for (int dy = 0; dy < factor; ++dy) {
                    const int sy = std::min(y * factor + dy, image.height() - 1);
                    for (int dx = 0; dx < factor; ++dx) {
                        const int sx = std::min(x * factor + dx, image.width() - 1);
                        const float* p = image.pixel(sx, sy);
                        for (int c = 0; c < 4; ++c)
                            acc[c] += p[c];
                        ++n;
                    }
                }
                float* o = out.pixel(x, y);
                for (int c = 0; c < 4; ++c)
                    o[c] = acc[c] / static_cast<float>(n);
            }
    });
    return out;
}

} // namespace lut::gui
