// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the scopes dock draws, computed from a preview frame's 8-bit picture on the preview worker
// (PreviewFrame), so they follow every frame without work on the UI thread:
//   histogram   counts of each 8-bit level per channel R, G, B and Rec.709 luma (integer
//               weights 54, 183, 19 of 256);
//   parade      R, G and B side by side, each `columns` wide and 256 high: for each column of the
//               picture (resampled to `columns`) how many pixels have each level, as brightness;
//   waveform    the luma waveform: for each column (as the parade) how many pixels have each
//               luma level Y' = (13933 R + 46871 G + 4732 B + 32768) >> 16 of the 8-bit values
//               (the Rec. 709 weights 0.2126, 0.7152, 0.0722 in 16-bit fixed point, summing to
//               65536, rounded), counts and picture;
//   vectorscope the Rec. 709 colour-difference plane: Cb = (B' - Y') / 1.8556 and
//               Cr = (R' - Y') / 1.5748, both in [-0.5, 0.5], in 16-bit fixed point from the
//               8-bit values: u = -7509 R - 25259 G + 32768 B, v = 32768 R - 29763 G - 3005 B
//               (= 255 * 65536 * Cb, Cr), counted in a kVectorscopeSize square grid: column
//               min(255, (u + 8355840) / 65280), row from the top 255 - min(255, (v + 8355840) /
//               65280) (integer division: floor((Cb + 0.5) * 256)); the picture shows each
//               occupied cell in its own hue. The view draws the graticule: the 75 % primary and
//               secondary targets, and the skin-tone line at kSkinToneDegrees (where faces of
//               every complexion fall);
//   clipping    pixels with a channel at 255 (clipped high) or at 0 (clipped low), and an overlay
//               that marks them (red high, blue low, transparent elsewhere).
#include <QImage>

#include <array>
#include <cstdint>
#include <vector>

namespace lut::gui {

constexpr int kVectorscopeSize = 256;
// The skin-tone (flesh) line: degrees counter-clockwise from the +Cb axis (the I axis of YIQ,
// drawn on every broadcast vectorscope).
constexpr double kSkinToneDegrees = 123.0;

struct Scopes {
    std::array<std::array<std::uint32_t, 256>, 4> histogram{}; // R, G, B, luma
    QImage parade;                                             // Format_RGB32
    int columns = 0;                        // columns of the parade and the waveform
    std::vector<std::uint32_t> waveform;    // [column * 256 + luma level]
    QImage waveformImage;                   // columns x 256, Format_RGB32, level 255 at the top
    std::vector<std::uint32_t> vectorscope; // [row * kVectorscopeSize + column], row 0 = Cr +0.5
    QImage vectorscopeImage;                // kVectorscopeSize square, Format_RGB32
    std::uint64_t pixels = 0;
    std::uint64_t clippedHigh = 0; // pixels with any channel at 255
    std::uint64_t clippedLow = 0;  // pixels with any channel at 0
};

// The luma level and vectorscope cell (row * kVectorscopeSize + column) of an 8-bit colour, as
// defined above; Cb and Cr in floating point, where the view draws a colour.
int waveformLevel(int r, int g, int b);
int vectorscopeCell(int r, int g, int b);
void vectorscopeCbCr(int r, int g, int b, double* cb, double* cr);

// `display` is an 8-bit picture in Format_RGBX8888 (PreviewFrame::display).
Scopes computeScopes(const QImage& display, int columns = 256);
// Same size as `display`, Format_ARGB32_Premultiplied.
QImage clipOverlay(const QImage& display);

} // namespace lut::gui
