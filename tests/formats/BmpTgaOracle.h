// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the BMP and TGA reader tests share (test_bmp_read.cpp, test_tga_read.cpp): files made by
// ImageMagick at test time (or by the test from them, byte by byte, where ImageMagick writes no
// such variant), read by lutkit's native reader and by OpenImageIO 2.4, the reader lutkit used
// before: its samples as `oiiotool --iconfig oiio:UnassociatedAlpha 1 --dumpdata` prints them
// (lutkit reads with that setting: no premultiplication), its ImageInfo and attributes through
// lutkit's OpenImageIO module (openOiioSource). Where the native reader differs on purpose, the
// case says how (each difference is in the reader's summary comment).
#include "TestSupport.h"

#include "imageio/ImageCodec.h"
#include "lut/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace lut::test::bmptga {

using Bytes = std::string;

inline std::uint32_t get16(const Bytes& b, std::size_t at) {
    return static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8;
}
inline std::uint32_t get32(const Bytes& b, std::size_t at) {
    return get16(b, at) | get16(b, at + 2) << 16;
}
inline void put16(Bytes& b, std::size_t at, std::uint32_t v) {
    b[at] = static_cast<char>(v & 0xff);
    b[at + 1] = static_cast<char>((v >> 8) & 0xff);
}
inline void put32(Bytes& b, std::size_t at, std::uint32_t v) {
    put16(b, at, v & 0xffff);
    put16(b, at + 2, v >> 16);
}
inline void writeBytes(const std::string& path, const Bytes& b) {
    std::ofstream(path, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
}

// ImageMagick: `convert ARGS OUT`; the file's bytes.
inline Bytes magick(const std::string& args, const std::string& out) {
    const RunResult r = runCommand("convert " + args + " " + shellQuoted(out));
    EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
    const std::size_t colon = out.find(':');
    return fileBytes(colon == std::string::npos ? out : out.substr(colon + 1));
}

// The pictures every case starts from: 37x23 (odd: rows padded; narrow: the RLE readers' marks
// every few rows), a plasma of many colours, and the same with an alpha ramp from 255 to 0.
struct Sources {
    std::string rgb, rgba;
};
inline Sources makeSources(const std::string& dir) {
    Sources s{dir + "/src.png", dir + "/src-alpha.png"};
    magick("-seed 3 -size 37x23 plasma:fractal -depth 8", s.rgb);
    magick(shellQuoted(s.rgb) + " \\( -size 37x23 gradient:white-black \\) -alpha off -compose "
                                "CopyOpacity -composite",
           s.rgba);
    return s;
}

struct Pixels {
    int width = 0, height = 0, channels = 0;
    std::vector<int> samples; // row-major, interleaved
};

// OpenImageIO's samples of every file (`oiiotool --dumpdata --iconfig oiio:UnassociatedAlpha 1
// EXTRA PATH ...`: one run for them all, oiiotool takes ~0.4 s to start), by path.
inline std::map<std::string, Pixels> oiioPixels(const std::vector<std::string>& paths,
                                                const std::string& extra = {}) {
    std::string cmd = "oiiotool --dumpdata";
    for (const std::string& p : paths) // a setting holds for the next input only
        cmd += " --iconfig oiio:UnassociatedAlpha 1 " + extra + " " + shellQuoted(p);
    const RunResult r = runCommand(cmd);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::map<std::string, Pixels> out;
    Pixels* p = nullptr;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
        const std::size_t colon = line.find(" : ");
        if (!line.empty() && line[0] != ' ' && colon != std::string::npos) {
            std::string name = line.substr(0, colon);
            while (!name.empty() && name.back() == ' ')
                name.pop_back();
            p = &out[name];
            std::sscanf(line.c_str() + colon + 3, "%d x %d, %d channel", &p->width, &p->height,
                        &p->channels);
            p->samples.assign(static_cast<std::size_t>(p->width) * p->height * p->channels, -1);
            continue;
        }
        int x = 0, y = 0, n = 0;
        if (!p || std::sscanf(line.c_str(), " Pixel (%d, %d):%n", &x, &y, &n) != 2 || x < 0 ||
            y < 0 || x >= p->width || y >= p->height)
            continue;
        std::istringstream codes(line.substr(static_cast<std::size_t>(n)));
        int c = 0;
        for (int v = 0; c < p->channels && codes >> v; ++c)
            p->samples[(static_cast<std::size_t>(y) * p->width + x) * p->channels + c] = v;
    }
    return out;
}

