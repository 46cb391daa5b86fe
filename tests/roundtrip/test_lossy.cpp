// SPDX-License-Identifier: Apache-2.0
// Lossy files: chroma subsampling is told from the file's metadata and from the patch's pixels,
// and extract says so.
#include "RoundtripTestUtil.h"
#include "SavedAs.h"

#include "lut/formats/ImageIO.h"
#include "lut/roundtrip/ChromaCheck.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lut;
using namespace lut::rt;

TEST(Lossy, ChromaSubsamplingIsToldFromTheMetadataAndThePixels) {
    const std::string dir = rtDir();
    struct Case {
        Storage storage;
        int scale;
        const char* metadata;
        const char* pixels;
    };
    const Case cases[] = {{Storage::Jpeg420, 8, "4:2:0", "4:2:0"},
                          {Storage::Jpeg420, 4, "4:2:0", "4:2:0"},
                          {Storage::Jpeg444, 8, "4:4:4", "4:4:4"},
                          {Storage::Png8, 8, "", "4:4:4"},
                          {Storage::Tiff16, 4, "", "4:4:4"}};
    for (const auto& c : cases) {
        Image shot = syntheticScreenshot(kShotWidth, kShotHeight, storageBits(c.storage));
        EmbedOptions eo;
        eo.scale = c.scale;
        eo.bitDepth = storageBits(c.storage);
        embedPatch(shot.view(), eo);
        applyEdit(shot, curvesEdit(), storageBits(c.storage));
        const std::string path = writeAs(shot, c.storage, dir, "shot" + std::to_string(c.scale));
        const formats::LoadedImage loaded = formats::readImage(path);
        EXPECT_EQ(loaded.info.chromaSubsampling, c.metadata) << storageName(c.storage);
        const FindResult f = findPatch(loaded.image.view());
        ASSERT_EQ(f.status, FindStatus::Found) << storageName(c.storage) << " " << f.message;
        const PatchReading patch = readPatch(loaded.image.view(), f.placement);
        const ChromaCheck& cc = patch.chroma;
        std::printf("[ measured ] %-12s scale %d: luma sharpness %.2f / %.2f, chroma %.2f / %.2f "
                    "(across columns / rows) -> %s\n",
                    storageName(c.storage), c.scale, cc.lumaSharpness[0], cc.lumaSharpness[1],
                    cc.chromaSharpness[0], cc.chromaSharpness[1], cc.scheme().c_str());
        ASSERT_TRUE(cc.measured);
        EXPECT_EQ(cc.scheme(), c.pixels) << storageName(c.storage) << " scale " << c.scale;
        // extract says so, and warns when the blocks are not on the JPEG grid
        ExtractOptions o;
        o.fileChromaSubsampling = loaded.info.chromaSubsampling;
        const ExtractResult r = extractLut(patch, o);
        const bool subsampled = std::string(c.pixels) != "4:4:4";
        EXPECT_EQ(r.has(RoundtripWarning::ChromaSubsampling), subsampled && c.scale < 8)
            << storageName(c.storage) << " scale " << c.scale;
        bool said = false;
        for (const auto& d : r.diagnostics)
            said = said || d.message.find("chroma subsampling: the file's metadata says 4:2:0; "
                                          "the patch's pixels show 4:2:0") != std::string::npos;
        EXPECT_EQ(said, subsampled) << storageName(c.storage) << " scale " << c.scale;
    }
}
