// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUT image layouts: where entry (r, g, b) of an N^3 LUT sits in a 2D picture. See
// docs/specs/strip-layouts.md. Pixel (x, y) has y = 0 at the top row.
#include "lut/Image.h"
#include "lut/Lut3D.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

// Users see and type the names in quotes (toString); the older names stay accepted (aliases).
enum class LutLayout {
    Pilot, // "unreal": N^2 x N, x = r + N*b, y = g (Unreal Engine's 256x16; aliases pilot, godot)
    Unity, // "unity":  N^2 x N, x = r + N*b, y = N-1-g
    Smush, // "smush":  N^2 x N, x = r + N*g, y = b (Smush-LUT, ociolutimage; alias lattice)
    Hald,  // "hald":   L^3 x L^3 with N = L^2: i = r + N*g + N^2*b, x = i mod L^3, y = i div L^3
    // The 1024x32 strips, 32^3 only (named sizes: a picture of another size is not one of them):
    Reshade, // "reshade": as unreal, N = 32 (ReShade's LUT.fx and MultiLUT rows; Unreal's 1024x32,
             // alias unreal-32)
    Unity32, // "unity-32": as unity, N = 32 (Unity's NeutralLdrLut.png, 1024x32)
};

const char* toString(LutLayout);
// The other names parseLayout accepts for a layout (e.g. "pilot" and "godot" for unreal).
std::vector<std::string> layoutAliases(LutLayout);
// Accepts the names and aliases above; throws lut::Error listing the valid names.
LutLayout parseLayout(std::string_view name);
// The same, with "" meaning "not given" (nullopt): for options whose default is auto-detection.
std::optional<LutLayout> parseOptionalLayout(std::string_view name);
std::vector<LutLayout> allLayouts();

// The one lattice size a layout is made for: 32 for reshade and unity-32, 0 for the others (any N).
int layoutFixedSize(LutLayout);
// The layout whose pixel placement `layout` uses: unreal for reshade, unity for unity-32, else
// itself.
LutLayout layoutPlacement(LutLayout);
// "" when an N^3 LUT can be written in `layout` (size 0 = not given: always), else why not, e.g.
// "the reshade layout is 1024x32 (32^3), not 16^3 (unreal is the same placement at any N)".
std::string layoutSizeProblem(LutLayout layout, int size);
// The N an image of width x height holds in `layout`, 0 when that layout does not fit the size.
int layoutSizeForImage(LutLayout layout, int width, int height);

struct LayoutFit {
    LutLayout layout;
    int size; // N
};
// Every layout whose picture size is exactly width x height, with the N it implies, each pixel
// placement once: a 1024x32 picture fits reshade, unity-32 and smush (unreal and unity are the
// same pixels as the first two), other N^2 x N pictures unreal, unity and smush.
std::vector<LayoutFit> layoutsForImageSize(int width, int height);
// Picture size of an N^3 LUT in a layout (Hald needs N = L^2; throws lut::Error otherwise).
void layoutImageSize(LutLayout layout, int size, int& width, int& height);
// Pixel of entry (r, g, b).
void layoutPixel(LutLayout layout, int size, int r, int g, int b, int& x, int& y);

// Reads an N^3 LUT from the patch of `image` whose top-left pixel is (x0, y0), each entry
// averaged over a block x block square (block >= 1). Throws lut::Error if it does not fit.
Lut3D lutFromImage(const ImageView& image, LutLayout layout, int size, int x0 = 0, int y0 = 0,
                   int block = 1);
// Draws lut into image at (x0, y0) (each entry a block x block square; alpha set to 1).
void drawLut(const Lut3D& lut, LutLayout layout, const ImageView& image, int x0 = 0, int y0 = 0,
             int block = 1);
// A new image holding just the LUT in a layout.
Image lutToImage(const Lut3D& lut, LutLayout layout, int block = 1);

} // namespace lut
