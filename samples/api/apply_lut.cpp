// SPDX-License-Identifier: Apache-2.0
// Applies a .cube LUT to an image the way `lutkit apply` does: the stored pixel values go through
// the LUT (no colour conversion), alpha passes through.
//   api_apply_lut GRADE.cube IMAGE OUT.png
// ctest runs it on samples/sample_grade.cube and samples/sample_scene.png and it checks, exiting 1
// on the first failure:
//  - the LUT changed the picture (some value moved by more than one 8-bit step);
//  - the 16-bit PNG read back holds, for every pixel, what Sampler::sample() (the scalar
//    reference) gives for the input pixel, to one 16-bit step (the rounding, plus the float
//    rounding differences between the SIMD kernel apply() runs and sample(), which can carry a
//    value over a rounding boundary), and the input alpha exactly.
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

namespace {

int fail(const std::string& what) {
    std::fprintf(stderr, "api_apply_lut: %s\n", what.c_str());
    return 1;
}

int run(const std::string& lutPath, const std::string& imagePath, const std::string& outPath) {
    // Any LUT format the registry knows; toLut3D() bakes a 1D shaper in, if the file has one.
    const lut::Lut3D grade = lut::formats::readLut(lutPath).toLut3D();
    const auto sampler = lut::makeSampler(grade, lut::Interpolation::Tetrahedral);

    const lut::Image input = lut::formats::readImage(imagePath).image;
    lut::Image graded = input;
    sampler->apply(graded.view()); // all cores

    lut::formats::ImageWriteOptions options;
    options.bitDepth = 16;
    lut::formats::writeImage(outPath, graded, options);

    const lut::Image written = lut::formats::readImage(outPath).image;
    if (written.width() != input.width() || written.height() != input.height())
        return fail("the written image has another size");
    const float step16 = 1.0f / 65535.0f;
    float largestChange = 0.0f;
    for (int y = 0; y < input.height(); ++y)
        for (int x = 0; x < input.width(); ++x) {
            const float* in = input.pixel(x, y);
            const float* out = written.pixel(x, y);
            const glm::vec3 want = sampler->sample({in[0], in[1], in[2]});
            for (int c = 0; c < 3; ++c) {
                if (std::fabs(out[c] - want[c]) > step16)
                    return fail("pixel " + std::to_string(x) + "," + std::to_string(y) + " is " +
                                std::to_string(out[c]) + ", the LUT gives " +
                                std::to_string(want[c]));
                largestChange = std::fmax(largestChange, std::fabs(out[c] - in[c]));
            }
            if (out[3] != in[3])
                return fail("alpha changed at " + std::to_string(x) + "," + std::to_string(y));
        }
    if (largestChange <= 1.0f / 255.0f)
        return fail("the LUT left the picture unchanged");
    std::printf("%s: %dx%d graded with %s (largest change %.3f)\n", outPath.c_str(),
                written.width(), written.height(), lutPath.c_str(), largestChange);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: api_apply_lut GRADE.cube IMAGE OUT.png\n");
        return 2;
    }
    try {
        return run(argv[1], argv[2], argv[3]);
    } catch (const std::exception& e) { // lut::Error names the file and what is wrong with it
        return fail(e.what());
    }
}
