// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tools > Compare with LUT File: the report and the heat map of a Comparison (gui/model/
// Comparison.h: the export against a LUT file, as `lutkit diff` reports it), with Save Heat Map.
#include "Comparison.h"

#include <QDialog>

namespace lut::gui {

class FileActions;

class CompareDialog : public QDialog {
    Q_OBJECT
public:
    // Save Heat Map writes through `files`.
    CompareDialog(QWidget* parent, Comparison comparison, FileActions* files);

    QString reportText() const;

private:
    Comparison m_comparison;
    FileActions* m_files;
};

} // namespace lut::gui
