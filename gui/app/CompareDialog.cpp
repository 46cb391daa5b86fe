// SPDX-License-Identifier: Apache-2.0
#include "CompareDialog.h"

#include "Document.h"
#include "FileActions.h"
#include "PreviewFrame.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include <utility>

namespace lut::gui {

namespace {

QString g3(double v) {
    return QString::number(v, 'g', 3);
}

} // namespace

CompareDialog::CompareDialog(QWidget* parent, Comparison comparison, FileActions* files)
    : QDialog(parent), m_comparison(std::move(comparison)), m_files(files) {
    setWindowTitle(tr("Compare with %1").arg(QFileInfo(m_comparison.otherPath).fileName()));
    auto* layout = new QVBoxLayout(this);
    auto* text = new QPlainTextEdit(reportText(), this);
    text->setObjectName("compareReport");
    text->setReadOnly(true);
    text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    text->setLineWrapMode(QPlainTextEdit::NoWrap);
    layout->addWidget(text);
    layout->addWidget(new QLabel(tr("Heat map: black = ΔE2000 0 to pale yellow = ΔE %1 and above")
                                     .arg(g3(m_comparison.heat.maxDeltaE)),
                                 this));
    auto* picture = new QLabel(this);
    picture->setObjectName("heatMap");
    picture->setPixmap(QPixmap::fromImage(m_comparison.heatPicture.isNull()
                                              ? toDisplayImage(m_comparison.heat.image)
                                              : m_comparison.heatPicture));
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(picture);
    scroll->setAlignment(Qt::AlignCenter);
    layout->addWidget(scroll, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* save = buttons->addButton(tr("Save Heat Map…"), QDialogButtonBox::ActionRole);
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path =
            QFileDialog::getSaveFileName(this, tr("Save Heat Map"), QStringLiteral("heatmap.png"),
                                         tr("PNG pictures (*.png);;All files (*)"));
        if (!path.isEmpty()) // the file dialog asked before replacing
            m_files->savePicture(path, m_comparison.heat.image, true);
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(900, 700);
}

QString CompareDialog::reportText() const {
    return comparisonText(m_comparison);
}

} // namespace lut::gui
