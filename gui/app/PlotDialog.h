// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tools > Plot LUT: the picture `lutkit plot` draws (lut::plotLut: curves along the neutral
// axis, three slices, the lattice in 3D) of the LUT the editor would export now for the window's
// target (the default export's table read back from its bytes: makeTargetLut's `shown`, what
// the preview grades with), scaled to fit, with Save PNG.
#include "ExportTarget.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"

#include <QDialog>

#include <memory>

class QLabel;

namespace lut::gui {

class Document;
class FileActions;

// The table the default export for `target` gives (what the file holds); throws lut::Error.
std::shared_ptr<const Lut3D> exportedLut(const Document& doc, ExportTarget target);
// lut::plotLut of that table, with lutkit plot's defaults; throws lut::Error.
Image plotExportedLut(const Document& doc, ExportTarget target);

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
