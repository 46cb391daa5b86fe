#pragma once
// The editor's preview: the same lutlib pipeline `lutkit preview` runs (lut/pipeline/Pipeline.h),
// as plain C++ so the document model and tests can use it without widgets. The worker thread in
// the app calls render(); everything here is re-entrant (no shared mutable state).
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/Pipeline.h"

#include <memory>
#include <string>

namespace lut::gui {

struct PreviewOptions {
    Preset preset = Preset::Smash;
    bool bloom = true;
    bool lutEnabled = true; // off: the pipeline runs with a neutral LUT
    bool brighten = true;   // smash-grade's brighten pass (only where the pipeline offers it)
    Interpolation interpolation = Interpolation::Trilinear;
    bool operator==(const PreviewOptions&) const = default;
};

// The scene frame the pipeline starts from, made once per opened image: stored values of
// 8/16-bit files are sRGB-decoded to linear, float files (EXR) are already linear scene values;
// fromScreenshot also undoes the game's grading (neutral LUT). Same call the CLI makes
// (lut::prepareSceneFrame).
Image prepareScene(const Image& stored, bool storedIsLinear, bool fromScreenshot = false,
                   int nthreads = 0);

// What a preview settings choice means for the pipeline.
PipelineSettings pipelineSettings(const PreviewOptions& options, std::shared_ptr<const Lut3D> lut);
// Whether the pipeline's smash-grade stage has a switch for its brighten pass.
bool brightenToggleAvailable();
// Whether "brighten off" can be previewed: with the stage's switch, or else by grading with
// withoutBrighten(lut), which is exact for trilinear and tetrahedral interpolation (the brighten
// inverse is affine in the input s, and both interpolations reproduce affine functions), not for
// nearest.
bool brightenToggleWorks(Interpolation method);
// The LUT L' with ((L'(s) - s) * 0.99961 + s) * 1.3703 == L(s) at every lattice point, so the
// Smash grading pass with L' shows L without its brighten step.
Lut3D withoutBrighten(const Lut3D& lut);

struct PreviewResult {
    Image image;               // display-encoded RGBA float, what `lutkit preview` writes
    double milliseconds = 0.0; // wall time of the pipeline run
    std::string report;        // PipelineReport::str()
};

// Runs the pipeline on a copy of `scene` (the prepared linear frame).
PreviewResult renderPreview(const Image& scene, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads = 0);

// The same preview in two parts, so a LUT edit re-runs only what the LUT affects:
//   renderBeforeLut  the stages before the first LUT stage (sanitize, bloom, vignette...: what
//                    depends only on the image and the preset), run once and cached;
//   renderFromLut    the LUT stage and everything after it (grading, brighten, display).
// Running stages one after the other is bit-identical to the fused whole-pipeline run
// (lut/pipeline/Stage.h), so renderFromLut(renderBeforeLut(x)) == renderPreview(x) (tested).
Image renderBeforeLut(const Image& scene, const PreviewOptions& options, int nthreads = 0);
PreviewResult renderFromLut(const Image& beforeLut, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads = 0);
// Whether a before-LUT frame made with options `a` is valid for options `b`.
bool sameBeforeLut(const PreviewOptions& a, const PreviewOptions& b);

// A box-filtered copy of `image` reduced by an integer factor (>= 1) in each direction: the
// proxy the editor previews on while a slider is being dragged.
Image downscale(const Image& image, int factor);

} // namespace lut::gui
