// SPDX-License-Identifier: Apache-2.0
#include "lut/Image.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/os/Memory.h"

#include <cstdint>

namespace lut {

Image::Image(int width, int height, float fill) {
    if (width < 0 || height < 0 ||
        static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) >
            limits::kMaxImagePixels)
        throw LimitError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the limit of " + std::to_string(limits::kMaxImagePixels) +
                         " pixels");
    m_width = width;
    m_height = height;
    const std::size_t n = static_cast<std::size_t>(width) * height * 4;
    m_pixels.reserve(n); // allocated, not yet touched: the advice comes before the first write
    // Huge pages (a 1080p preview: 0.20 -> 0.18 s wall in paired runs, bench/RESULTS.md).
    os::adviseHugePages(m_pixels.data(), n * sizeof(float));
    m_pixels.assign(n, fill);
}

ImageView Image::view() {
    return ImageView{m_pixels.data(), m_width, m_height, static_cast<std::ptrdiff_t>(m_width) * 4};
}

ImageView Image::view() const {
    return ImageView{const_cast<float*>(m_pixels.data()), m_width, m_height,
                     static_cast<std::ptrdiff_t>(m_width) * 4};
}

} // namespace lut
