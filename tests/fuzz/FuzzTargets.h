// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fuzz targets, shared by the libFuzzer harnesses (tests/fuzz/fuzz_*.cpp, clang build) and
// the regression replay (tests/regress, normal build): a crashing input found by a fuzzer is
// replayed through exactly the same code path by the ordinary test suite.
//
// Contract checked for every reader: given any bytes it returns a well-formed LutFile or throws
// lut::Error. Any other exception escapes (the fuzzer reports it as a crash, the replay test as a
// failure); a malformed result trips invariant(), which traps.
#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/LutFile.h"
#include "lut/formats/Atlas.h"
#include "lut/formats/Cube.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Format.h"
#include "nutexb/NutexbCodec.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

namespace lut::fuzz {

enum class Outcome { Accepted, Refused };

// A failed invariant is a bug in the reader even though nothing crashed: stop loudly.
inline void invariant(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz invariant violated: %s\n", what);
        std::abort();
    }
}

// One scratch folder per process (tmpfs when available: the readers take paths, not bytes).
inline const std::filesystem::path& scratchDir() {
    static const std::filesystem::path dir = [] {
        std::filesystem::path base = std::filesystem::exists("/dev/shm")
                                         ? std::filesystem::path("/dev/shm")
                                         : std::filesystem::temp_directory_path();
        auto d = base / ("lutkit-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

inline std::string writeScratch(const std::string& name, const std::uint8_t* data,
                                std::size_t size) {
    const std::string path = (scratchDir() / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

// Checks what any reader promises about a result it returns.
inline void checkLutFile(const LutFile& f) {
    invariant(f.cube.has_value() || f.shaper.has_value(), "result holds neither cube nor shaper");
    if (f.cube) {
        const int n = f.cube->size();
        invariant(n >= limits::kMin3DSize && n <= limits::kMax3DSize, "3D size out of range");
        invariant(f.cube->entries().size() == static_cast<std::size_t>(n) * n * n,
                  "3D entry count differs from size^3");
        const auto lo = f.cube->domainMin(), hi = f.cube->domainMax();
        for (int c = 0; c < 3; ++c)
            invariant(std::isfinite(lo[c]) && std::isfinite(hi[c]) && lo[c] < hi[c],
                      "bad 3D domain");
    }
    if (f.shaper) {
        const int n = f.shaper->size();
        invariant(n >= limits::kMin1DSize && n <= limits::kMax1DSize, "1D size out of range");
    }
}

inline Outcome readChecked(const std::string& path, const FormatOptions& options) {
    try {
        LutFile f = formats::readLut(path, options);
        checkLutFile(f);
        return Outcome::Accepted;
    } catch (const lut::Error&) {
        return Outcome::Refused;
    }
}

// The same picture read as an atlas (lut/formats/Atlas.h): whole rows of one size, or refused.
inline Outcome readAtlasChecked(const std::string& path) {
    try {
        const formats::AtlasReading a = formats::readAtlas(path);
        invariant(a.shape.size >= 2 && a.shape.size <= 256, "atlas row size out of range");
        invariant(a.shape.rows >= 1 && a.height == a.shape.rows * a.shape.size &&
                      a.width == a.shape.size * a.shape.size,
                  "atlas shape differs from the picture");
        invariant(a.neutral.size() == static_cast<std::size_t>(a.shape.rows),
                  "atlas rows differ from its shape");
        for (const auto& [later, earlier] : a.duplicates)
            invariant(earlier < later && later < a.shape.rows, "atlas repeat out of range");
        return Outcome::Accepted;
    } catch (const lut::Error&) {
        return Outcome::Refused;
    }
}

inline Outcome checkedCall(const auto& read) {
    try {
        LutFile f = read();
        checkLutFile(f);
        return Outcome::Accepted;
    } catch (const lut::Error&) {
        return Outcome::Refused;
    }
}

// .cube: the bytes are the file, parsed straight from the fuzzer's buffer (it has exactly `size`
// bytes, so AddressSanitizer sees any read past the end), in normal and strict mode.
inline Outcome runCube(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const Outcome o = checkedCall([&] { return formats::parseCube(text, "fuzz.cube"); });
    formats::CubeReadOptions strict;
    strict.strict = true;
    const Outcome s = checkedCall([&] { return formats::parseCube(text, "fuzz.cube", strict); });
    invariant(o == s, "strict mode changed whether a .cube file is accepted");
    if (o == Outcome::Accepted) {
        // What we accept we must be able to write, and read back.
        const LutFile f = formats::parseCube(text, "fuzz.cube");
        const std::string again = formats::writeCubeString(f);
        invariant(checkedCall([&] { return formats::parseCube(again, "again.cube"); }) ==
                      Outcome::Accepted,
                  "a .cube file we wrote does not read back");
    }
    return o;
}

// nutexb: the bytes are the file, parsed from the fuzzer's buffer.
inline Outcome runNutexb(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const Outcome o = checkedCall([&] { return formats::nutexb::readBytes(bytes, "fuzz.nutexb"); });
    if (o == Outcome::Accepted) {
        // Reading back what we write from an accepted volume gives the same 8-bit texels.
        const LutFile f = formats::nutexb::readBytes(bytes, "fuzz.nutexb");
        const std::string again = formats::nutexb::writeBytes(*f.cube, "", true);
        const LutFile g = formats::nutexb::readBytes(again, "again.nutexb");
        invariant(g.cube->entries() == f.cube->entries(), "nutexb write/read changed texels");
    }
    return o;
}

// LUT images. Raw image bytes would mostly exercise libpng; what we own is the layout code, so
// the fuzz bytes describe a small image that OIIO writes as a real file, which our reader then
// maps through a layout:
//   byte 0: bit 7 set -> the rest is the raw file (.png), to exercise header checks;
//           else bits 0-2 layout (pilot, unity, smush, unreal, godot, lattice, "" auto, hald),
//           bits 3-4 file type (png8, png16, tif16, exr float)
//   byte 1: the LUT edge N (2..17) or, for hald, the level L (2..4)
//   byte 2: bit 0 set -> width and height from bytes 3 and 4 (1..256, 1..64) instead of the
//           layout's own size; bits 1-2 channels (3, 4, 1, 2)
//   rest:   pixel values, repeated to fill the image (float files read them as 32-bit floats,
//           so NaN, Inf and huge values reach the reader)
struct ImageSpecFromBytes {
    std::string layout;
    std::string ext;
    OIIO::TypeDesc type = OIIO::TypeDesc::UINT8;
    int width = 0, height = 0, channels = 4;
};

inline Outcome runImage(const std::uint8_t* data, std::size_t size, bool hald) {
    if (size < 5)
        return Outcome::Refused;
    FormatOptions options;
    if (data[0] & 0x80) {
        if (hald)
            options.layout = LutLayout::Hald;
        const std::string raw =
            writeScratch(hald ? "raw-hald.png" : "raw-strip.png", data + 1, size - 1);
        if (!hald)
            (void)readAtlasChecked(raw); // the strip harness reads every picture as an atlas too
        return readChecked(raw, options);
    }
    static const char* const kLayouts[] = {"pilot", "unity",   "smush", "unreal",
                                           "godot", "lattice", "",      "hald"};
    ImageSpecFromBytes s;
    s.layout = hald ? "hald" : kLayouts[data[0] & 7];
    switch ((data[0] >> 3) & 3) {
    case 0:
        s.ext = ".png";
        s.type = OIIO::TypeDesc::UINT8;
        break;
    case 1:
        s.ext = ".png";
        s.type = OIIO::TypeDesc::UINT16;
        break;
    case 2:
        s.ext = ".tif";
        s.type = OIIO::TypeDesc::UINT16;
        break;
    default:
        s.ext = ".exr";
        s.type = OIIO::TypeDesc::FLOAT;
        break;
    }
    if (s.layout == "hald") {
        const int level = 2 + data[1] % 3; // 2..4: up to 64x64, N = 16
        s.width = s.height = level * level * level;
    } else {
        const int n = 2 + data[1] % 16; // up to 289x17: small images keep the fuzzer fast
        s.width = n * n;
        s.height = n;
    }
    if (data[2] & 1) {
        s.width = 1 + data[3];
        s.height = 1 + data[4] % 64;
    }
    static const int kChannels[] = {3, 4, 1, 2};
    s.channels = kChannels[(data[2] >> 1) & 3];
    if (!s.layout.empty())
        options.layout = parseLayout(s.layout);

    const std::uint8_t* px = data + 5;
    const std::size_t pxSize = size - 5;
    const std::size_t bytesPer = s.type.size();
    const std::size_t total = static_cast<std::size_t>(s.width) * s.height * s.channels * bytesPer;
    std::vector<std::uint8_t> pixels(total, 0);
    if (pxSize > 0)
        for (std::size_t i = 0; i < total; ++i)
            pixels[i] = px[i % pxSize];

    const std::string path = (scratchDir() / ((hald ? "hald" : "strip") + s.ext)).string();
    {
        auto out = OIIO::ImageOutput::create(path);
        if (!out)
            return Outcome::Refused;
        OIIO::ImageSpec spec(s.width, s.height, s.channels, s.type);
        if (!out->open(path, spec) || !out->write_image(s.type, pixels.data()))
            return Outcome::Refused;
        out->close();
    }
    if (!hald)
        (void)readAtlasChecked(path);
    return readChecked(path, options);
}

inline Outcome runStrip(const std::uint8_t* data, std::size_t size) {
    return runImage(data, size, false);
}
inline Outcome runHald(const std::uint8_t* data, std::size_t size) {
    return runImage(data, size, true);
}

// Parse helpers the CLI uses for user-typed words and numbers. The bytes are one argument.
inline Outcome runCliWords(const std::uint8_t* data, std::size_t size) {
    const std::string_view word(reinterpret_cast<const char*>(data), size);
    Outcome o = Outcome::Refused;
    try {
        const Interpolation m = parseInterpolation(word);
        invariant(parseInterpolation(toString(m)) == m, "interpolation name does not round-trip");
        o = Outcome::Accepted;
    } catch (const lut::Error&) {
    }
    return o;
}

} // namespace lut::fuzz
