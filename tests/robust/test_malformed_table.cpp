// SPDX-License-Identifier: Apache-2.0
// The malformed-input table: one defect per row, across every reader, each with the exact
// message the user sees (what() of the error, with the test folder stripped from paths). A
// message that changes must change here too, on purpose: these texts are the user interface.
// Run with LUTKIT_PRINT_MESSAGES=1 to print the actual messages.
#include "RobustSupport.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <set>

using namespace lut::robust;

namespace {

struct Defect {
    const char* name;                   // the file name (its extension picks the reader)
    std::function<std::string()> bytes; // file contents; empty function = made by `make`
    const char* expected;               // exact what() with the folder stripped
    const char* layout = "";
    std::function<void(const std::string& path)> make = {};
};

std::function<std::string()> text(const char* t) {
    return [t] { return std::string(t); };
}

// 2^3 RGBA8 block-linear data is 1024 bytes (padding included).
std::function<std::string()> nut(std::function<void(NutexbFields&)> edit,
                                 std::size_t dataBytes = 1024) {
    return [=] {
        NutexbFields f;
        edit(f);
        return nutexbFile(f, dataBytes);
    };
}

std::function<void(const std::string&)> image(int w, int h, int channels = 3,
                                              OIIO::TypeDesc type = OIIO::TypeDesc::UINT8) {
    return [=](const std::string& path) {
        auto out = OIIO::ImageOutput::create(path);
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(w, h, channels, type);
        std::vector<float> px(static_cast<std::size_t>(w) * h * channels, 0.5f);
        ASSERT_TRUE(out->open(path, spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        out->close();
    };
}

const std::string k8Rows = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n";

// ASCII text as UTF-16 (big- or little-endian) after the given byte order mark.
std::string utf16(const std::string& ascii, const std::string& bom, bool bigEndian) {
    std::string s = bom;
    for (char c : ascii) {
        s += bigEndian ? '\0' : c;
        s += bigEndian ? c : '\0';
    }
    return s;
}

const std::vector<Defect>& table() {
    static const std::vector<Defect> t = {
        // ---- .cube
        {"empty.cube", text(""),
         "empty.cube:1:1: the file is empty: expected a .cube header with LUT_3D_SIZE or "
         "LUT_1D_SIZE"},
        {"comments-only.cube", text("# nothing\n\n# here\n"),
         "comments-only.cube:4:1: expected LUT_3D_SIZE or LUT_1D_SIZE, found the end of the file"},
        {"size-1.cube", text("LUT_3D_SIZE 1\n0 0 0\n"),
         "size-1.cube:1:13: LUT_3D_SIZE 1 is below the minimum of 2 (found '1')"},
        {"size-257.cube", text("LUT_3D_SIZE 257\n"),
         "size-257.cube:1:13: LUT_3D_SIZE 257 is over the limit of 256 (lut::limits::kMax3DSize) "
         "(found '257')"},
        {"size-100000.cube", text("TITLE \"x\"\nLUT_3D_SIZE 100000\n"),
         "size-100000.cube:2:13: LUT_3D_SIZE 100000 is over the limit of 256 "
         "(lut::limits::kMax3DSize) (found '100000')"},
        {"size-word.cube", text("LUT_3D_SIZE big\n"),
         "size-word.cube:1:13: expected an integer size after LUT_3D_SIZE (found 'big')"},
        {"size-fraction.cube", text("LUT_3D_SIZE 2.5\n"),
         "size-fraction.cube:1:13: expected an integer size after LUT_3D_SIZE (found '2.5')"},
        {"size-missing.cube", text("LUT_3D_SIZE\n"),
         "size-missing.cube:1:13: expected a size after LUT_3D_SIZE (found 'LUT_3D_SIZE')"},
        {"size-1d-1.cube", text("LUT_1D_SIZE 1\n0 0 0\n"),
         "size-1d-1.cube:1:13: LUT_1D_SIZE 1 is below the minimum of 2 (found '1')"},
        {"size-1d-65537.cube", text("LUT_1D_SIZE 65537\n"),
         "size-1d-65537.cube:1:13: LUT_1D_SIZE 65537 is over the limit of 65536 "
         "(lut::limits::kMax1DSize) (found '65537')"},
        {"size-twice.cube", [] { return "LUT_3D_SIZE 2\nLUT_3D_SIZE 3\n" + k8Rows; },
         "size-twice.cube:2:1: LUT_3D_SIZE given twice with different values (first on line 1) "
         "(found 'LUT_3D_SIZE 3')"},
        {"no-size.cube", [] { return "TITLE \"t\"\n" + k8Rows; },
         "no-size.cube:2:1: expected LUT_3D_SIZE or LUT_1D_SIZE before the first data line (found "
         "'0 0 0')"},
        {"title-unclosed.cube", [] { return "TITLE \"open\nLUT_3D_SIZE 2\n" + k8Rows; },
         "title-unclosed.cube:1:12: TITLE has no closing quote (found '\"open')"},
        {"title-empty.cube", [] { return "TITLE\nLUT_3D_SIZE 2\n" + k8Rows; },
         "title-empty.cube:1:7: expected a quoted title after TITLE"},
        {"domain-two.cube", [] { return "LUT_3D_SIZE 2\nDOMAIN_MIN 0 0\n" + k8Rows; },
         "domain-two.cube:2:16: expected 3 numbers after DOMAIN_MIN, found 2 (found 'DOMAIN_MIN 0 "
         "0')"},
        {"domain-reversed.cube",
         [] { return "LUT_3D_SIZE 2\nDOMAIN_MIN 1 0 0\nDOMAIN_MAX 0 1 1\n" + k8Rows; },
         "domain-reversed.cube:3:12: DOMAIN_MIN must be below DOMAIN_MAX for every channel: red "
         "has min 1 and max 0 (found '0')"},
        {"domain-nan.cube", [] { return "LUT_3D_SIZE 2\nDOMAIN_MAX 1 nan 1\n" + k8Rows; },
         "domain-nan.cube:2:14: DOMAIN_MAX values must be finite numbers (NaN and infinity are not "
         "allowed) (found 'nan')"},
        {"domain-word.cube", [] { return "LUT_3D_SIZE 2\nDOMAIN_MAX 1 one 1\n" + k8Rows; },
         "domain-word.cube:2:14: expected 3 numbers after DOMAIN_MAX (found 'one')"},
        {"range-reversed.cube", [] { return "LUT_3D_SIZE 2\nLUT_3D_INPUT_RANGE 1 0\n" + k8Rows; },
         "range-reversed.cube:2:22: LUT_3D_INPUT_RANGE min must be below max (found '1 0')"},
        {"row-two-values.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"),
         "row-two-values.cube:3:5: expected 3 numbers on a data line, found 2 (found '1 0')"},
        {"row-four-values.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 0 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"),
         "row-four-values.cube:3:7: expected 3 numbers on a data line, found 4 (found '1 0 0 0')"},
        {"row-word.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 x 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"),
         "row-word.cube:3:3: expected a number (found 'x')"},
        {"row-nan.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 nan 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"),
         "row-nan.cube:4:3: NaN and infinity are not allowed in .cube data; expected a finite "
         "number (found 'nan')"},
        {"row-inf.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 -inf\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"),
         "row-inf.cube:5:5: NaN and infinity are not allowed in .cube data; expected a finite "
         "number (found '-inf')"},
        {"row-1e39.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n1e39 0 1\n1 0 1\n0 1 1\n1 1 1\n"),
         "row-1e39.cube:6:1: number is out of the 32-bit float range (found '1e39')"},
        {"too-few-rows.cube",
         text("LUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n"),
         "too-few-rows.cube:9:1: expected 8 data rows for LUT_3D_SIZE 2, found 7 before the end of "
         "the file"},
        {"too-many-rows.cube", [] { return "LUT_3D_SIZE 2\n" + k8Rows + "0.5 0.5 0.5\n"; },
         "too-many-rows.cube:10:1: too many data rows: expected 8 data rows for LUT_3D_SIZE 2, "
         "this is row 9 (found '0.5 0.5 0.5')"},
        {"keyword-after-data.cube",
         [] { return "LUT_3D_SIZE 2\n0 0 0\nTITLE \"late\"\n" + k8Rows.substr(6); },
         "keyword-after-data.cube:3:1: TITLE must come before the first data line (line 2) (found "
         "'TITLE')"},
        // Line numbers are physical: blank lines, comments and CR LF count like any line.
        {"line-count-after-blanks.cube",
         text("# c\n\nLUT_3D_SIZE 2\n\n# rows\n0 0 0\n1 0 0\n\n0 1 0\n1 1 zero\n0 0 1\n1 0 1\n0 1 "
              "1\n1 1 1\n"),
         "line-count-after-blanks.cube:10:5: expected a number (found 'zero')"},
        {"line-count-crlf.cube",
         text("LUT_3D_SIZE 2\r\n\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n1 1 0\r\n0 0 1\r\n1 0 1\r\n0 1 "
              "1\r\n1 1 1 1\r\n"),
         "line-count-crlf.cube:10:7: expected 3 numbers on a data line, found 4 (found '1 1 1 1')"},
        {"line-too-long.cube",
         [] { return "LUT_3D_SIZE 2\n# " + std::string(70000, 'x') + "\n" + k8Rows; },
         "line-too-long.cube:2:65537: line is longer than the limit of 65536 bytes "
         "(lut::limits::kMaxTextLineBytes) (found '# "
         "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...')"},
        // A .cube saved as UTF-16 (Windows Notepad's "Unicode"), with or without a byte order
        // mark, or as UTF-32: named for what it is.
        {"utf16le-bom.cube", [] { return utf16("LUT_3D_SIZE 2\n" + k8Rows, "\xFF\xFE", false); },
         "utf16le-bom.cube: the file is UTF-16 text; save it as UTF-8 or ASCII"},
        {"utf16be-bom.cube", [] { return utf16("LUT_3D_SIZE 2\n" + k8Rows, "\xFE\xFF", true); },
         "utf16be-bom.cube: the file is UTF-16 text; save it as UTF-8 or ASCII"},
        {"utf16le-no-bom.cube", [] { return utf16("LUT_3D_SIZE 2\n" + k8Rows, "", false); },
         "utf16le-no-bom.cube: the file is UTF-16 text; save it as UTF-8 or ASCII"},
        {"utf32le-bom.cube",
         [] { return std::string("\xFF\xFE\0\0", 4) + utf16("LUT_3D_SIZE 2\n", "", false); },
         "utf32le-bom.cube: the file is UTF-32 text; save it as UTF-8 or ASCII"},
        // ---- nutexb (2^3 volumes crafted from nutexb.md)
        {"truncated.nutexb", [] { return std::string(100, '\0'); },
         "truncated.nutexb: nutexb file size: truncated: 100 bytes, expected at least 176 "
         "(0x40-byte mip table + 0x70-byte footer)"},
        {"magic-xnt.nutexb", nut([](NutexbFields& f) { f.magic1 = "XNT "; }),
         "magic-xnt.nutexb: nutexb magic at footer+0x00: found 58 4e 54 20, expected 20 58 4e 54 "
         "(\" XNT\"); not a nutexb file or truncated"},
        {"magic-xet.nutexb", nut([](NutexbFields& f) { f.magic2 = "TEX "; }),
         "magic-xet.nutexb: nutexb magic at footer+0x68: found 54 45 58 20, expected 20 58 45 54 "
         "(\" XET\")"},
        {"width-0.nutexb", nut([](NutexbFields& f) { f.width = 0; }),
         "width-0.nutexb: nutexb width: found 0, expected > 0"},
        {"depth-1.nutexb", nut([](NutexbFields& f) { f.depth = 1; }),
         "depth-1.nutexb: nutexb depth: found 1, expected > 1 (a 2D texture, not a 3D LUT volume)"},
        {"height-differs.nutexb", nut([](NutexbFields& f) { f.height = 4; }),
         "height-differs.nutexb: nutexb height: found 4, expected 2 (equal to width for a LUT)"},
        // A corrupted width is the width's fault, not the height's: the field that disagrees
        // with the two others is named.
        {"width-differs.nutexb", nut([](NutexbFields& f) { f.width = 3; }),
         "width-differs.nutexb: nutexb width: found 3, expected 2 (equal to height and depth for a "
         "LUT)"},
        {"width-2p31.nutexb",
         nut([](NutexbFields& f) { f.width = f.height = f.depth = 0x80000000u; }),
         "width-2p31.nutexb: nutexb width: found 2147483648, expected a LUT size 2..256"},
        {"width-257.nutexb", nut([](NutexbFields& f) { f.width = f.height = f.depth = 257; }),
         "width-257.nutexb: nutexb width: found 257, expected a LUT size 2..256"},
        {"type-2d.nutexb", nut([](NutexbFields& f) { f.type = 4; }),
         "type-2d.nutexb: nutexb texture type: found 4, expected 8 (3D); 4 is 2D"},
        {"layers-6.nutexb", nut([](NutexbFields& f) { f.layers = 6; }),
         "layers-6.nutexb: nutexb layer count: found 6, expected 1"},
        {"mips-0.nutexb", nut([](NutexbFields& f) { f.mips = 0; }),
         "mips-0.nutexb: nutexb mip count: found 0, expected 1..16 (1 for a LUT)"},
        {"format-bc7.nutexb", nut([](NutexbFields& f) { f.format = 0x04e0; }),
         "format-bc7.nutexb: nutexb image format: found 0x04e0 (BC7), expected 0x0400 "
         "(R8G8B8A8_UNORM) or 0x0405 (R8G8B8A8_SRGB)"},
        {"format-unknown.nutexb", nut([](NutexbFields& f) { f.format = 0x1234; }),
         "format-unknown.nutexb: nutexb image format: found 0x1234 (unknown), expected 0x0400 "
         "(R8G8B8A8_UNORM) or 0x0405 (R8G8B8A8_SRGB)"},
        {"tiling-odd.nutexb", nut([](NutexbFields& f) { f.tiling = 0x0500; }),
         "tiling-odd.nutexb: nutexb tiling: found 0x0500, expected 0x1000 (block-linear) or 0x0000 "
         "(linear)"},
        {"data-size-wrong.nutexb", nut([](NutexbFields& f) { f.dataSize = 32; }),
         "data-size-wrong.nutexb: nutexb data size: found 32, expected 1024 (block-linear tiled "
         "2x2x2 RGBA8)"},
        {"data-past-table.nutexb", nut([](NutexbFields& f) {}, 512),
         "data-past-table.nutexb: nutexb data size: found 1024, past the mip table: the file has "
         "room for 512 bytes of data (file truncated?)"},
        {"extra-bytes.nutexb", nut([](NutexbFields& f) {}, 1024 + 16),
         "extra-bytes.nutexb: nutexb file size: found 1216 bytes, expected 1200 (data size 1024 + "
         "0x40 mip table + 0x70 footer)"},
        // ---- LUT images (strip layouts and Hald)
        {"not-an-image.png", text("this is not a PNG file\n"),
         "not-an-image.png: cannot read image: Not a PNG file"},
        {"fits-nothing.png",
         {},
         "fits-nothing.png: image is 100x11, not a LUT image size: unreal, unity and smush need "
         "N^2 x N (e.g. 256x16), hald needs L^3 x L^3 (e.g. 64x64)",
         "",
         image(100, 11)},
        {"pilot-wrong-size.png",
         {},
         "pilot-wrong-size.png: image is 64x64, the unreal layout needs N^2 x N pixels with N "
         "2..256 (e.g. 256x16, 1024x32); this size fits hald",
         "pilot",
         image(64, 64)},
        {"hald-wrong-size.png",
         {},
         "hald-wrong-size.png: image is 256x16, the hald layout needs L^3 x L^3 pixels (e.g. 64x64 "
         "for 16^3, 512x512 for 64^3); this size fits unreal, unity, smush",
         "hald",
         image(256, 16)},
        {"huge-header.png",
         {},
         "huge-header.png: image is 65536x65536 with 4 channels, over the limit of 268435456 "
         "pixels and 64 channels",
         "",
         [](const std::string& path) {
             // A PNG header claiming 65536 x 65536 pixels and no data: refused before allocation
             // (libpng stops reading the header at the first IDAT: its contents never matter).
             writeBytes(path, craftedPng(65536, 65536, 6, "\x78\x01"));
         }},
        {"truncated.png",
         {},
         "truncated.png: cannot read PNG: the file ends early (truncated)",
         "pilot",
         [](const std::string& path) {
             image(256, 16)(path);
             std::string b = fileBytes(path);
             writeBytes(path, b.substr(0, b.size() / 2));
         }},
        // ---- formats read through OpenColorIO
        // OpenColorIO's own words, short: the format's reason without its FileTransform wrapper
        // ("The specified transform file '...' could not be loaded. All formats have been tried
        // ..."), the path named once, first (issue 41: messages of 482 characters).
        {"garbage.3dl", text("this is not a 3dl file\n"),
         "garbage.3dl: OpenColorIO cannot read it: flame: Error parsing .3dl file. Does not "
         "appear to contain a valid shaper LUT or a 3D LUT."},
        {"bad-header.spi3d", text("SPILUT 1.0\n3 3\n2 2\n0 0 0 0 0 0\n"),
         // lutkit's own reader: the place, as in the editions without OpenColorIO.
         "bad-header.spi3d:3:4: expected the lattice size (an integer)"},
        {"garbage.csp", text("CSPLUTV100\n3D\nnonsense\n"),
         "garbage.csp: OpenColorIO cannot read it: cinespace: Prelut does not specify valid "
         "dimension size on channel '0: 'nonsense'"},
        // A line number where OpenColorIO gives one: PATH:LINE.
        {"bad-row.spi1d", text("Version 1\nFrom 0 1\nLength 2\nComponents 3\n{\n0 0 0\nzz\n}\n"),
         "bad-row.spi1d:7: OpenColorIO cannot read it: spi1d: Malformed LUT line (zz)"},
        // A reader inside OCIO that believes a size in the file fails with a bare C++ library
        // message (std::length_error: "vector::reserve"); it is explained.
        {"huge-size.itx", text("LUT_3D_SIZE 100000\n0 0 0\n"),
         "huge-size.itx: OpenColorIO cannot read it: iridas_itx: a size declared in the file is "
         "too large to allocate (vector::reserve)"},
        {"empty.clf", text(""),
         "empty.clf: OpenColorIO cannot read it: Academy/ASC Common LUT Format: Parsing error: "
         "the file is not a CTF/CLF file."},
    };
    return t;
}

