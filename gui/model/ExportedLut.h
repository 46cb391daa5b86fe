// SPDX-License-Identifier: Apache-2.0
#pragma once
// The LUT the editor would export now for a target, as a table (the default export's table read
// back from its bytes: makeTargetLut's `shown`, what the preview grades with), and its plot as
// `lutkit plot` draws it (lut::plotLut: curves along the neutral axis, three slices, the lattice
// in 3D). Tools > Plot LUT (gui/app/PlotDialog.h) shows the plot.
#include "ExportTarget.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"

#include <memory>

namespace lut::gui {

class Document;

// The table the default export for `target` gives (what the file holds); throws lut::Error.
std::shared_ptr<const Lut3D> exportedLut(const Document& doc, ExportTarget target);
// lut::plotLut of that table, with lutkit plot's defaults; throws lut::Error.
Image plotExportedLut(const Document& doc, ExportTarget target);

} // namespace lut::gui
