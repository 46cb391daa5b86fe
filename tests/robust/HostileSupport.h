// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for the hostile-file tests (issue 29): oiiotool to make real files, OpenImageIO's own
// reader as the oracle for pixels, /usr/bin/time for a command's peak memory, crafted bytes.
#include "RobustSupport.h"
#include "TestPaths.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace lut::robust {

// Sanitizer builds (scripts/sanitize.sh, tsan.sh) keep freed memory in quarantine and add
// shadow memory: peak memory figures mean nothing there.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kMemorySanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kMemorySanitized = true;
#else
constexpr bool kMemorySanitized = false;
#endif
#else
constexpr bool kMemorySanitized = false;
#endif

using lut::test::shellQuoted;

// Runs a shell command, its output discarded; its exit status.
inline int sh(const std::string& cmd) {
    const int status = std::system((cmd + " >/dev/null 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// oiiotool with these arguments (OpenImageIO's own writer makes the test files).
inline void oiiotool(const std::string& args) {
    ASSERT_EQ(sh("oiiotool " + args), 0) << "oiiotool " << args;
}

// A 2^3 .cube mapping (r, g, b) to (1 - r, 1 - g, 1 - b): linear, so every interpolation gives
// exactly 1 - x between the lattice points too; the oracle is that formula.
inline std::string invertCube(const std::string& dir) {
    std::string s = "LUT_3D_SIZE 2\n";
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r)
                s += std::to_string(1 - r) + " " + std::to_string(1 - g) + " " +
                     std::to_string(1 - b) + "\n";
    const std::string path = dir + "/invert.cube";
    writeBytes(path, s);
    return path;
}

// One image of a file as OpenImageIO reads it (float samples, interleaved).
struct OiioImage {
    bool ok = false;
    int width = 0, height = 0, channels = 0, tileWidth = 0, tileHeight = 0;
    int subimages = 0, mipLevels = 0;
    std::vector<float> pixels;
};

inline OiioImage oiioRead(const std::string& path, int subimage = 0, int mip = 0) {
    OiioImage img;
    auto in = OIIO::ImageInput::open(path);
    if (!in)
        return img;
    while (in->seek_subimage(img.subimages, 0))
        ++img.subimages;
    while (in->seek_subimage(subimage, img.mipLevels))
        ++img.mipLevels;
    (void)in->geterror(); // seeking one past the last is how the counts were found
    if (!in->seek_subimage(subimage, mip))
        return img;
    const OIIO::ImageSpec& s = in->spec();
    img.width = s.width;
    img.height = s.height;
    img.channels = s.nchannels;
    img.tileWidth = s.tile_width;
    img.tileHeight = s.tile_height;
    img.pixels.resize(static_cast<std::size_t>(s.width) * s.height * s.nchannels);
    img.ok =
        in->read_image(subimage, mip, 0, s.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data()) &&
        !in->has_error();
    (void)in->geterror();
    return img;
}

// The largest |out - (1 - in)| over the colour channels (the first three, or the only one).
inline double worstInverted(const OiioImage& in, const OiioImage& out) {
    if (!in.ok || !out.ok || in.width != out.width || in.height != out.height)
        return 1e9;
    double worst = 0.0;
    const int colour = std::min(3, std::min(in.channels, out.channels));
    const std::size_t pixels = static_cast<std::size_t>(in.width) * in.height;
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < colour; ++c)
            worst = std::max(worst, std::abs(static_cast<double>(out.pixels[p * out.channels + c]) -
                                             (1.0 - in.pixels[p * in.channels + c])));
    return worst;
}

// Runs `lutkit ARGS` (standard input from `input`) under /usr/bin/time: the result and the peak
// resident memory in MiB.
struct Measured {
    test::RunResult run;
    double peakMiB = 0.0;
};
inline Measured runMeasured(const std::string& args, const std::string& dir,
                            const std::string& input = "/dev/null") {
    Measured m;
    const std::string timeFile = dir + "/time.txt", out = dir + "/run.out", err = dir + "/run.err";
    const std::string cmd = "/usr/bin/time -f 'peak %M' -o " + shellQuoted(timeFile) + " " +
                            shellQuoted(LUTKIT_CLI) + " " + args + " <" + shellQuoted(input) +
                            " >" + shellQuoted(out) + " 2>" + shellQuoted(err);
    const int status = std::system(cmd.c_str());
    m.run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    m.run.out = fileBytes(out);
    m.run.err = fileBytes(err);
    const std::string t = fileBytes(timeFile);
    const auto at = t.rfind("peak ");
    m.peakMiB = at == std::string::npos ? -1.0 : std::atof(t.c_str() + at + 5) / 1024.0;
    return m;
}

inline std::string le16(unsigned v) {
    return {char(v & 0xFF), char((v >> 8) & 0xFF)};
}
inline std::string le32(std::uint32_t v) {
    return {char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
}

} // namespace lut::robust