class Malformed : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Malformed, IsRefusedWithTheExactMessage) {
    const Defect& d = table()[GetParam()];
    const std::string dir = lut::test::tempDir();
    const std::string path = dir + "/" + d.name;
    if (d.make)
        d.make(path);
    else
        writeBytes(path, d.bytes());
    lut::FormatOptions options;
    options.layout = lut::parseOptionalLayout(d.layout);
    std::string message;
    try {
        (void)lut::formats::readLut(path, options);
        FAIL() << d.name << " was accepted";
    } catch (const lut::Error& e) {
        message = stripDir(e.what(), dir);
    }
    if (std::getenv("LUTKIT_PRINT_MESSAGES"))
        std::cout << "MSG " << d.name << " => " << message << "\n";
    EXPECT_EQ(message, d.expected);
}

INSTANTIATE_TEST_SUITE_P(Table, Malformed, ::testing::Range<std::size_t>(0, table().size()),
                         [](const auto& info) {
                             std::string n = table()[info.param].name;
                             for (auto& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return n;
                         });

TEST(MalformedTable, HasAtLeastFortyDistinctDefects) {
    std::set<std::string> names, messages;
    for (const auto& d : table()) {
        names.insert(d.name);
        messages.insert(d.expected);
    }
    EXPECT_EQ(names.size(), table().size());
    EXPECT_GE(messages.size(), 40u);
}

} // namespace
