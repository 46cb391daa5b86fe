// SPDX-License-Identifier: Apache-2.0
#pragma once
// The game's grading undone pixel by pixel ("deprocess", smashGradeInverse), set up once for a
// stage LUT and used on any number of frames or runs of pixels: smashUngrade runs it over a
// frame, a streamed preview (lutkit preview of a screenshot without bloom) over the runs of
// pixels the file is read in. Each pixel's result depends on that pixel alone, so both give the
// same values bit for bit.
#include "lut/Error.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

#include <cstddef>
#include <memory>

namespace lut {

class Sampler;

class SmashUngrader {
public:
    // stageLut: the LUT the picture was graded with (null: the neutral 16^3 LUT), copied.
    explicit SmashUngrader(const Lut3D* stageLut, Interpolation interp = Interpolation::Trilinear);
    ~SmashUngrader();
    SmashUngrader(SmashUngrader&&) noexcept;
    SmashUngrader& operator=(SmashUngrader&&) noexcept;

    // Rewrites the linear RGB of count RGBA pixels (display encoding already undone) to the
    // pre-grading scene, alpha kept; returns how many pixels have a colour the LUT cannot make
    // (the closest kept). Const and thread-safe: concurrent calls on disjoint runs.
    std::size_t apply(float* rgba, std::size_t count) const;

    // Whether the stage LUT is the neutral one: a pixel with alpha >= 1 is then undone channel
    // by channel, each by neutralChannel (apply gives exactly that), so callers may table it.
    bool neutral() const { return m_identity; }
    static float neutralChannel(float linear);

private:
    std::unique_ptr<const Sampler> m_sampler;
    bool m_identity = true; // the neutral LUT: a closed form per channel, memoised per thread
};

// What to say after ungrading: that bloom cannot be undone, and how many pixels kept the closest
// colour (when any).
Diagnostics ungradeNotes(std::size_t unconverged);

} // namespace lut
