// SPDX-License-Identifier: Apache-2.0
// PixelProcessor and ProcessorChain (lut/PixelProcessor.h).
#include "lut/PixelProcessor.h"

#include "lut/Parallel.h"

#include <algorithm>

namespace lut {

PixelProcessor::~PixelProcessor() = default;

void ProcessorChain::append(std::shared_ptr<const PixelProcessor> step) {
    if (step)
        m_steps.push_back(std::move(step));
}

void ProcessorChain::processPixels(float* rgba, std::size_t count) const {
    for (const auto& s : m_steps)
        s->processPixels(rgba, count);
}

void ProcessorChain::apply(const ImageView& image, int nthreads) const {
    if (image.empty() || m_steps.empty())
        return;
    const std::size_t w = static_cast<std::size_t>(image.width);
    const int band =
        std::max(1, std::min(256, static_cast<int>((1u << 16) / std::max<std::size_t>(w, 1))));
    const int bands = (image.height + band - 1) / band;
    const bool packed = image.strideFloats == static_cast<std::ptrdiff_t>(4 * w);
    parallelForDynamic(bands, nthreads, 1, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b) {
            const int y0 = b * band, y1 = std::min(image.height, y0 + band);
            if (packed)
                processPixels(image.row(y0), w * static_cast<std::size_t>(y1 - y0));
            else
                for (int y = y0; y < y1; ++y)
                    processPixels(image.row(y), w);
        }
    });
}

} // namespace lut
