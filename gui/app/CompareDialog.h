#pragma once
// Tools > Compare with LUT File: how the LUT the editor would export now (exportedLut, the
// window's target) differs from a LUT file, as `lutkit diff` reports it: lut::diffLuts over the
// lattice, or lut::diffLutsOnImage over the open image's colours; the heat map of lut::diffHeatMap
// on the image, else lut::diffHeatMapSlices. The dialog shows the report and the heat map.
#include "ExportTarget.h"

#include "lut/ops/Diff.h"
#include "lut/ops/HeatMap.h"

#include <QDialog>
#include <QString>

namespace lut::gui {

class Document;
class MainWindow;

struct Comparison {
    QString otherPath;
    QString over; // "" = the lattice, else the image's path
    DiffReport report;
    HeatMap heat;
};

// Reads `otherPath` with any registered format and compares (A = the export, B = the file);
// throws lut::Error.
Comparison compareWithFile(const Document& doc, ExportTarget target, const QString& otherPath);
// The report as text: ΔE2000 max/mean, 8-bit steps per channel max/mean, the worst colour, the
// regions (largest mean ΔE first).
QString comparisonText(const Comparison& c);

class CompareDialog : public QDialog {
    Q_OBJECT
public:
    CompareDialog(MainWindow* window, Comparison comparison);

    QString reportText() const;

private:
    MainWindow* m_window;
    Comparison m_comparison;
};

} // namespace lut::gui
