#pragma once
// What the scopes dock draws, computed from a preview frame's 8-bit picture on the preview worker
// (PreviewFrame), so they follow every frame without work on the UI thread:
//   histogram  counts of each 8-bit level per channel R, G, B and Rec.709 luma (integer
//              weights 54, 183, 19 of 256);
//   parade     R, G and B side by side, each `columns` wide and 256 high: for each column of the
//              picture (resampled to `columns`) how many pixels have each level, as brightness;
//   clipping   pixels with a channel at 255 (clipped high) or at 0 (clipped low), and an overlay
//              that marks them (red high, blue low, transparent elsewhere).
#include <QImage>

#include <array>
#include <cstdint>

namespace lut::gui {

struct Scopes {
    std::array<std::array<std::uint32_t, 256>, 4> histogram{}; // R, G, B, luma
    QImage parade;                                             // Format_RGB32
    std::uint64_t pixels = 0;
    std::uint64_t clippedHigh = 0; // pixels with any channel at 255
    std::uint64_t clippedLow = 0;  // pixels with any channel at 0
};

// `display` is an 8-bit picture in Format_RGBX8888 (PreviewFrame::display).
Scopes computeScopes(const QImage& display, int columns = 256);
// Same size as `display`, Format_ARGB32_Premultiplied.
QImage clipOverlay(const QImage& display);

} // namespace lut::gui
