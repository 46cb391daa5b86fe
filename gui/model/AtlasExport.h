// SPDX-License-Identifier: Apache-2.0
#pragma once
// The export as a row of a LUT atlas (File > Export LUT…, "LUT atlas"): what ReShade's
// MultiLUT.fx (or a Unity 1024x32 stack) samples, several LUTs as the rows of one picture. The
// atlas is made by the library's lut::formats::buildAtlas (lutkit atlas build: every row at the
// atlas's N, resampled with its error said, stored in 8 bits, a LUT already in the atlas refused
// naming its row), so the editor writes the bytes the command line writes:
//   - `path` does not exist: a new atlas, the neutral LUT as row 0 (MultiLUT's "Neutral") and
//     the LUT as row 1;
//   - `path` is an atlas: its rows are kept and the LUT is added as the last row (nothing the
//     file held is lost; a file that is no atlas is refused, never replaced).
// The rows are handed to the library in memory (no temporary file), named in its messages as
// what they are: the atlas's file for the rows it held, "the export" for the new one.
#include "lut/Error.h"
#include "lut/Lut3D.h"
#include "lut/LutPurpose.h"
#include "lut/io/Layout.h"

#include <QString>

namespace lut::gui {

struct AtlasExportResult {
    int row = 0;  // the row the LUT went to
    int rows = 0; // rows in the atlas written
    int size = 0; // N of every row
    Diagnostics diagnostics;
};

// Throws lut::Error (naming the file) and leaves the file as it was.
AtlasExportResult exportAtlasRow(const Lut3D& table, LutPurpose purpose, const QString& path,
                                 LutLayout layout);

} // namespace lut::gui
