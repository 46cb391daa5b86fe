// SPDX-License-Identifier: Apache-2.0
// Auto-detection of the layout of an N^2 x N image (rule in formats/src/image/StripFormat.cpp): a
// table that is close to neutral (each output channel follows its own input axis) in exactly
// one layout is read in it; else the one layout whose brightness is neutral-shaped; otherwise
// unreal (pilot) when it is the most plausible, else refused.
#include "lut/formats/Registry.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <cmath>

using lut::test::tempDir;

namespace {

lut::LutFile fileOf(const lut::Lut3D& l) {
    lut::LutFile f;
    f.cube = l;
    return f;
}

void write(const std::string& path, const lut::Lut3D& l, const std::string& layout) {
    lut::FormatOptions o;
    o.layout = lut::parseOptionalLayout(layout);
    lut::formats::writeLut(path, fileOf(l), o);
}

const lut::Diagnostic* find(const lut::Diagnostics& d, const std::string& s) {
    for (const auto& x : d)
        if (x.message.find(s) != std::string::npos)
            return &x;
    return nullptr;
}

// A typical grade: contrast S-curve, warm tint, some cross-talk; each channel still rises with
// its own input.
lut::Lut3D grade(int n) {
    lut::Lut3D lut(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 in = glm::vec3(r, g, b) / static_cast<float>(n - 1);
                auto s = [](float x) { return x * x * (3.0f - 2.0f * x); };
                const float luma = 0.2126f * in.x + 0.7152f * in.y + 0.0722f * in.z;
                glm::vec3 o(s(in.x) * 1.05f + 0.02f, s(in.y), s(in.z) * 0.9f);
                o = glm::mix(glm::vec3(luma), o, 0.8f);
                lut.at(r, g, b) = glm::clamp(o, 0.0f, 1.0f);
            }
    return lut;
}

} // namespace

TEST(StripDetect, NeutralInEachLayoutIsFoundAndSaidUnlessDefault) {
    const std::string dir = tempDir();
    for (const char* layout : {"unreal", "unity", "smush"}) {
        for (int n : {2, 16, 32}) {
            SCOPED_TRACE(std::string(layout) + " " + std::to_string(n));
            const std::string path = dir + "/" + layout + std::to_string(n) + ".png";
            write(path, lut::Lut3D::identity(n), layout);
            const lut::LutFile f = lut::formats::readLut(path);
            // 1024x32 pictures are named by the size their engines read: unreal's placement is
            // reshade (Unreal's and ReShade's 1024x32), unity's unity-32.
            const std::string named = n != 32                           ? layout
                                      : std::string(layout) == "unreal" ? "reshade"
                                      : std::string(layout) == "unity"  ? "unity-32"
                                                                        : layout;
            EXPECT_EQ(f.dialect, named);
            EXPECT_LE(f.cube->maxDeviationFromIdentity(), 0.5f / 255.0f + 1e-6f);
            if (std::string(layout) == "unreal") {
                // A clean strip read as the default layout changes nothing the user expects:
                // no note (it used to print ~250 characters on every read, issue 18).
                EXPECT_TRUE(f.diagnostics.empty()) << f.diagnostics.front().str();
                continue;
            }
            const lut::Diagnostic* d = find(f.diagnostics, "layout detected: " + named);
            ASSERT_NE(d, nullptr);
            EXPECT_EQ(d->severity, lut::Diagnostic::Severity::Info);
        }
    }
}

TEST(StripDetect, GradedLutIsFoundInItsOwnLayout) {
    const std::string dir = tempDir();
    for (const char* layout : {"pilot", "unity", "smush"}) {
        SCOPED_TRACE(layout);
        const std::string path = dir + "/" + std::string(layout) + ".png";
        write(path, grade(16), layout);
        const lut::LutFile f = lut::formats::readLut(path);
        EXPECT_EQ(f.dialect, lut::toString(lut::parseLayout(layout)));
        // Same values as reading with the layout given.
        lut::FormatOptions o;
        o.layout = lut::parseOptionalLayout(layout);
        EXPECT_EQ(f.cube->entries(), lut::formats::readLut(path, o).cube->entries());
    }
}

