// SPDX-License-Identifier: Apache-2.0
// Built-in LUTs (lut/io/BuiltinLut.h): builtin:smash-default holds the reference renderer's
// default stage LUT, written here from its source (ScanMountGoat/ssbh_wgpu,
// ssbh_wgpu/src/texture.rs, create_default_lut: the values below per channel, x = red, y = green,
// z = blue, Rgba8Unorm); builtin:neutral the identity; other names are refused listing these.
#include "lut/Error.h"
#include "lut/formats/Registry.h"
#include "lut/io/BuiltinLut.h"

#include <gtest/gtest.h>

#include <string>

using namespace lut;

TEST(BuiltinLut, SmashDefaultIsTheReferenceRenderersTable) {
    const int values[16] = {0,   15,  30,  46,  64,  82,  101, 121,
                            140, 158, 176, 193, 209, 224, 240, 255};
    const Lut3D l = builtinLut("builtin:smash-default");
    ASSERT_EQ(l.size(), 16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::vec3 e = l.at(r, g, b);
                ASSERT_EQ(e.r * 255.0f, static_cast<float>(values[r]));
                ASSERT_EQ(e.g * 255.0f, static_cast<float>(values[g]));
                ASSERT_EQ(e.b * 255.0f, static_cast<float>(values[b]));
            }
    EXPECT_TRUE(isBuiltinGameLut("builtin:smash-default"));
    EXPECT_FALSE(isBuiltinGameLut("builtin:neutral"));
    EXPECT_FALSE(isBuiltinGameLut("smash-default"));
}

TEST(BuiltinLut, ReadLutAnswersTheNamesAndRefusesOthers) {
    const LutFile n = formats::readLut("builtin:neutral");
    ASSERT_TRUE(n.cube);
    EXPECT_EQ(n.cube->size(), 16);
    EXPECT_TRUE(n.cube->isIdentity(0.0f));
    EXPECT_EQ(n.format, "builtin");
    EXPECT_EQ(n.dialect, "neutral");
    try {
        (void)formats::readLut("builtin:smash");
        FAIL();
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("unknown built-in LUT 'builtin:smash'"), std::string::npos) << m;
        EXPECT_NE(m.find("builtin:neutral, builtin:smash-default"), std::string::npos) << m;
        EXPECT_NE(m.find("./builtin:smash"), std::string::npos) << m;
    }
    // A file is still a file: ./builtin:x is a path.
    EXPECT_FALSE(isBuiltinLutName("./builtin:neutral"));
}
