// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a preview plan undoes before its chain (lut/pipeline/PreviewPlan.h): the sRGB decode of
// the stored values, the game's grading undone with the stage LUT, or the none preset's display
// encode, as the plan says; set up once, then run on any run of pixels from any thread. Every
// step is per pixel, so preparePreviewFrame (the frame's rows) and a preview streamed from a file
// (the runs the file is read in) give the same values bit for bit.
#include "lut/Error.h"
#include "lut/Lut3D.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/smash/SmashUngrader.h"

#include <atomic>
#include <cstddef>
#include <optional>

namespace lut {

struct PreviewPlan;

class PreviewPreparation {
public:
    // stageLut: the LUT a screenshot was taken with (null: neutral; copied). stored8Bit: the
    // values are exactly k / 255 (an 8-bit file): the decode then goes by table, bit-identical
    // to the per-value function.
    PreviewPreparation(const PreviewPlan& plan, const Lut3D* stageLut, bool stored8Bit);
    ~PreviewPreparation();

    // Whether it changes anything (a linear scene for the game's chain: nothing to undo).
    bool active() const { return m_decode || m_ungrader || m_display; }
    // count RGBA pixels in place. Const and thread-safe (concurrent calls on disjoint runs).
    void apply(float* rgba, std::size_t count) const;
    // The notes of what was done so far (the undo's: bloom cannot be undone unless the plan left
    // the bloom to the screenshot; pixels whose colour the stage LUT cannot make).
    Diagnostics notes() const;

private:
    // The 8-bit code k a value is exactly (k / 255 as a file's code reads), else -1.
    int code(float v) const {
        const int k = static_cast<int>(v * 255.0f + 0.5f);
        return k >= 0 && k < 256 && m_codes[k] == v ? k : -1;
    }

    bool m_decode = false;
    bool m_table = false;
    float m_codes[256] = {}; // k / 255 as a file's 8-bit code k reads
    float m_linear[256] = {};
    float m_undone[256] = {}; // m_linear undone by a neutral stage LUT (alpha >= 1)
    bool m_undoneTable = false;
    std::optional<SmashUngrader> m_ungrader;
    bool m_quietBloom = false;
    std::optional<Pipeline> m_display; // the none preset (displayEncode)
    mutable std::atomic<std::size_t> m_unconverged{0};
};

} // namespace lut
