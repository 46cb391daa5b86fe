// SPDX-License-Identifier: Apache-2.0
#include "PlotDialog.h"

#include "Document.h"
#include "FileActions.h"
#include "PreviewFrame.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace lut::gui {

PlotDialog::PlotDialog(QWidget* parent, const Document& doc, ExportTarget target,
                       FileActions* files)
    : QDialog(parent), m_doc(doc), m_files(files), m_plot(plotExportedLut(doc, target)),
      m_picture(toDisplayImage(m_plot)) {
    const ExportTargetInfo& t = exportTargetInfo(target);
    setWindowTitle(tr("Plot LUT: %1").arg(doc.displayName()));
    auto* layout = new QVBoxLayout(this);
    auto* caption = new QLabel(
        tr("The %1 export (%2): curves along the neutral axis, slices at blue 0, 0.5 and 1, the "
           "lattice in 3D, as lutkit plot draws it.")
            .arg(QString::fromStdString(t.label), QString::fromStdString(t.extension)),
        this);
    caption->setWordWrap(true);
    layout->addWidget(caption);
    m_view = new QLabel(this);
    m_view->setObjectName("plotPicture");
    m_view->setAlignment(Qt::AlignCenter);
    m_view->setMinimumSize(320, 120);
    m_view->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    layout->addWidget(m_view, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* save = buttons->addButton(tr("Save PNG…"), QDialogButtonBox::ActionRole);
    save->setObjectName("savePlot");
    connect(save, &QPushButton::clicked, this, &PlotDialog::savePng);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(std::min(m_picture.width() + 40, 1200), std::min(m_picture.height() + 120, 800));
    showScaled();
}

void PlotDialog::resizeEvent(QResizeEvent* event) {
    QDialog::resizeEvent(event);
    showScaled();
}

void PlotDialog::showScaled() {
    if (!m_view)
        return;
    const QSize room = m_view->size();
    QImage shown = m_picture;
    if (m_picture.width() > room.width() || m_picture.height() > room.height())
        shown = m_picture.scaled(room, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    m_view->setPixmap(QPixmap::fromImage(shown));
}

void PlotDialog::savePng() {
    const QString from = !m_doc.lutPath().isEmpty() ? m_doc.lutPath() : m_doc.imagePath();
    const QString base = from.isEmpty()
                             ? QStringLiteral("plot.png")
                             : QFileInfo(from).absolutePath() + '/' +
                                   QFileInfo(from).completeBaseName() + QStringLiteral("_plot.png");
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Plot"), base,
                                                      tr("PNG pictures (*.png);;All files (*)"));
    if (!path.isEmpty())
        m_files->savePicture(path, m_plot, true); // the file dialog asked
}

} // namespace lut::gui
