// SPDX-License-Identifier: Apache-2.0
// LUT images: an N^3 LUT stored as a 2D picture in a named layout (strip-layouts.md).
//
//   unreal (pilot, godot)  N^2 x N   x = r + N*b, y = g          (green 0 on the top row)
//   unity                  N^2 x N   x = r + N*b, y = N-1-g      (green 0 on the bottom row)
//   smush (lattice)        N^2 x N   x = r + N*g, y = b          (Smush-LUT, ociolutimage)
//   hald                   L^3 x L^3 i = r + N*g + N^2*b, x = i mod L^3, y = i div L^3, N = L^2
//   reshade (unreal-32)    1024 x 32 as unreal, N = 32 only (ReShade's LUT.fx, Unreal's 1024x32)
//   unity-32               1024 x 32 as unity, N = 32 only (Unity's NeutralLdrLut.png)
//
// Files go through lutkit's image codecs (OpenImageIO for TIFF): 8/16-bit PNG and TIFF, float EXR
// (also float TIFF), from and to files or bytes in memory alike (readMemory/writeMemory need no
// temporary file). Integer
// samples are read exactly (v/255, v/65535) and written by rounding to nearest with clamping
// (lut::toUnorm8/16), optionally dithered (FormatOptions::dither); a diagnostic says how many
// values were clamped and what the quantisation cost. Default output depth: 8 bits for PNG and
// TIFF, float for EXR; FormatOptions::bitDepth = 8, 16 or 32 overrides. Any N from 2 to 256.
//
// Which layout a file is in (nothing in the file says so):
//  1. FormatOptions::layout when given (an image of the wrong size is refused, naming both).
//  2. The picture size: L^3 x L^3 fits hald only, N^2 x N fits unreal, unity and smush, and
//     1024x32 reshade, unity-32 and smush, the 1024x32 names of the same placements
//     (lut::layoutsForImageSize); other sizes are refused, naming the sizes the layouts need.
//  3. Among several fitting layouts, read the table in each and ask whether it is "close to
//     neutral" in the sense that matters for telling layouts apart: each output channel follows
//     its own input axis. For every layout we take the Pearson correlation of output red with
//     input r, green with g, blue with b over all N^3 entries; the layout passes when all three
//     are >= 0.75. A neutral LUT scores 1, 1, 1 in its own layout; in a wrong layout two axes
//     are swapped (smush vs unreal: green and blue follow the other axis, correlation ~0) or
//     green runs backwards (unity vs unreal: -1). Ordinary grades (contrast, tint, curves) keep
//     each channel increasing with its own input, so they pass in their own layout only. If
//     exactly one layout passes, it is taken; an Info diagnostic says so only when it is not
//     unreal (reshade for 1024x32), the default of an N^2 x N strip (a clean default read
//     changes nothing the user expects, so it needs no note).
//  4. Otherwise (none or several pass), the layout that is "neutral-shaped" in brightness: the
//     table's output luminance, fitted linearly to the input indices, weighs them like the
//     neutral's (0.2126 r + 0.7152 g + 0.0722 b, all of one sign: a gradient map, a
//     black-and-white conversion or an inverting map of the neutral keeps that shape, the other
//     layouts swap green and blue or reverse green). If exactly one layout fits that shape
//     (cosine >= 0.9, every other one < 0.7) it is taken, with an Info diagnostic.
//  5. If that does not decide either (e.g. a strongly cross-channel grade), the image is read
//     as unreal, the default layout of an N^2 x N strip, with a Warning -- but only when unreal
//     scores best or ties (sum of the three correlations, within 0.05); if another layout looks
//     more plausible, the read is refused with the layouts that fit and their scores, asking for
//     the layout (lutkit: --in-layout). Reading never swaps axes silently.
#include "Formats.h"
#include "LutPrep.h"
#include "image/LayoutScore.h"
#include "image/LutImage.h"
#include "imageio/ImageCodec.h"
#include "imageio/ImageHeaderChecks.h"

#include "lut/Error.h"
#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

