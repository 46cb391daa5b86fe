// SPDX-License-Identifier: Apache-2.0
#pragma once
// The LUT an edited file shows, whatever the file is: what `lutkit extract` and the editor's "LUT
// from Edited Screenshot" both call, so they read the same files the same way
// (docs/roundtrip.md):
//   - a screenshot with an embedded patch (lut::extractLut: the target the patch records unless
//     one is given);
//   - no patch, but a LUT image (an N^2 x N strip, a Hald image): a graded neutral (Smush-LUT's
//     neutral.png, lutkit neutral's), the edit itself unless its tag says otherwise, turned into
//     the target's purpose by lut::convertPurpose;
//   - no patch, named like Smush-LUT's first strips (".lut."): its top-left 256x16 pixels.
// The result says what its LUT is for, so the file written from it can say so (lut/LutPurpose.h).
#include "lut/LutFile.h"
#include "lut/LutPurpose.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/Extract.h"
#include "lut/smash/PurposeConversion.h"

#include <optional>
#include <string>

namespace lut::formats {

struct ExtractFileOptions {
    // The patch's extraction; its `target` is the output's purpose for every kind of file
    // (nullopt: what the patch records; a LUT image's own purpose).
    ExtractOptions extract;
    std::optional<LutLayout> inLayout;   // a graded LUT image: its layout (nullopt: detected)
    std::optional<LutPurpose> inPurpose; // a graded LUT image: what it is (nullopt: its tag, else
                                         // raw, the edit)
};

enum class ExtractSource { Patch, LutImage, SmushStrip };

struct ExtractFileResult {
    ExtractSource source = ExtractSource::Patch;
    Lut3D lut;
    LutPurpose purpose = LutPurpose::Raw; // what `lut` is for
    // Patch and Smush strip: the extraction with its report.
    std::optional<ExtractResult> extract;
    // LUT image: the file as read, what it was taken for, and the conversion to the target.
    std::optional<LutFile> image;
    PurposeDecision decision;
    std::optional<PurposeConversion> conversion;
};

// Throws lut::Error naming the file when it cannot be read, holds no patch and is no LUT image
// (the finder's reason), or the patch cannot be read.
ExtractFileResult extractLutFromFile(const std::string& path, const ExtractFileOptions& options);

} // namespace lut::formats
