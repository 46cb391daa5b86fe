// SPDX-License-Identifier: Apache-2.0
// The write matrix (issue 41: every TIFF written from a JPEG was unreadable, exit 0, and nothing
// in the tests read such a TIFF with another program). tests/robust/write_matrix.py makes inputs
// with oiiotool and ImageMagick (with and without Exif, an ICC profile and the sRGB tag; 8/16-bit,
// half and float; with and without alpha; tiled, multi-page, multi-part, MIP-mapped), runs lutkit,
// and reads every output back with oiiotool, ImageMagick (ffmpeg for DPX) and, for TIFF, libtiff's
// tiffinfo and tiffdump, comparing its pixels in numpy with an affine LUT's formula applied to
// OpenImageIO's reading of the input, and its tags with the input's. One test per group: each
// output format of `apply`, the structures, standard output, every compression, preview, embed.
#include "RobustSupport.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <string>

namespace {

const char* const kPython = "/usr/bin/python3"; // Debian's, with numpy

bool haveOracles(std::string& missing) {
    for (const char* p : {"oiiotool", "convert", "tiffinfo", "tiffdump", "ffmpeg"})
        if (!lut::test::haveProgram(p))
            missing += std::string(missing.empty() ? "" : ", ") + p;
    if (lut::test::runCommand(std::string(kPython) + " -c 'import numpy'").exitCode != 0)
        missing += std::string(missing.empty() ? "" : ", ") + "numpy in " + kPython;
    return missing.empty();
}

class WriteMatrix : public ::testing::TestWithParam<std::string> {};

TEST_P(WriteMatrix, EveryOutputReadBackByOtherPrograms) {
    std::string missing;
    if (!haveOracles(missing))
        GTEST_SKIP() << "the outside readers are missing: " << missing
                     << " (scripts/install-deps.sh installs them)";
    const std::string dir = lut::test::tempDir();
    const std::string script =
        lut::test::shellQuoted(std::string(LUTKIT_SOURCE_DIR) + "/tests/robust/write_matrix.py");
    const std::string run = std::string(kPython) + " " + script + " " +
                            lut::test::shellQuoted(LUTKIT_CLI) + " " + lut::test::shellQuoted(dir) +
                            " ";
    const auto inputs = lut::test::runCommand(run + "inputs");
    ASSERT_EQ(inputs.exitCode, 0) << inputs.out << inputs.err;
    const auto r = lut::test::runCommand(run + lut::test::shellQuoted(GetParam()));
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find(" comparisons, 0 failures"), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(Groups, WriteMatrix,
                         ::testing::Values("apply:png", "apply:jpg", "apply:tif", "apply:exr",
                                           "apply:bmp", "apply:tga", "apply:hdr", "apply:webp",
                                           "apply:dpx", "apply:gif", "apply:ppm", "structure",
                                           "stdout", "compression", "preview", "embed"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string n = info.param;
                             for (char& c : n)
                                 if (c == ':')
                                     c = '_';
                             return n;
                         });

} // namespace
