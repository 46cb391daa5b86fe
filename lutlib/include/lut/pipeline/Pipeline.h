// SPDX-License-Identifier: Apache-2.0
#pragma once
// The preview pipeline: an ordered list of stages (lut/pipeline/Stage.h) run on a linear float
// RGBA frame, used by `lutkit preview` and by the editor, so both show the same pixels.
//
// Stages, in their one canonical order (a preset enables some of them; any can be switched on or
// off and tuned: setParam("smash-bloom.strength", "0.5")):
// clang-format off
//   sanitize              NaN -> 0, +-Inf and |x| > 65504 -> +-65504 (always first; keeps one bad
//                         pixel from spreading through the blurs)
//   exposure              x * 2^stops
//   tonemap               reinhard | aces (Narkowicz fit) | hable (Uncharted 2 filmic)
//   hdr-bloom             cinematic: max(x - 1, 0), Gaussian, add
//   soft-bloom            filmic (old name filter-bloom): luminance soft-knee filter, separable
//                         9-tap Gaussian, add
//   glow-bloom            (old name sugar-bloom): i = max(rgb) - th, dilate(C * i), mip-pyramid
//                         blur, C*f0 + B*(1-i)*f1
//   smash-bloom           Smash Ultimate bloom, exactly (docs/specs/smash-pipeline.md section 1)
//   chromatic-aberration  r and b sampled at slightly different radial distances
//   vignette              darken by distance to the centre
//   grain                 seeded film grain (same seed + frame index -> same frame)
//   smash-grade           Smash grading LUT + brighten + alpha mix (section 2)
//   lut                   any 3D LUT with any interpolation
//   display               sRGB (piecewise) or pure gamma encode, last
// clang-format on
// Presets: smash (sanitize, smash-bloom, smash-grade, display=srgb), filmic (old name pilot:
// tonemap, soft-bloom, lut, display=gamma 2.2), cinematic (old name lecture: exposure, hdr-bloom,
// chromatic-aberration, vignette, grain, lut, display=gamma 2.2), none (sanitize, display).
//
// Not implemented: depth of field, SSAO and SSR need per-pixel depth and normals, which an image
// does not have (see docs/pipeline.md).
#include "lut/Error.h"
#include "lut/Image.h"
#include "lut/Lut1D.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/Stage.h"

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lut {

// Users see and type: smash, filmic (Pilot), cinematic (Lecture), none.
enum class Preset { Smash, Pilot, Lecture, None };
const char* toString(Preset);
std::vector<std::string> presetAliases(Preset); // older names parsePreset accepts ("pilot")
const char* describe(Preset);                   // what the preset looks like, one line
const std::vector<Preset>& allPresets();
Preset parsePreset(std::string_view name); // names and aliases; throws lut::Error

// Every stage name, in pipeline order.
const std::vector<std::string>& stageNames();
// Older stage names still accepted wherever a stage is named: {old name, stage name}.
const std::vector<std::pair<std::string, std::string>>& stageAliases();
// The stage an old name stands for ("sugar-bloom" -> "glow-bloom"); other names unchanged.
std::string_view canonicalStageName(std::string_view name);
// A stage by name with default settings (disabled ones too); throws lut::Error if unknown.
std::unique_ptr<Stage> makeStage(std::string_view name);

// The settings of a pipeline as plain copyable data (what the editor's document keeps).
struct PipelineSettings {
    Preset preset = Preset::Smash;
    std::shared_ptr<const Lut3D> lut; // grading LUT (smash-grade and lut); null = neutral
    // A 1D shaper run before lut's table, exactly (a Resolve .cube's; lut null: the shaper
    // alone); null = none.
    std::shared_ptr<const Lut1D> shaper;
    Interpolation interpolation = Interpolation::Trilinear;
    bool bloom = true;                // false disables every bloom stage
    std::vector<std::string> enable;  // stage names to switch on
    std::vector<std::string> disable; // stage names to switch off
    // "stage.param=value" assignments applied in order; stage "bloom" means the preset's bloom.
    std::vector<std::string> assignments;
};

// A pipeline in two parts around its LUT, so a LUT edit re-runs only what the LUT affects:
//   BeforeLut  the stages before the first LUT stage (smash-grade or lut): sanitize, bloom,
//              vignette... what depends only on the frame and the settings of those stages;
//   FromLut    the first LUT stage and every stage after it (grading, display).
// Running BeforeLut, then FromLut on its output, is bit-identical to running Whole: the parts
// are the same stages run one after the other (lut/pipeline/Stage.h), and the one fusion that
// is not bit-identical (sRGB display into smash-grade) happens inside FromLut as in Whole.
enum class PipelinePart { Whole, BeforeLut, FromLut };

struct RunOptions {
    int nthreads = 0;                  // 0 = all cores
    bool forceAll = false;             // run enabled stages even when they say they cannot change
    unsigned long long frameIndex = 0; // for film grain
    PipelinePart part = PipelinePart::Whole;
};

struct StageReport {
    std::string name;
    bool ran = false;
    bool enabled = true;       // switched on and in the part that ran (RunOptions::part)
    bool fused = false;        // ran inside the previous stage's loop (display after smash-grade)
    double milliseconds = 0.0; // wall time of prepare + this stage's share of the fused passes
};
struct PipelineReport {
    std::vector<StageReport> stages; // every stage of the pipeline, enabled or not, in order
    double totalMilliseconds = 0.0;
    std::string str() const; // a readable table for --verbose
};

class Pipeline {
public:
    Pipeline();
    explicit Pipeline(Preset preset);
    // Builds the preset, then applies settings; throws lut::Error for an unknown stage/parameter.
    explicit Pipeline(const PipelineSettings& settings);
    ~Pipeline();
    Pipeline(Pipeline&&) noexcept;
    Pipeline& operator=(Pipeline&&) noexcept;

    Preset preset() const { return m_preset; }
    const std::vector<std::unique_ptr<Stage>>& stages() const { return m_stages; }
    Stage* find(std::string_view name); // null if absent; "bloom" = the preset's bloom
    const Stage* find(std::string_view name) const;
    Stage& stage(std::string_view name); // throws lut::Error if absent

    void setEnabled(std::string_view stageName, bool on);
    // "stage.param=value"; throws lut::Error naming what is wrong.
    void assign(std::string_view assignment);
    // The grading LUT for smash-grade and lut (copied; sampled with `method`). Null = neutral.
    // With a shaper: the shaper, then lut's table, each exactly (lut null: the shaper alone).
    void setLut(std::shared_ptr<const Lut3D> lut, Interpolation method = Interpolation::Trilinear,
                std::shared_ptr<const Lut1D> shaper = nullptr);
    void setBloom(bool on); // every *bloom stage

    // Index in stages() of the first LUT stage (smash-grade, lut), where PipelinePart::FromLut
    // starts; stages().size() if there is none.
    std::size_t firstLutStage() const;
    // Whether this pipeline's BeforeLut part makes the same frame as `other`'s from the same
    // input: the same stages, switched on or off alike, with the same parameter values. A frame
    // cached from one can then stand in for the other's BeforeLut run.
    bool sameBeforeLut(const Pipeline& other) const;

    // Runs the enabled stages in place on `frame`.
    PipelineReport run(const ImageView& frame, const RunOptions& options = {});
    // The result-returning form.
    Image run(const Image& frame, const RunOptions& options = {}, PipelineReport* report = nullptr);

    // Whether every enabled stage is pointwise (Stage::pointwise: no bloom, chromatic
    // aberration, vignette or grain): the pipeline can then run on runs of pixels streamed from a
    // file (runPixels), never holding a frame.
    bool isPointwise() const;
    // A pointwise pipeline on count RGBA pixels in place (the part options.part names; nthreads
    // and forceAll are not used): run()'s result for those pixels, bit for bit, as every enabled
    // stage runs (skipping never changes a pixel) and the display encode is fused into
    // smash-grade as run() fuses it. Const and thread-safe: concurrent calls on disjoint runs.
    // Throws lut::Error when the pipeline is not pointwise.
    void runPixels(float* rgba, std::size_t count, const RunOptions& options = {}) const;

private:
    Preset m_preset = Preset::None;
    std::vector<std::unique_ptr<Stage>> m_stages;
};

} // namespace lut