namespace lut::formats {

namespace {

using S = Diagnostic::Severity;

// Sums of correlations closer than this count as a tie (unreal, the default, wins ties).
constexpr double kScoreTie = 0.05;

// How much the table's luminance weighs the input axes like the neutral's: the cosine between
// the least-squares weights (w_r, w_g, w_b) of luma(out) ~ c + w . (r, g, b) and (0.2126, 0.7152,
// 0.0722), as an absolute value; 0 when the weights are not all of one sign or one of them is
// less than a quarter of the neutral's.
double lumaShape(const Lut3D& lut) {
    const int n = lut.size();
    // normal equations on centred indices: the three axes are uncorrelated over the full lattice
    double sxy[3] = {0, 0, 0}, sxx = 0.0;
    double mean = 0.0;
    const double cm = (n - 1) / 2.0;
    std::size_t count = 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 v = lut.at(r, g, b);
                const double y = 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z;
                if (!std::isfinite(y))
                    continue;
                mean += y;
                ++count;
            }
    if (count == 0)
        return 0.0;
    mean /= static_cast<double>(count);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 v = lut.at(r, g, b);
                const double y = 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z - mean;
                if (!std::isfinite(y))
                    continue;
                const double idx[3] = {r - cm, g - cm, b - cm};
                for (int c = 0; c < 3; ++c)
                    sxy[c] += idx[c] * y;
            }
    for (int i = 0; i < n; ++i)
        sxx += (i - cm) * (i - cm);
    sxx *= static_cast<double>(n) * n;
    const double w[3] = {sxy[0] / sxx, sxy[1] / sxx, sxy[2] / sxx};
    const bool oneSign = (w[0] > 0 && w[1] > 0 && w[2] > 0) || (w[0] < 0 && w[1] < 0 && w[2] < 0);
    if (!oneSign)
        return 0.0;
    const double ref[3] = {0.2126, 0.7152, 0.0722};
    double dot = 0.0, ww = 0.0, rr = 0.0;
    for (int c = 0; c < 3; ++c) {
        dot += w[c] * ref[c];
        ww += w[c] * w[c];
        rr += ref[c] * ref[c];
    }
    if (!(ww > 0.0))
        return 0.0;
    // every axis must count, at least a quarter as much as in the neutral (a flat channel is
    // not a neutral's shape)
    const double scale = std::sqrt(ww / rr);
    for (int c = 0; c < 3; ++c)
        if (std::fabs(w[c]) < 0.25 * ref[c] * scale)
            return 0.0;
    return std::fabs(dot) / std::sqrt(ww * rr);
}

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

std::string fitsText(const std::vector<LayoutFit>& fits) {
    std::string s;
    for (const auto& f : fits)
        s += (s.empty() ? "" : ", ") + std::string(toString(f.layout));
    return s;
}

// The layouts of an N^2 x N strip, by the names users type: "unreal, unity and smush".
std::string stripLayoutNames() {
    std::string s;
    const auto layouts = layoutsForImageSize(256, 16);
    for (std::size_t i = 0; i < layouts.size(); ++i)
        s += (i == 0                    ? ""
              : i + 1 == layouts.size() ? " and "
                                        : ", ") +
             std::string(toString(layouts[i].layout));
    return s;
}

int defaultBitDepth(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == ".exr" || ext == ".hdr" ? 32 : 8;
}

struct Shaped {
    std::size_t index;
    std::string table;
};

// The one layout whose table is neutral-shaped in brightness (lumaShape >= 0.9, the others
// < 0.7), if there is one.
std::optional<Shaped> neutralShaped(const ImageView& img, const std::vector<LayoutFit>& fits) {
    std::vector<double> shape;
    std::string table;
    for (const auto& f : fits) {
        shape.push_back(lumaShape(lutFromImage(img, f.layout, f.size)));
        table += (table.empty() ? "" : ", ") + std::string(toString(f.layout)) + " " +
                 fmt2(shape.back());
    }
    std::optional<Shaped> found;
    for (std::size_t i = 0; i < fits.size(); ++i) {
        if (shape[i] >= 0.9) {
            if (found)
                return std::nullopt;
            found = Shaped{i, "brightness shape " + table};
        } else if (shape[i] >= 0.7) {
            return std::nullopt;
        }
    }
    return found;
}

// What the image's description says the LUT is for (a PNG tEXt "Description", a TIFF
// ImageDescription, an OpenEXR comments attribute holding "LUTKIT_PURPOSE smash").
std::optional<LutPurpose> purposeOf(const ImageMetadata* meta, const std::string& path) {
    std::optional<LutPurpose> found;
    if (!meta)
        return found;
    for (const auto& [key, value] : meta->text)
        if (const auto p = purposeInText(value, path + ": " + key)) {
            if (found && *found != *p)
                throw Error(path + ": two LUTKIT_PURPOSE tags that disagree (raw and smash)");
            found = p;
        }
    return found;
}

} // namespace

