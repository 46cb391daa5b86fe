#pragma once
// Something that rewrites RGBA float pixels in place, and a chain of them run over an image in
// chunks: the shape of `lutkit apply` once colour management is involved (an OpenColorIO
// conversion into the space the LUT was made for, the LUT, a conversion out of it), each chunk of
// rows going through every step while it is in cache, chunks shared out over all cores.
//
// lutlib only defines the interface; the OpenColorIO processors live in lut::formats
// (lut/formats/ColourTransform.h), the LUT step is lut::Sampler (samplerProcessor()).
#include "lut/Image.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace lut {

class Sampler;

class PixelProcessor {
public:
    virtual ~PixelProcessor();
    // Rewrites the RGB (and possibly alpha) of `count` RGBA pixels in place. Called from several
    // threads at once on disjoint pixels: must not change shared state without synchronising.
    virtual void processPixels(float* rgba, std::size_t count) const = 0;
};

// The sampler as a pixel step (alpha untouched).
std::shared_ptr<const PixelProcessor> samplerProcessor(std::shared_ptr<const Sampler> sampler);

class PixelChain {
public:
    void append(std::shared_ptr<const PixelProcessor> step);
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
