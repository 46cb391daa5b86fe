// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstddef>
#include <vector>

namespace lut {

// A non-owning view of a float RGBA image, rows top to bottom, 4 interleaved channels.
// strideFloats is the distance between row starts in floats (>= 4 * width).
struct ImageView {
    float* data = nullptr;
    int width = 0;
    int height = 0;
    std::ptrdiff_t strideFloats = 0;

    float* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * strideFloats; }
    float* pixel(int x, int y) const { return row(y) + 4 * static_cast<std::ptrdiff_t>(x); }
    bool empty() const { return data == nullptr || width <= 0 || height <= 0; }
};

// An owning float RGBA image (tightly packed).
class Image {
public:
    Image() = default;
    Image(int width, int height, float fill = 0.0f);

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool empty() const { return m_pixels.empty(); }
    ImageView view();
    ImageView view() const; // the view is mutable; constness is the caller's promise
    float* data() { return m_pixels.data(); }
    const float* data() const { return m_pixels.data(); }
    float* pixel(int x, int y) {
        return m_pixels.data() + 4 * (static_cast<std::size_t>(y) * m_width + x);
    }
    const float* pixel(int x, int y) const {
        return m_pixels.data() + 4 * (static_cast<std::size_t>(y) * m_width + x);
    }
    std::vector<float>& pixels() { return m_pixels; }
    const std::vector<float>& pixels() const { return m_pixels; }

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<float> m_pixels;
};

} // namespace lut