namespace {

// The picture size against the layouts, from the header before any pixel is decoded (a small
// file can claim a huge picture): the layouts the size fits; with a layout wanted, its N (else
// 0, decided from the pixels). Throws naming the sizes the layouts need.
std::vector<LayoutFit> checkLayoutSize(const std::string& path, const ImageInfo& header,
                                       std::optional<LutLayout> wanted, int& n) {
    const int w = header.width, h = header.height;
    const std::vector<LayoutFit> fits = layoutsForImageSize(w, h);

    n = 0;
    if (wanted) {
        const LutLayout layout = *wanted;
        n = layoutSizeForImage(layout, w, h);
        if (n == 0) {
            const std::string need =
                layout == LutLayout::Hald
                    ? "L^3 x L^3 pixels (e.g. 64x64 for 16^3, 512x512 for 64^3)"
                : layoutFixedSize(layout)
                    ? "1024x32 pixels (32^3; " + std::string(toString(layoutPlacement(layout))) +
                          " is the same placement at any N)"
                    : std::string("N^2 x N pixels with N 2..256 (e.g. 256x16, 1024x32)");
            throw Error(path + ": image is " + sizeText(w, h) + ", the " + toString(layout) +
                        " layout needs " + need +
                        (fits.empty() ? "" : "; this size fits " + fitsText(fits)));
        }
    } else if (fits.empty()) {
        throw Error(path + ": image is " + sizeText(w, h) +
                    ", not a LUT image size: " + stripLayoutNames() +
                    " need N^2 x N (e.g. 256x16), hald needs L^3 x L^3 (e.g. 64x64)");
    }

    return fits;
}

// The pixels, once their size was checked: at most a 256^3 LUT's worth (65536x256 or
// 4096x4096).
LoadedImage decodeLutImage(const std::string& path, const ImageInfo& header,
                           const std::function<LoadedImage()>& decode) {
    const std::uint64_t pixels =
        static_cast<std::uint64_t>(header.width) * static_cast<std::uint64_t>(header.height);
    return allocating(path, "decoding the " + sizeText(header.width, header.height) + " image",
                      pixels * (16 + 4 * static_cast<std::uint64_t>(std::max(header.channels, 1))),
                      decode);
}

// The LUT in the decoded image: the layout wanted (n its size) or detected (fits).
LutFile lutFromLoadedImage(const std::string& path, const LoadedImage& img,
                           std::optional<LutLayout> wanted, const std::vector<LayoutFit>& fits,
                           int n) {
    const int w = img.image.width(), h = img.image.height();
    LutLayout layout = wanted.value_or(LutLayout::Pilot);
    LutFile file;
    file.sourceBitDepth = img.info.isFloat ? 0 : img.info.bitDepth;
    file.purpose = purposeOf(img.metadata.get(), path);

    // Without --layout, the layout from the size, or (several fit) from the pixels.
    if (!wanted && fits.size() == 1) {
        layout = fits.front().layout;
        n = fits.front().size;
    } else if (!wanted) {
        // Several layouts fit: see the rule in the header comment.
        std::vector<AxisScore> scores;
        std::vector<std::size_t> passing;
        for (std::size_t i = 0; i < fits.size(); ++i) {
            scores.push_back(
                axisScore(lutFromImage(img.image.view(), fits[i].layout, fits[i].size)));
            if (scores.back().followsAxes())
                passing.push_back(i);
        }
        std::string table;
        for (std::size_t i = 0; i < fits.size(); ++i)
            table += (table.empty() ? "" : "; ") + std::string(toString(fits[i].layout)) + ": " +
                     scores[i].str();
        if (passing.size() == 1) {
            layout = fits[passing.front()].layout;
            n = fits[passing.front()].size;
            if (layout != defaultStripLayout(n))
                file.diagnostics.push_back(makeDiagnostic(
                    S::Info, path,
                    std::string("layout detected: ") + toString(layout) + " (" + sizeText(w, h) +
                        " fits " + fitsText(fits) + "; only in " + toString(layout) +
                        " does each output channel follow its own input axis, correlations " +
                        table + "); name the layout (--in-layout) to override"));
        } else if (const auto shaped = neutralShaped(img.image.view(), fits)) {
            layout = fits[shaped->index].layout;
            n = fits[shaped->index].size;
            file.diagnostics.push_back(makeDiagnostic(
                S::Info, path,
                std::string("layout detected: ") + toString(layout) + " (" + sizeText(w, h) +
                    " fits " + fitsText(fits) + "; only in " + toString(layout) +
                    " does the table's brightness weigh the inputs like a neutral's, e.g. after "
                    "a gradient map: " +
                    shaped->table + "); name the layout (--in-layout) to override"));
        } else {
            std::size_t best = 0;
            for (std::size_t i = 1; i < fits.size(); ++i)
                if (scores[i].sum() > scores[best].sum())
                    best = i;
            std::size_t def = fits.size();
            for (std::size_t i = 0; i < fits.size(); ++i)
                if (fits[i].layout == defaultStripLayout(fits[i].size))
                    def = i;
            if (passing.empty() && def < fits.size() &&
                scores[def].sum() >= scores[best].sum() - kScoreTie) {
                layout = fits[def].layout;
                n = fits[def].size;
                file.diagnostics.push_back(makeDiagnostic(
                    S::Warning, path,
                    "layout not detectable (" + sizeText(w, h) + " fits " + fitsText(fits) +
                        " and the table is not close to neutral in any: correlations " + table +
                        "); read as " + toString(layout) +
                        ", the default for N^2 x N images; name the layout (--in-layout) if it "
                        "is another"));
            } else {
                throw Error(path + ": image is " + sizeText(w, h) + ", which fits the layouts " +
                            fitsText(fits) +
                            (passing.empty() ? " and is close to neutral in none of them"
                                             : " and looks neutral in more than one") +
                            " (correlation of each output channel with its input axis: " + table +
                            "); name the layout (--in-layout): " +
                            (passing.empty() ? stripLayoutNames() : fitsText(fits)));
            }
        }
    }

    file.cube = lutFromImage(img.image.view(), layout, n);
    file.format = layout == LutLayout::Hald ? "hald" : "strip";
    file.dialect = toString(layout);
    if (img.info.channels < 3)
        file.diagnostics.push_back(makeDiagnostic(
            S::Warning, path, "grey image: the same value was used for red, green and blue"));
    std::size_t nonFinite = 0;
    for (auto& v : file.cube->entries())
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(v[c]))
                ++nonFinite;
    if (nonFinite)
        file.diagnostics.push_back(makeDiagnostic(
            S::Warning, path, std::to_string(nonFinite) + " channel values are NaN or infinite"));
    return file;
}

} // namespace

