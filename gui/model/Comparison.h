// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tools > Compare with LUT File's model (the dialog is gui/app/CompareDialog.h): how the LUT the
// editor would export now (the window's target) differs from a LUT file, as `lutkit diff`
// reports it: lut::diffLuts over the lattice, or lut::diffLutsOnImage over the open image's
// colours; the heat map of lut::diffHeatMap on the image, else lut::diffHeatMapSlices.
#include "ExportTarget.h"

#include "lut/Image.h"
#include "lut/Progress.h"
#include "lut/ops/Diff.h"
#include "lut/ops/HeatMap.h"

#include <QImage>
#include <QString>

#include <memory>

namespace lut::gui {

class Document;

struct Comparison {
    QString otherPath;
    QString over; // "" = the lattice, else the image's path
    DiffReport report;
    HeatMap heat;
    QImage heatPicture; // the heat map in 8 bits, made with it (on the worker)
};

// What a comparison is made from, taken from the document on the window's thread so the
// comparison itself can run on a worker (BackgroundTask) while the document changes.
struct CompareInput {
    LutSource source;
    ExportTarget target = ExportTarget::Smash;
    std::shared_ptr<const Image> image; // null: over the lattice
    QString imagePath;
    QString otherPath;
};
CompareInput compareInput(const Document& doc, ExportTarget target, const QString& otherPath);
// Reads `otherPath` with any registered format and compares (A = the export, B = the file): the
// diff is the first 60 % of `progress`, the heat map the rest; throws lut::Error, or
// lut::CancelledError once `progress` is cancelled.
Comparison compareLuts(const CompareInput& input, const Progress* progress = nullptr);
// The same on the calling thread.
Comparison compareWithFile(const Document& doc, ExportTarget target, const QString& otherPath);
// The report as text: ΔE2000 max/mean, 8-bit steps per channel max/mean, the worst colour, the
// regions (largest mean ΔE first).
QString comparisonText(const Comparison& c);

} // namespace lut::gui
