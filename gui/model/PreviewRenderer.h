#pragma once
// The editor's preview: the same lutlib pipeline `lutkit preview` runs (lut/pipeline/Pipeline.h),
// as plain C++ so the document model and tests can use it without widgets. The preview worker
// (PreviewController) calls these; everything here is re-entrant (no shared mutable state).
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
    bool brighten = true;   // smash-grade's brighten step (the smash preset has one, no other)
    Interpolation interpolation = Interpolation::Trilinear;
    bool operator==(const PreviewOptions&) const = default;
};

// The scene frame the pipeline starts from, made once per opened image: stored values of
// 8/16-bit files are sRGB-decoded to linear, float files (EXR) are already linear scene values;
// fromScreenshot also undoes the game's grading (neutral LUT). Same call the CLI makes
// (lut::prepareSceneFrame).
Image prepareScene(const Image& stored, bool storedIsLinear, bool fromScreenshot = false,
                   int nthreads = 0);

// Whether the preview with these options has a brighten step the user can switch: only the
// smash preset has one. Brighten off grades with lut::smashWithoutBrighten(lut), which shows the
// LUT with no brighten step, exactly for trilinear and tetrahedral interpolation and within
// lut::smashWithoutBrightenError (< 2e-5) for nearest (lut/pipeline/SmashCompensation.h).
bool brightenSwitchable(const PreviewOptions& options);
// Whether the preview applies the brighten step: the smash preset with brighten on.
bool brightenApplied(const PreviewOptions& options);

// What a preview settings choice means for the pipeline.
PipelineSettings pipelineSettings(const PreviewOptions& options, std::shared_ptr<const Lut3D> lut);

struct PreviewResult {
    Image image;               // display-encoded RGBA float, what `lutkit preview` writes
    double milliseconds = 0.0; // wall time of the pipeline run
    std::string report;        // PipelineReport::str()
};

// Runs the pipeline on a copy of `scene` (the prepared linear frame).
PreviewResult renderPreview(const Image& scene, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads = 0);

// The same preview in the pipeline's two parts (lut::PipelinePart), so a LUT edit re-runs only
// what the LUT affects:
//   renderBeforeLut  the stages before the first LUT stage (sanitize, bloom, vignette...: what
//                    depends only on the image and the preset), run once and cached;
//   renderFromLut    the LUT stage and everything after it (grading, brighten, display).
// renderFromLut(renderBeforeLut(x)) == renderPreview(x) bit for bit (tested).
Image renderBeforeLut(const Image& scene, const PreviewOptions& options, int nthreads = 0);
PreviewResult renderFromLut(const Image& beforeLut, const PreviewOptions& options,
                            std::shared_ptr<const Lut3D> lut, int nthreads = 0);
// Whether a before-LUT frame made with options `a` is valid for options `b`
// (lut::Pipeline::sameBeforeLut of the two pipelines).
bool sameBeforeLut(const PreviewOptions& a, const PreviewOptions& b);

// The "before" picture: `scene` with nothing but the display encoding (the `none` preset).
Image renderBefore(const Image& scene, int nthreads = 0);

} // namespace lut::gui