LutFile readLutImage(const std::string& path, const FormatOptions& options,
                     std::optional<LutLayout> forced) {
    const std::optional<LutLayout> wanted = forced ? forced : options.layout;
    // OpenImageIO opens the file itself: a FIFO, a directory or a device is refused first.
    checkRegularInput(path);
    const ImageInfo header = readImageInfo(path);
    int n = 0;
    const std::vector<LayoutFit> fits = checkLayoutSize(path, header, wanted, n);
    const LoadedImage img = decodeLutImage(path, header, [&] { return readImage(path); });
    if (img.image.width() != header.width || img.image.height() != header.height)
        throw Error(path + ": the file changed while being read (" +
                    sizeText(header.width, header.height) + " when opened, " +
                    sizeText(img.image.width(), img.image.height()) + " now)");
    return lutFromLoadedImage(path, img, wanted, fits, n);
}

LutFile readLutImageMemory(std::string_view bytes, const std::string& name,
                           const FormatOptions& options, std::optional<LutLayout> forced) {
    const std::optional<LutLayout> wanted = forced ? forced : options.layout;
    // One source: the header, checked, then its pixels (bytes in memory cannot change between).
    const auto source = openImageMemory(name, std::string(bytes));
    const ImageInfo header = source->info();
    int n = 0;
    const std::vector<LayoutFit> fits = checkLayoutSize(name, header, wanted, n);
    const LoadedImage img =
        decodeLutImage(name, header, [&] { return readFrame(*source, name, nullptr, kOnlyImage); });
    return lutFromLoadedImage(name, img, wanted, fits, n);
}

