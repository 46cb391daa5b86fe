// SPDX-License-Identifier: Apache-2.0
#include "lut/io/Layout.h"

#include "lut/Error.h"
#include "lut/Math.h"

#include <cmath>

namespace lut {

const char* toString(LutLayout l) {
    switch (l) {
    case LutLayout::Pilot:
        return "unreal";
    case LutLayout::Unity:
        return "unity";
    case LutLayout::Smush:
        return "smush";
    case LutLayout::Hald:
        return "hald";
    case LutLayout::Reshade:
        return "reshade";
    case LutLayout::Unity32:
        return "unity-32";
    }
    return "?";
}

std::vector<std::string> layoutAliases(LutLayout l) {
    switch (l) {
    case LutLayout::Pilot:
        return {"pilot", "godot"};
    case LutLayout::Smush:
        return {"lattice"};
    case LutLayout::Reshade:
        return {"unreal-32"};
    case LutLayout::Unity:
    case LutLayout::Hald:
    case LutLayout::Unity32:
        break;
    }
    return {};
}

LutLayout parseLayout(std::string_view name) {
    std::string names, aliases;
    for (const LutLayout l : allLayouts()) {
        if (name == toString(l))
            return l;
        for (const std::string& alias : layoutAliases(l)) {
            if (name == alias)
                return l;
            aliases += (aliases.empty() ? "" : ", ") + alias;
        }
        names += (names.empty() ? "" : ", ") + std::string(toString(l));
    }
    throw Error("unknown layout '" + std::string(name) + "' (expected " + names + "; also " +
                aliases + ")");
}

std::optional<LutLayout> parseOptionalLayout(std::string_view name) {
    if (name.empty())
        return std::nullopt;
    return parseLayout(name);
}

std::vector<LutLayout> allLayouts() {
    return {LutLayout::Pilot, LutLayout::Unity,   LutLayout::Smush,
            LutLayout::Hald,  LutLayout::Reshade, LutLayout::Unity32};
}

int layoutFixedSize(LutLayout l) {
    return l == LutLayout::Reshade || l == LutLayout::Unity32 ? 32 : 0;
}

LutLayout layoutPlacement(LutLayout l) {
    return l == LutLayout::Reshade   ? LutLayout::Pilot
           : l == LutLayout::Unity32 ? LutLayout::Unity
                                     : l;
}

static int haldLevel(int size) {
    const int level = static_cast<int>(std::lround(std::sqrt(static_cast<double>(size))));
    return level * level == size ? level : 0;
}

void layoutImageSize(LutLayout layout, int size, int& width, int& height) {
    if (layout == LutLayout::Hald) {
        const int level = haldLevel(size);
        if (level < 2)
            throw Error("a Hald image needs a LUT size that is a square of a level >= 2 (4, 9, 16, "
                        "25, 36, 49, 64, ...), not " +
                        std::to_string(size));
        width = height = level * level * level;
        return;
    }
    width = size * size;
    height = size;
}

std::vector<LayoutFit> layoutsForImageSize(int width, int height) {
    std::vector<LayoutFit> fits;
    if (height >= 2 && height <= 256 && static_cast<long long>(height) * height == width) {
        const bool named = height == layoutFixedSize(LutLayout::Reshade);
        fits.push_back({named ? LutLayout::Reshade : LutLayout::Pilot, height});
        fits.push_back({named ? LutLayout::Unity32 : LutLayout::Unity, height});
        fits.push_back({LutLayout::Smush, height});
    }
    if (width == height && width >= 8) {
        const int level =
            static_cast<int>(std::lround(lut::math::cbrt(static_cast<double>(width))));
        if (level >= 2 && level * level * level == width && level * level <= 256)
            fits.push_back({LutLayout::Hald, level * level});
    }
    return fits;
}

std::string layoutSizeProblem(LutLayout layout, int size) {
    const int fixed = layoutFixedSize(layout);
    if (size == 0 || fixed == 0 || size == fixed)
        return {};
    return "the " + std::string(toString(layout)) + " layout is " + std::to_string(fixed * fixed) +
           "x" + std::to_string(fixed) + " (" + std::to_string(fixed) + "^3), not " +
           std::to_string(size) + "^3 (" + toString(layoutPlacement(layout)) +
           " is the same placement at any N)";
}

int layoutSizeForImage(LutLayout layout, int width, int height) {
    if (layout == LutLayout::Hald) {
        for (const LayoutFit& f : layoutsForImageSize(width, height))
            if (f.layout == LutLayout::Hald)
                return f.size;
        return 0;
    }
    const bool strip =
        height >= 2 && height <= 256 && static_cast<long long>(height) * height == width;
    if (!strip)
        return 0;
    const int fixed = layoutFixedSize(layout);
    return fixed == 0 || fixed == height ? height : 0;
}

void layoutPixel(LutLayout layout, int n, int r, int g, int b, int& x, int& y) {
    switch (layoutPlacement(layout)) {
    case LutLayout::Pilot:
        x = r + n * b;
        y = g;
        return;
    case LutLayout::Unity:
        x = r + n * b;
        y = n - 1 - g;
        return;
    case LutLayout::Smush:
        x = r + n * g;
        y = b;
        return;
    case LutLayout::Hald: {
        const int level = haldLevel(n);
        const long long side = static_cast<long long>(level) * level * level;
        const long long i = r + static_cast<long long>(n) * (g + static_cast<long long>(n) * b);
        x = static_cast<int>(i % side);
        y = static_cast<int>(i / side);
        return;
    }
    case LutLayout::Reshade: // placed as their base layouts (layoutPlacement)
    case LutLayout::Unity32:
        return;
    }
}

static void checkPatch(const ImageView& image, LutLayout layout, int size, int x0, int y0,
                       int block) {
    int w = 0, h = 0;
    layoutImageSize(layout, size, w, h);
    if (block < 1 || x0 < 0 || y0 < 0 ||
        static_cast<long long>(x0) + static_cast<long long>(w) * block > image.width ||
        static_cast<long long>(y0) + static_cast<long long>(h) * block > image.height)
        throw Error("a " + std::to_string(size) + "^3 LUT in the " + toString(layout) +
                    " layout needs " + std::to_string(static_cast<long long>(w) * block) + "x" +
                    std::to_string(static_cast<long long>(h) * block) + " pixels at (" +
                    std::to_string(x0) + ", " + std::to_string(y0) + "), the image is " +
                    std::to_string(image.width) + "x" + std::to_string(image.height));
}

Lut3D lutFromImage(const ImageView& image, LutLayout layout, int size, int x0, int y0, int block) {
    Lut3D lut(size);
    checkPatch(image, layout, size, x0, y0, block);
    const double inv = 1.0 / (static_cast<double>(block) * block);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r) {
                int x = 0, y = 0;
                layoutPixel(layout, size, r, g, b, x, y);
                double acc[3] = {0, 0, 0};
                for (int dy = 0; dy < block; ++dy)
                    for (int dx = 0; dx < block; ++dx) {
                        const float* p = image.pixel(x0 + x * block + dx, y0 + y * block + dy);
                        for (int c = 0; c < 3; ++c)
                            acc[c] += p[c];
                    }
                lut.at(r, g, b) =
                    glm::vec3(static_cast<float>(acc[0] * inv), static_cast<float>(acc[1] * inv),
                              static_cast<float>(acc[2] * inv));
            }
    return lut;
}

void drawLut(const Lut3D& lut, LutLayout layout, const ImageView& image, int x0, int y0,
             int block) {
    const int size = lut.size();
    checkPatch(image, layout, size, x0, y0, block);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r) {
                int x = 0, y = 0;
                layoutPixel(layout, size, r, g, b, x, y);
                const glm::vec3 v = lut.at(r, g, b);
                for (int dy = 0; dy < block; ++dy)
                    for (int dx = 0; dx < block; ++dx) {
                        float* p = image.pixel(x0 + x * block + dx, y0 + y * block + dy);
                        p[0] = v.x;
                        p[1] = v.y;
                        p[2] = v.z;
                        p[3] = 1.0f;
                    }
            }
}

Image lutToImage(const Lut3D& lut, LutLayout layout, int block) {
    int w = 0, h = 0;
    layoutImageSize(layout, lut.size(), w, h);
    Image img(w * block, h * block);
    drawLut(lut, layout, img.view(), 0, 0, block);
    return img;
}

} // namespace lut
