// SPDX-License-Identifier: Apache-2.0
// The truth harness, fit: the printed maxima ("error over those pixels", "held out") against the
// written LUT read by OpenColorIO (tetrahedral) on every pixel of the picture it was fitted on,
// for a float .cube and a 12-bit .3dl. The edit is a float64 formula written here, stored 8-bit as
// the after picture holds it.
#include "TruthHarness.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

glm::dvec3 edit(glm::dvec3 x) {
    glm::dvec3 t;
    for (int c = 0; c < 3; ++c)
        t[c] = std::pow(x[c], 0.8);
    const double y = 0.3 * t.x + 0.6 * t.y + 0.1 * t.z;
    t = glm::dvec3(y) + 1.3 * (t - glm::dvec3(y));
    t *= glm::dvec3(1.05, 1.0, 0.9);
    for (int c = 0; c < 3; ++c)
        t[c] = std::clamp(t[c], 0.0, 1.0);
    return t;
}

} // namespace

TEST(Truth, FitPrintedMaximaBoundTheFittedPicture) {
    const std::string dir = workDir("fit");
    const int w = 320, h = 200;
    std::mt19937 rng(40);
    std::uniform_int_distribution<int> u(0, 255);
    std::vector<unsigned char> before(static_cast<std::size_t>(w) * h * 3), after(before.size());
    // smooth gradients with noise, like a screenshot's colours
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = 0.5 + 0.45 * std::sin(0.021 * x * (c + 1) + 0.033 * y * (3 - c));
                const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 3 + c;
                before[i] = static_cast<unsigned char>(
                    std::clamp(std::lround(v * 255.0) + u(rng) % 9 - 4, 0l, 255l));
            }
    for (std::size_t i = 0; i < before.size(); i += 3) {
        const glm::dvec3 e = edit(glm::dvec3(before[i], before[i + 1], before[i + 2]) / 255.0);
        for (int c = 0; c < 3; ++c)
            after[i + c] = static_cast<unsigned char>(std::lround(e[c] * 255.0));
    }
    writePng(dir + "/before.png", w, h, before);
    writePng(dir + "/after.png", w, h, after);
    for (const std::string ext : {".cube", ".3dl"}) {
        for (const int size : {9, 17}) {
            const std::string out = dir + "/fit" + std::to_string(size) + ext;
            const auto r = lut::test::runCli("fit " + shellQuoted(dir + "/before.png") + " " +
                                             shellQuoted(dir + "/after.png") + " " +
                                             shellQuoted(out) + " --size " + std::to_string(size));
            ASSERT_EQ(r.exitCode, 0) << r.err;
            std::vector<float> x(before.size()), want(before.size());
            for (std::size_t i = 0; i < x.size(); ++i) {
                x[i] = before[i] / 255.0f;
                want[i] = after[i] / 255.0f;
            }
            ocioApply(out, x);
            const Truth t = compare(want, x);
            const double pixels = maxAfter(r.out, "error over those pixels") / 255.0;
            const double held = maxAfter(r.out, "held out") / 255.0;
            row("fit " + std::to_string(size) + "^3 " + ext + ": pixels", t.max, pixels);
            row("fit " + std::to_string(size) + "^3 " + ext + ": held out", t.max, held);
            EXPECT_GE(held, t.max) << r.out;
            if (ext == ".cube") { // the pixels' figure is the float table's (a .3dl adds 12 bits)
                EXPECT_GE(pixels, t.max) << r.out;
            }
        }
    }
}
