// SPDX-License-Identifier: Apache-2.0
#pragma once
// One step of the preview pipeline (lut::Pipeline). Every stage works in place on a float RGBA
// linear frame (lut::ImageView) and never changes alpha (the sanitize stage, which runs first,
// is the one exception: it maps NaN alpha to 0).
//
// A stage runs in two parts so the pipeline can fuse consecutive stages into one pass over the
// frame, tile by tile (the frame is streamed through the cache once, not once per stage):
//   prepare(frame)            may read the whole frame (bloom builds its blurred image here); a
//                             stage with needsPrepare() starts a new pass;
//   processRows(frame, y0,y1) writes rows [y0, y1), reading only those rows of the frame and
//                             what prepare() built. Called concurrently for disjoint row ranges.
// Running the stages one after the other on the whole frame gives bit-identical results, with
// one exception: when sRGB display directly follows smash-grade, the pipeline fuses the encode
// into the grading loop through one table (within 2e-7 of the two-step result).
//
// Rule for canChange(): a stage that does not inspectsColor() is asked before earlier stages of
// the same pass have run, so its answer may depend only on its settings and on alpha (which no
// stage but sanitize changes, and sanitize always completes its own pass first).
//
// Skipping: canChange(frame) says whether running the stage can change any pixel of this frame
// with these settings (zero strength, nothing above the bloom threshold, identity LUT, all alpha
// 0 ...). The pipeline skips the stage when it says no, and process*() honours the same settings
// checks, so skipping never changes the output (tested bit-for-bit).
#include "lut/Image.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

// A tunable setting of a stage: a number in [min, max], or one of `choices` (stored as its index).
struct StageParam {
    std::string name;
    std::string help;
    float value = 0.0f;
    float defaultValue = 0.0f;
    float min = 0.0f;
    float max = 0.0f;
    std::vector<std::string> choices; // non-empty: an enumeration ("reinhard", "aces", ...)
    std::string valueString() const;  // the choice name, or the number
};

struct StageContext {
    int nthreads = 0;                  // 0 = all cores
    unsigned long long frameIndex = 0; // film grain changes per frame, reproducibly
    // The pipeline fused the sRGB display encode into smash-grade's loop (Pipeline::run decides;
    // only smash-grade reads it).
    bool fusedDisplay = false;
};

class Stage {
public:
    virtual ~Stage();
    Stage(const Stage&) = delete;
    Stage& operator=(const Stage&) = delete;

    virtual const char* name() const = 0;        // unique in a pipeline: "smash-bloom", "vignette"
    virtual const char* description() const = 0; // one line for --help / --list-stages

    // Whether running the stage can change any pixel of `frame` with the current settings.
    // Stages whose answer depends on colour (not only alpha or settings) say so with
    // inspectsColor(), so the pipeline asks them on the frame as it is when they run.
    virtual bool canChange(const ImageView& frame, int nthreads) const = 0;
    virtual bool inspectsColor() const { return false; }
    // Whether each pixel's result depends only on that pixel and the settings (not on its
    // position, its neighbours or the rest of the frame), with no prepare(): processRows then
    // gives the same result on any run of pixels (a 1-row view), as Pipeline::runPixels uses it.
    virtual bool pointwise() const { return false; }

    virtual bool needsPrepare() const { return false; }
    virtual void prepare(const ImageView& frame, const StageContext& ctx) {}
    virtual void processRows(const ImageView& frame, int y0, int y1,
                             const StageContext& ctx) const = 0;
    // Releases what prepare() built.
    virtual void finish() {}

    // The whole stage on the whole frame: prepare, then all rows on ctx.nthreads threads.
    void process(const ImageView& frame, const StageContext& ctx = {});

    // Settings.
    bool enabled() const { return m_enabled; }
    void setEnabled(bool on) { m_enabled = on; }
    const std::vector<StageParam>& params() const { return m_params; }
    float param(std::string_view name) const; // throws lut::Error for an unknown name
    // Sets a number ("0.5") or a choice ("aces"); throws lut::Error naming the stage and the
    // parameter for an unknown name, a value that is not a number / choice, or out of range.
    void setParam(std::string_view name, std::string_view value);
    void setParam(std::string_view name, float value);
    // Copies enabled state, parameter values and any LUT from another stage of the same kind.
    virtual void copySettingsFrom(const Stage& other);

protected:
    Stage() = default;
    // Registers a parameter bound to a member; the member is kept in sync by setParam.
    void addParam(float* target, std::string name, float defaultValue, float min, float max,
                  std::string help);
    void addChoice(float* target, std::string name, std::vector<std::string> choices,
                   int defaultIndex, std::string help);

private:
    bool m_enabled = true;
    std::vector<StageParam> m_params;
    std::vector<float*> m_targets;
};

} // namespace lut
