// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tools > Plot LUT: the picture `lutkit plot` draws of the LUT the editor would export now for
// the window's target (plotExportedLut, gui/model/ExportedLut.h), scaled to fit, with Save PNG.
#include "ExportedLut.h"

#include <QDialog>

#include <memory>

class QLabel;

namespace lut::gui {

class Document;
class FileActions;

class PlotDialog : public QDialog {
    Q_OBJECT
public:
    // Plots what `doc` exports for `target` (throws lut::Error); Save PNG writes through
    // `files`.
    PlotDialog(QWidget* parent, const Document& doc, ExportTarget target, FileActions* files);

    const Image& plot() const { return m_plot; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void showScaled();
    void savePng();

    const Document& m_doc;
    FileActions* m_files;
    Image m_plot;
    QImage m_picture;
    QLabel* m_view = nullptr;
};

} // namespace lut::gui