// lutkit's read through openImageSource (or openImageMemory: memory = true), in chunks of
// `rows` rows (0: one chunk).
inline Pixels lutkitPixels(const std::string& path, int rows, bool memory = false) {
    auto src =
        memory ? formats::openImageMemory(path, fileBytes(path)) : formats::openImageSource(path);
    const formats::ImageInfo& info = src->info();
    Pixels p{info.width, info.height, info.channels, {}};
    const std::size_t rb = formats::rowBytes(info);
    std::vector<unsigned char> buf(rb * static_cast<std::size_t>(info.height));
    const int step = rows > 0 ? rows : info.height;
    for (int y = 0; y < info.height; y += step)
        src->readRows(y, std::min(info.height, y + step), buf.data() + rb * y);
    src->finish();
    p.samples.assign(buf.begin(), buf.end());
    return p;
}

// OpenImageIO's attributes as the module serialises them (OiioImage.cpp's serialize()), by name:
// "type value" (int, uint, float, string).
inline std::map<std::string, std::string> attributes(const std::string& s) {
    std::map<std::string, std::string> out;
    std::size_t at = 0;
    auto word = [&]() {
        std::uint32_t v = 0;
        if (at + 4 <= s.size())
            std::memcpy(&v, s.data() + at, 4);
        at += 4;
        return v;
    };
    auto bytes = [&]() {
        const std::uint32_t n = word();
        std::string v = at + n <= s.size() ? s.substr(at, n) : std::string();
        at += n;
        return v;
    };
    while (at < s.size()) {
        const std::string name = bytes();
        const std::uint32_t base = word(), aggregate = word();
        word(); // vector semantics
        const std::uint32_t arraylen = word(), n = word();
        std::ostringstream v;
        v << base << "/" << aggregate << "/" << arraylen << "/" << n << ":";
        if (base == 13) { // STRING
            for (std::uint32_t i = 0; i < n * std::max<std::uint32_t>(1, arraylen); ++i)
                v << " [" << bytes() << "]";
        } else {
            const std::string data = bytes();
            for (std::size_t i = 0; i + 4 <= data.size(); i += 4) {
                std::uint32_t w = 0;
                std::memcpy(&w, data.data() + i, 4);
                float f = 0;
                std::memcpy(&f, &w, 4);
                if (base == 11)
                    v << " " << f;
                else if (base == 7)
                    v << " " << static_cast<std::int32_t>(w);
                else
                    v << " " << w;
            }
        }
        out[name] = v.str();
    }
    return out;
}

// One file checked against OpenImageIO.
struct Case {
    Case(std::string file, std::string twin = {})
        : path(std::move(file)), oracle(std::move(twin)) {}
    std::string path;   // the file lutkit reads
    std::string oracle; // the file OpenImageIO reads ("" = path): a twin it accepts
    std::string extra;  // more oiiotool options for the samples
    // Where lutkit differs on purpose (the reader's summary comment):
    bool greyFromRed = false; // OIIO's samples read as RGB (monochrome_detect 0): lutkit's Y = R
    bool opaque = false;      // OIIO's alpha 0 everywhere: lutkit's 255
    int bitsPerSample = 0;    // lutkit's, where OIIO's differs (and its oiio:BitsPerSample)
    std::vector<std::string> names; // lutkit's channel names where OIIO's differ
    int alphaChannel = -2;          // lutkit's alpha channel where OIIO's differs
};

inline void checkCase(const Case& c, Pixels want) {
    SCOPED_TRACE(c.path);
    const std::string oracle = c.oracle.empty() ? c.path : c.oracle;
    ASSERT_GT(want.width, 0) << "OpenImageIO read no " << oracle;
    if (c.greyFromRed) {
        std::vector<int> y;
        for (std::size_t i = 0; i < want.samples.size(); i += 3)
            y.push_back(want.samples[i]);
        want.samples = y;
        want.channels = 1;
    }
    if (c.opaque)
        for (std::size_t i = static_cast<std::size_t>(want.channels) - 1; i < want.samples.size();
             i += static_cast<std::size_t>(want.channels)) {
            EXPECT_EQ(want.samples[i], 0) << "OpenImageIO's alpha is not 0 everywhere";
            want.samples[i] = 255;
        }
    for (const auto& [rows, memory] :
         {std::pair{0, false}, std::pair{1, false}, std::pair{7, false}, std::pair{5, true}}) {
        SCOPED_TRACE("chunks of " + std::to_string(rows) + " rows" + (memory ? ", memory" : ""));
        Pixels got;
        ASSERT_NO_THROW(got = lutkitPixels(c.path, rows, memory));
        ASSERT_EQ(got.width, want.width);
        ASSERT_EQ(got.height, want.height);
        ASSERT_EQ(got.channels, want.channels);
        std::size_t wrong = 0, first = 0;
        for (std::size_t i = 0; i < want.samples.size(); ++i)
            if (got.samples[i] != want.samples[i] && wrong++ == 0)
                first = i;
        EXPECT_EQ(wrong, 0u) << "first at sample " << first << " (pixel " << first / want.channels
                             << "): " << got.samples[first] << " vs OpenImageIO's "
                             << want.samples[first];
    }
    // What the file is: lutkit's description against OpenImageIO's, through the module.
    auto ours = formats::openImageSource(c.path);
    auto theirs = formats::openOiioSource(oracle, "", "");
    formats::ImageInfo a = ours->info(), b = theirs->info();
    if (c.bitsPerSample > 0)
        b.bitsPerSample = c.bitsPerSample;
    if (!c.names.empty())
        b.channelNames = c.names;
    if (c.alphaChannel > -2)
        b.alphaChannel = c.alphaChannel;
    EXPECT_EQ(a.format, b.format);
    EXPECT_EQ(a.channels, b.channels);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.bitDepth, b.bitDepth);
    EXPECT_EQ(a.bitsPerSample, b.bitsPerSample);
    EXPECT_EQ(a.compression, b.compression);
    EXPECT_EQ(a.channelNames, b.channelNames);
    EXPECT_EQ(a.alphaChannel, b.alphaChannel);
    EXPECT_EQ(a.colorSpace, b.colorSpace);
    EXPECT_EQ(a.subimages, b.subimages);
    EXPECT_EQ(ours->metadata()->format, theirs->metadata()->format);
    EXPECT_EQ(ours->metadata()->text, theirs->metadata()->text);
    auto attrsTheirs = attributes(theirs->metadata()->oiioAttributes);
    const auto attrsOurs = attributes(ours->metadata()->oiioAttributes);
    if (c.bitsPerSample > 0)
        attrsTheirs["oiio:BitsPerSample"] =
            attrsOurs.count("oiio:BitsPerSample") ? attrsOurs.at("oiio:BitsPerSample") : "";
    EXPECT_EQ(attrsOurs, attrsTheirs);
}

