// SPDX-License-Identifier: Apache-2.0
// Shows what Smash Ultimate would show: runs the game's post-processing (bloom, the grading LUT
// with its brighten and alpha mix, sRGB display; lut/pipeline/Pipeline.h) on a linear HDR scene.
//   api_smash_preview SCENE.exr GRADE.cube OUT.png
// Checks, exiting 1 on the first failure:
//  - every output value is finite and not negative (the spec's promise for finite input; the
//    brighten pass may carry values above 1, which the screen clips);
//  - a second run gives the same bits (the stages run on all cores; the result must not depend
//    on how the rows were shared out);
//  - the grade matters: the same scene with a neutral LUT differs somewhere by more than one
//    8-bit step.
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/pipeline/Pipeline.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

namespace {

int fail(const std::string& what) {
    std::fprintf(stderr, "api_smash_preview: %s\n", what.c_str());
    return 1;
}

int run(const std::string& scenePath, const std::string& lutPath, const std::string& outPath) {
    const lut::Image scene = lut::formats::readImage(scenePath).image; // linear, values above 1
    auto grade = std::make_shared<const lut::Lut3D>(lut::formats::readLut(lutPath).toLut3D());

    lut::Pipeline smash(lut::Preset::Smash);
    smash.setLut(grade);
    lut::PipelineReport report;
    const lut::Image shown = smash.run(scene, {}, &report);
    const lut::Image again = smash.run(scene);

    smash.setLut(nullptr); // neutral
    const lut::Image ungraded = smash.run(scene);

    float gradeEffect = 0.0f;
    for (std::size_t i = 0; i < shown.pixels().size(); ++i) {
        const float v = shown.pixels()[i];
        if (!std::isfinite(v) || v < 0.0f)
            return fail("value " + std::to_string(v) + " at float " + std::to_string(i));
        if (again.pixels()[i] != v)
            return fail("a second run differs at float " + std::to_string(i));
        gradeEffect = std::fmax(gradeEffect, std::fabs(v - ungraded.pixels()[i]));
    }
    if (gradeEffect <= 1.0f / 255.0f)
        return fail("the grading LUT made no visible difference");

    lut::formats::writeImage(outPath, shown, {}); // 8-bit, alpha kept
    std::printf("%s: %dx%d in %.1f ms (grade changes up to %.3f)\n", outPath.c_str(), shown.width(),
                shown.height(), report.totalMilliseconds, gradeEffect);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: api_smash_preview SCENE.exr GRADE.cube OUT.png\n");
        return 2;
    }
    try {
        return run(argv[1], argv[2], argv[3]);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
