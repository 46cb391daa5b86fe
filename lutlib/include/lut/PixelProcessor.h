// SPDX-License-Identifier: Apache-2.0
#pragma once
// Something that rewrites RGBA float pixels in place (an OpenColorIO conversion,
// lut::formats::ColorTransform), and a chain of them run over a whole image in bands of rows on
// all cores: how `lutkit preview` converts its frames with --from and --to.
//
// `lutkit apply` streams its frames instead; its per-chunk chain (conversion, LUT, conversion,
// with the values outside the LUT's domain counted) is lut::PixelChain (lut/interp/PixelChain.h),
// whose steps can wrap a PixelProcessor.
#include "lut/Image.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace lut {

class PixelProcessor {
public:
    virtual ~PixelProcessor();
    // Rewrites the RGB (and possibly alpha) of `count` RGBA pixels in place. Called from several
    // threads at once on disjoint pixels: must not change shared state without synchronising.
    virtual void processPixels(float* rgba, std::size_t count) const = 0;
};

class ProcessorChain {
public:
    void append(std::shared_ptr<const PixelProcessor> step); // null: nothing to do, skipped
    bool empty() const { return m_steps.empty(); }
    std::size_t size() const { return m_steps.size(); }

    // Every step, in order, on one buffer.
    void processPixels(float* rgba, std::size_t count) const;
    // Every step on the image, in bands of rows (about 64 Ki pixels each) taken by up to
    // nthreads workers (0 = all cores); each band goes through all steps before the next.
    void apply(const ImageView& image, int nthreads = 0) const;

private:
    std::vector<std::shared_ptr<const PixelProcessor>> m_steps;
};

} // namespace lut
