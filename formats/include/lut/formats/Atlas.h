// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUT atlases as files (lutkit atlas build / split / info): several LUTs as the rows of one 8-bit
// picture in a strip layout (lut/io/Atlas.h), ReShade's MultiLUT.fx atlas by default, and back.
// Every row is the LUT resampled to the atlas's N with the error said, stored in 8 bits with the
// error said; two rows that store the same LUT are refused, naming both.
#include "lut/Error.h"
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Atlas.h"
#include "lut/io/FormatOptions.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lut::formats {

struct AtlasBuildOptions {
    LutLayout layout = LutLayout::Reshade; // the rows' layout
    // N of every row; 0 = the layout's own (32 for reshade and unity-32), else the first LUT's:
    // then a LUT of another size is refused (resampling happens only when the size is asked for).
    int size = 0;
    bool neutralFirst = false; // row 0 the neutral LUT (MultiLUT's "Neutral" entry)
    Interpolation interp = Interpolation::Tetrahedral; // resampling
    FormatOptions read;                                // reading the inputs (--in-layout)
};

struct AtlasRowReport {
    std::string source;                 // the file; "" for the neutral row
    int sourceSize = 0;                 // as read (after a shaper or domain was baked in)
    std::optional<ErrorStats> resample; // when resampled to the atlas's N
    ErrorStats storage;                 // 8-bit storage (rounding to nearest), clamped included
    std::size_t clamped = 0;            // channel values outside 0..1
    bool neutral = false;               // stores the neutral LUT exactly
    Diagnostics diagnostics;            // reading the file, baking a shaper or domain
};

struct AtlasBuildReport {
    AtlasShape shape;
    std::vector<AtlasRowReport> rows;
};

// Reads every input, makes each an N^3 row, refuses two rows that store the same 8-bit values
// (naming both rows and files) and writes the atlas picture to `output` (8-bit RGBA; through
// lut::formats::writeImage: atomic, verified; the caller applies the overwrite rule first).
// Throws lut::Error naming the row and file for a LUT of another size, an unreadable input, an
// output that is one of the inputs.
AtlasBuildReport buildAtlas(const std::vector<std::string>& inputs, const std::string& output,
                            const AtlasBuildOptions& options);

// One LUT of an atlas given in memory, and what stands for it in messages and the report (the
// editor: "the export" for its LUT, the atlas's file for the rows it already holds).
struct AtlasInput {
    LutFile lut;
    std::string name;
};

// The same from LUTs in memory: no file is read, nothing is refused as an input it overwrites.
AtlasBuildReport buildAtlas(const std::vector<AtlasInput>& luts, const std::string& output,
                            const AtlasBuildOptions& options);

struct AtlasReading {
    AtlasShape shape;
    int width = 0, height = 0;
    std::vector<bool> neutral; // the row is a neutral LUT (within half an 8-bit step)
    // (later row, earlier row) pairs that store the same values: each repeat with the first
    // row that held them (a row repeated 8192 times is 8191 pairs, not 33 million)
    std::vector<std::pair<int, int>> duplicates;
    std::string layoutReason; // how the layout was chosen ("given", or what detection saw)
    Diagnostics diagnostics;
};

// Reads an atlas picture: its rows in `layout`, else the strip layout in which most rows have
// each output channel following its own input (the rule of lut::formats' strip reader, row by
// row; a tie or no such row reads the default, reshade for 32^3 rows and unreal for others, with
// a warning). Throws lut::Error naming the file for a picture that is no atlas (width not N^2,
// height not whole rows). The picture is read a row of the atlas at a time, once to choose the
// layout (when not given) and once for the rows, none of which is kept: an atlas of 8192 rows
// takes the memory of one. Repeats are found by a 128-bit hash of each row's 8-bit values.
AtlasReading readAtlas(const std::string& path, std::optional<LutLayout> layout = std::nullopt);

// Another pass over an atlas readAtlas read: each row as a LUT, in order, to `row` (atlas
// split writes each as it comes). The same errors as readAtlas (the file may have changed).
void forEachAtlasRow(const std::string& path, const AtlasReading& atlas,
                     const std::function<void(int index, const Lut3D& row)>& row);

} // namespace lut::formats