// Every case, OpenImageIO's samples read in one oiiotool run per setting.
inline void checkCases(const std::vector<Case>& cases) {
    std::map<std::string, std::vector<std::string>> byExtra;
    for (const Case& c : cases)
        byExtra[c.extra].push_back(c.oracle.empty() ? c.path : c.oracle);
    std::map<std::string, std::map<std::string, Pixels>> read;
    for (const auto& [extra, paths] : byExtra)
        read[extra] = oiioPixels(paths, extra);
    for (const Case& c : cases)
        checkCase(c, read[c.extra][c.oracle.empty() ? c.path : c.oracle]);
}

// The error lutkit's reader gives for a file: one line that names it (empty: none).
inline std::string refusal(const std::string& path) {
    try {
        auto src = formats::openImageSource(path);
        const formats::ImageInfo& info = src->info();
        std::vector<unsigned char> buf(formats::rowBytes(info) *
                                       static_cast<std::size_t>(info.height));
        src->readRows(0, info.height, buf.data());
        src->finish();
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
        return what;
    }
    return {};
}

// The fixture of both readers' tests: the sources in the test's folder, files made from them by
// ImageMagick or derived byte by byte, each under its own name (the cases are checked together,
// at the end), and what a broken file must get.
class ReaderTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = tempDir();
        src = makeSources(dir);
    }
    // ImageMagick's file NAME written as PREFIX ("BMP3:", "TGA:") with ARGS.
    std::string madeAs(const std::string& prefix, const std::string& name, const std::string& args,
                       bool alpha) {
        const std::string path = unique(name);
        magick(shellQuoted(alpha ? src.rgba : src.rgb) + " " + args, prefix + path);
        return path;
    }
    std::string derived(const std::string& name, const Bytes& b) {
        const std::string path = unique(name);
        writeBytes(path, b);
        return path;
    }
    bool oiioRefuses(const std::string& path) {
        return runCommand("oiiotool " + shellQuoted(path) + " -o " +
                          shellQuoted(dir + "/oiio-read.exr"))
                   .exitCode != 0;
    }
    // The file b, written as NAME, is refused in one line naming it that says SAYS (and by
    // OpenImageIO too when oiioToo); its path.
    std::string refused(const std::string& name, const Bytes& b, const std::string& says,
                        bool oiioToo) {
        SCOPED_TRACE(name);
        const std::string path = derived(name, b);
        const std::string why = refusal(path);
        EXPECT_NE(why.find(says), std::string::npos) << why;
        if (oiioToo) {
            EXPECT_TRUE(oiioRefuses(path));
        }
        return path;
    }
    // The command line on a broken file: exit 1, one line.
    void expectCliRefuses(const std::string& path) {
        const RunResult r = runCli("apply --lut builtin:neutral " + shellQuoted(path) + " -o " +
                                   shellQuoted(dir + "/out.png"));
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    std::string unique(const std::string& name) {
        return dir + "/" + std::to_string(++m_files) + "-" + name;
    }
    std::string dir;
    Sources src;
    int m_files = 0;
};

} // namespace lut::test::bmptga
