// SPDX-License-Identifier: Apache-2.0
// The malformed nutexb corpus (tests/data/nutexb/bad_*.nutexb, one defect per file, built by
// make_corpus.py): each is refused with an error naming the file, the field, the value found and
// what was expected.
#include "lut/formats/Registry.h"
#include "nutexb/NutexbCodec.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <random>

namespace {

struct Case {
    const char* file;
    std::vector<std::string> expected; // substrings of the error
};

class NutexbMalformed : public ::testing::TestWithParam<Case> {};

TEST_P(NutexbMalformed, RefusedNamingFileFieldAndValues) {
    const Case& c = GetParam();
    const std::string path = lut::test::dataPath(std::string("nutexb/") + c.file);
    try {
        (void)lut::formats::readLut(path);
        FAIL() << c.file << " was accepted";
    } catch (const lut::LimitError& e) {
        FAIL() << "unexpected limit error: " << e.what();
    } catch (const lut::Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
        for (const auto& s : c.expected)
            EXPECT_NE(msg.find(s), std::string::npos) << "missing '" << s << "' in: " << msg;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, NutexbMalformed,
    ::testing::Values(
        Case{"bad_truncated_tiny.nutexb", {"file size", "truncated: 80 bytes", "at least 176"}},
        Case{"bad_truncated_data.nutexb", {"data size", "found 2048", "room for 1948"}},
        Case{"bad_magic_xnt.nutexb", {"magic at footer+0x00", "found 58 58 58 58", "20 58 4e 54"}},
        Case{"bad_magic_xet.nutexb", {"magic at footer+0x68", "found 00 58 45 54", "20 58 45 54"}},
        Case{"bad_format_bc7.nutexb", {"image format", "0x04e0 (BC7)", "expected 0x0400"}},
        Case{"bad_format_bgra.nutexb", {"image format", "0x0450 (B8G8R8A8_UNORM)"}},
        Case{"bad_width_huge.nutexb", {"width", "found 2147483648", "2..256"}},
        Case{"bad_height.nutexb", {"height", "found 8, expected 4"}},
        Case{"bad_depth1.nutexb", {"depth", "found 1, expected > 1"}},
        Case{"bad_width_zero.nutexb", {"width", "found 0, expected > 0"}},
        Case{"bad_layers.nutexb", {"layer count", "found 2, expected 1"}},
        Case{"bad_mips_zero.nutexb", {"mip count", "found 0"}},
        Case{"bad_tiling.nutexb", {"tiling", "found 0x0020", "0x1000"}},
        Case{"bad_type_2d.nutexb", {"texture type", "found 4, expected 8", "2D"}},
        Case{"bad_tiled_size.nutexb", {"data size", "found 256, expected 2048", "block-linear"}},
        Case{"bad_file_size.nutexb", {"file size", "found 2240 bytes, expected 2224"}},
        Case{"bad_data_past_table.nutexb", {"data size", "found 2048", "past the mip table"}}),
    [](const ::testing::TestParamInfo<Case>& info) {
        std::string n = info.param.file;
        n = n.substr(0, n.find('.'));
        return n;
    });

TEST(NutexbMalformedBytes, EveryTruncationOfAGoodFileIsRefused) {
    const std::string good = lut::formats::nutexb::writeBytes(lut::Lut3D::identity(4), "", true);
    for (std::size_t len = 0; len < good.size(); len += 37) {
        // Cut from the front (data lost) and from the back (footer lost).
        EXPECT_THROW(lut::formats::nutexb::readBytes(
                         std::string_view(good).substr(good.size() - len), "front"),
                     lut::Error);
        EXPECT_THROW(lut::formats::nutexb::readBytes(std::string_view(good).substr(0, len), "back"),
                     lut::Error);
    }
}

TEST(NutexbMalformedBytes, RandomFooterCorruptionReadsOrThrowsLutError) {
    // Any bytes: either a well-formed 2..256 LUT or lut::Error, never another exception or a crash.
    const std::string good = lut::formats::nutexb::writeBytes(lut::Lut3D::identity(4), "", true);
    std::mt19937 rng(12345);
    int accepted = 0;
    for (int iter = 0; iter < 3000; ++iter) {
        std::string b = good;
        const int flips = 1 + static_cast<int>(rng() % 4);
        for (int k = 0; k < flips; ++k) {
            const std::size_t at = b.size() - 0xB0 + rng() % 0xB0; // mip table and footer
            b[at] = static_cast<char>(rng() % 4 == 0 ? 0xFF : rng());
        }
        try {
            const lut::LutFile f = lut::formats::nutexb::readBytes(b, "mutant");
            ASSERT_TRUE(f.cube);
            ASSERT_GE(f.cube->size(), 2);
            ASSERT_LE(f.cube->size(), 256);
            ++accepted;
        } catch (const lut::Error&) {
        }
    }
    EXPECT_GT(accepted, 0); // corrupting the name or the mip table alone is harmless
}

} // namespace