namespace {

// The picture of a LUT image and how to write it; diagnostics name path.
Image lutImage(const std::string& path, const LutFile& source, const FormatOptions& options,
               LutLayout layout, ImageWriteOptions& wo, Diagnostics& diags) {
    int bits = options.bitDepth > 0 ? options.bitDepth : defaultBitDepth(path);
    if (bits != 8 && bits != 16 && bits != 32)
        throw Error(path + ": bit depth " + std::to_string(bits) + " is not 8, 16 or 32 (float)");
    const std::string ext = extensionOf(path);
    if (ext == ".exr" && bits != 32)
        throw Error(path + ": EXR stores float values; use bit depth 32 or a .png/.tif file for " +
                    std::to_string(bits) + "-bit output");
    int size = options.size;
    if (const int fixed = layoutFixedSize(layout)) {
        if (const std::string problem = layoutSizeProblem(layout, size); !problem.empty())
            throw Error(path + ": " + problem);
        size = fixed;
    }
    if (layout == LutLayout::Hald) {
        const int own = size > 0 ? size : source.toLut3D(0).size();
        size = haldSizeFor(own);
        if (size != own)
            diags.push_back(
                makeDiagnostic(S::Info, path,
                               "a Hald image stores N = L^2 only: " + std::to_string(own) +
                                   "^3 written as " + haldSizeText(size)));
    }
    const Lut3D lut = prepareUnitLut(source, size, path, diags);
    if (bits != 32) {
        addClampDiagnostic(countOutOfUnitRange(lut), bits, path, diags);
        if (!options.dither)
            addQuantizationDiagnostic(lut, bits, path, diags);
    }
    wo = ImageWriteOptions();
    if (ext.empty())
        wo.format = "png"; // standard output, a device or a name without extension: a PNG
    wo.bitDepth = bits;
    wo.dither = options.dither;
    wo.alpha = true;
    if (source.purpose) { // what the LUT is for, in the image's description
        auto meta = std::make_shared<ImageMetadata>();
        meta->text.emplace_back("ImageDescription", purposeTag(*source.purpose));
        wo.metadata = std::move(meta);
    }
    return lutToImage(lut, layout);
}

} // namespace

bool lutImageKeepsPurpose(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext.empty() || ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr";
}

Diagnostics writeLutImage(const std::string& path, const LutFile& source,
                          const FormatOptions& options, LutLayout layout) {
    Diagnostics diags;
    ImageWriteOptions wo;
    const Image image = lutImage(path, source, options, layout, wo, diags);
    writeImage(path, image, wo);
    return diags;
}

std::string writeLutImageMemory(const std::string& name, const LutFile& source,
                                const FormatOptions& options, LutLayout layout,
                                Diagnostics* diagnostics) {
    Diagnostics diags;
    ImageWriteOptions wo;
    const Image image = lutImage(name, source, options, layout, wo, diags);
    std::string bytes = writeImageMemory(name, image, wo);
    if (diagnostics)
        *diagnostics = std::move(diags);
    return bytes;
}

namespace {

class StripFormat final : public Format {
public:
    std::string name() const override { return "strip"; }
    std::string description() const override {
        return "LUT image in a named layout (unreal/pilot/godot, unity, smush/lattice, hald, "
               "reshade/unreal-32, unity-32): PNG/TIFF 8/16-bit, float EXR";
    }
    int fixedSizeFor(const FormatOptions& options) const override {
        return options.layout ? layoutFixedSize(*options.layout) : 0;
    }
    std::vector<std::string> extensions() const override {
        return {".png", ".tif", ".tiff", ".exr"};
    }
    bool keepsPurpose(const std::string& path, LutPurpose) const override {
        return lutImageKeepsPurpose(path);
    }

    LutFile read(const std::string& path, const FormatOptions& options) const override {
        return readLutImage(path, options);
    }
    std::uint64_t maxStreamBytes(std::string_view head) const override {
        return imageStreamBytes(head);
    }
    Diagnostics write(const std::string& path, const LutFile& lut,
                      const FormatOptions& options) const override {
        const LutLayout layout = options.layout.value_or(LutLayout::Pilot);
        return writeLutImage(path, lut, options, layout);
    }
    // In memory through the same codecs, no temporary file (the editor's export preview makes
    // and reads back a strip at every adjustment).
    LutFile readMemory(std::string_view bytes, const std::string& name,
                       const FormatOptions& options) const override {
        return readLutImageMemory(bytes, name, options);
    }
    std::string writeMemory(const LutFile& lut, const std::string& name,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        return writeLutImageMemory(name, lut, options, options.layout.value_or(LutLayout::Pilot),
                                   diagnostics);
    }
};

} // namespace

std::unique_ptr<Format> makeStripFormat() {
    return std::make_unique<StripFormat>();
}

} // namespace lut::formats