TEST(StripDetect, NeutralShapedBrightnessDecidesWhenNoChannelFollowsItsAxis) {
    // Black and white, a gradient map and an inverting map of a neutral: every channel is a
    // function of the input's luma, so no layout has each channel on its own axis; only in the
    // layout it was drawn in does the table's brightness weigh r, g, b like a neutral's. This is
    // Smush-LUT's neutral.png (smush layout) graded with a gradient map.
    const std::string dir = tempDir();
    auto lumaMap = [](auto f) {
        lut::Lut3D l(16);
        for (int b = 0; b < 16; ++b)
            for (int g = 0; g < 16; ++g)
                for (int r = 0; r < 16; ++r)
                    l.at(r, g, b) = f((0.2126f * r + 0.7152f * g + 0.0722f * b) / 15.0f);
        return l;
    };
    const lut::Lut3D maps[] = {
        lumaMap([](float y) { return glm::vec3(y); }),
        lumaMap([](float y) { return glm::vec3(0.1f + 0.8f * y, 0.9f * y * y, 0.3f + 0.4f * y); }),
        lumaMap([](float y) { return glm::vec3(1.0f - y, 0.95f - 0.9f * y, 0.9f - 0.8f * y); })};
    for (const char* layout : {"pilot", "smush", "unity"})
        for (std::size_t i = 0; i < 3; ++i) {
            SCOPED_TRACE(std::string(layout) + " map " + std::to_string(i));
            const std::string path = dir + "/map" + std::to_string(i) + layout + ".png";
            write(path, maps[i], layout);
            const lut::LutFile f = lut::formats::readLut(path);
            EXPECT_EQ(f.dialect, toString(lut::parseLayout(layout)));
            const lut::Diagnostic* d = find(f.diagnostics, "brightness");
            ASSERT_NE(d, nullptr);
            EXPECT_EQ(d->severity, lut::Diagnostic::Severity::Info);
            EXPECT_NE(d->message.find("--in-layout"), std::string::npos);
            EXPECT_NEAR(f.cube->at(15, 0, 0).x, maps[i].at(15, 0, 0).x, 0.5f / 255.0f);
        }
}

TEST(StripDetect, UndecidableStripDefaultsToPilotWithWarning) {
    // A table no layout explains (each channel a valley along its own axis: no correlation, no
    // brightness trend): pilot and smush score the same, so the N^2 x N default (unreal) is used,
    // with a warning.
    const std::string dir = tempDir();
    lut::Lut3D wave(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                wave.at(r, g, b) = glm::vec3((r - 7.5f) * (r - 7.5f), (g - 7.5f) * (g - 7.5f),
                                             (b - 7.5f) * (b - 7.5f)) /
                                   56.25f;
    write(dir + "/wave.png", wave, "pilot");
    const lut::LutFile f = lut::formats::readLut(dir + "/wave.png");
    EXPECT_EQ(f.dialect, "unreal");
    const lut::Diagnostic* d = find(f.diagnostics, "read as unreal, the default");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->severity, lut::Diagnostic::Severity::Warning);
}

TEST(StripDetect, AmbiguousAndNotPilotLikeIsRefusedNamingLayouts) {
    // In pilot order this table has red on r, green running backwards and blue flat: it looks
    // more like unity (r and g follow their axes) than pilot, yet is neutral in no layout.
    const std::string dir = tempDir();
    lut::Lut3D odd(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                odd.at(r, g, b) = glm::vec3(r / 15.0f, (15 - g) / 15.0f, 0.5f);
    write(dir + "/odd.png", odd, "pilot");
    try {
        (void)lut::formats::readLut(dir + "/odd.png");
        FAIL() << "read without a layout";
    } catch (const lut::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("256x16"), std::string::npos) << m;
        EXPECT_NE(m.find("unreal, unity, smush"), std::string::npos) << m;
        EXPECT_NE(m.find("--in-layout"), std::string::npos) << m;
    }
    // Given the layout, it reads.
    lut::FormatOptions o;
    o.layout = lut::parseOptionalLayout("pilot");
    EXPECT_EQ(lut::formats::readLut(dir + "/odd.png", o).cube->at(3, 4, 5),
              glm::vec3(3 / 15.0f, 11 / 15.0f, 128 / 255.0f));
}
