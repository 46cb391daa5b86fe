// SPDX-License-Identifier: Apache-2.0
// Built against an installed lutkit by tests/install (find_package(lutkit), lutkit::formats).
// Usage: consumer GRADE.cube OUT_DIR. Exits 1 with a message on the first check that fails:
//  - the installed lut/Version.h is the version the package was found with;
//  - the cube reads as a 33^3 LUT; written as a nutexb (16^3, 8-bit) and read back, every entry
//    is the original sampled at that lattice point to within half an 8-bit step;
//  - written as a LUT strip PNG through the installed image module (lutkit::imageio), the image is
//    33^2 x 33 pixels.
#include "lut/Version.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

bool fail(const std::string& what) {
    std::fprintf(stderr, "consumer: %s\n", what.c_str());
    return false;
}

bool run(const std::string& cubePath, const std::string& outDir) {
    if (std::string(LUTKIT_VERSION) != LUTKIT_EXPECTED_VERSION)
        return fail(std::string("lut/Version.h says ") + LUTKIT_VERSION);

    const lut::Lut3D grade = lut::formats::readLut(cubePath).toLut3D();
    if (grade.size() != 33)
        return fail("expected a 33^3 LUT, read " + std::to_string(grade.size()));

    const std::string nutexb = outDir + "/consumer.nutexb";
    lut::LutFile file;
    file.cube = grade;
    lut::formats::writeLut(nutexb, file);
    const lut::Lut3D stored = lut::formats::readLut(nutexb).toLut3D();
    if (stored.size() != 16)
        return fail("expected a 16^3 nutexb, read " + std::to_string(stored.size()));
    const auto sampler = lut::makeSampler(grade, lut::Interpolation::Tetrahedral);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::vec3 want = sampler->sample(stored.latticeInput(r, g, b));
                const glm::vec3 got = stored.at(r, g, b);
                for (int c = 0; c < 3; ++c)
                    if (std::fabs(got[c] - want[c]) > 0.5f / 255.0f + 1e-6f)
                        return fail("nutexb entry differs from the grade at " + std::to_string(r) +
                                    "," + std::to_string(g) + "," + std::to_string(b));
            }

    ::setenv("LUTKIT_IMAGEIO_MODULE", IMAGEIO_MODULE, 1);
    const std::string strip = outDir + "/consumer-strip.png";
    lut::formats::writeLut(strip, file);
    const lut::formats::ImageInfo info = lut::formats::readImageInfo(strip);
    if (info.width != 33 * 33 || info.height != 33)
        return fail("strip is " + std::to_string(info.width) + "x" + std::to_string(info.height));
    std::printf("consumer: lutkit %s, nutexb and strip ok\n", LUTKIT_VERSION);
    return true;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3)
        return fail("usage: consumer GRADE.cube OUT_DIR"), 2;
    try {
        return run(argv[1], argv[2]) ? 0 : 1;
    } catch (const std::exception& e) {
        return fail(e.what()), 1;
    }
}
