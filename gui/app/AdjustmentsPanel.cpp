// SPDX-License-Identifier: Apache-2.0
#include "AdjustmentsPanel.h"

#include "Document.h"
#include "FineSlider.h"
#include "FocusWheel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>

namespace lut::gui {

AdjustmentsPanel::AdjustmentsPanel(Document* doc, QWidget* parent) : QWidget(parent), m_doc(doc) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);
    QGroupBox* box = nullptr;
    QGridLayout* grid = nullptr;
    std::string group;
    int row = 0;
    for (const AdjustParamInfo& info : adjustParams()) {
        if (info.group != group) {
            group = info.group;
            box = new QGroupBox(QString::fromStdString(group), this);
            grid = new QGridLayout(box);
            grid->setContentsMargins(6, 4, 6, 4);
            grid->setVerticalSpacing(0);
            grid->setColumnStretch(0, 1);
            v->addWidget(box);
            row = 0;
        }
        // Label and value on one line, the slider across the whole width below them: the
        // longer the track, the finer a pixel.
        auto* label = new QLabel(QString::fromStdString(info.label), box);
        auto* slider = new FineSlider(Qt::Horizontal, box);
        slider->setRange(0, kSteps);
        slider->setSingleStep(kSteps / 200);
        slider->setPageStep(kSteps / 20);
        slider->setObjectName(QString::fromStdString("slider." + info.key));
        slider->setToolTip(tr("Drag (Shift: ten times finer); right-click resets. The box takes "
                              "values from %1 to %2")
                               .arg(info.min)
                               .arg(info.max));
        auto* spin = new QDoubleSpinBox(box);
        spin->setRange(info.min, info.max);
        spin->setDecimals(info.decimals);
        spin->setSingleStep(info.logScale ? 0.01 : (info.sliderMax - info.sliderMin) / 200.0);
        spin->setObjectName(QString::fromStdString("spin." + info.key));
        spin->setKeyboardTracking(false);
        spin->setFixedWidth(80);
        takeWheelOnlyWhenFocused(spin);
        grid->addWidget(label, row, 0);
        grid->addWidget(spin, row, 1);
        grid->addWidget(slider, row + 1, 0, 1, 2);
        row += 2;
        m_rows[info.id] = {slider, spin};

        const AdjustParam id = info.id;
        connect(slider, &QSlider::valueChanged, this, [this, id, slider](int pos) {
            m_doc->editParam(id, sliderToParam(adjustParamInfo(id), pos, kSteps));
            // Keyboard and click steps are one undo step each; drags merge until release.
            if (!slider->isSliderDown())
                m_doc->endGesture();
        });
        connect(slider, &QSlider::sliderPressed, this, [this] {
            if (m_pressed++ == 0)
                emit interactiveChanged(true);
        });
        connect(slider, &QSlider::sliderReleased, this, [this] {
            m_doc->endGesture();
            if (--m_pressed == 0)
                emit interactiveChanged(false);
        });
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, id](double value) {
            m_doc->editParam(id, value);
            m_doc->endGesture();
        });
        slider->setContextMenuPolicy(Qt::CustomContextMenu);
        connect(slider, &QWidget::customContextMenuRequested, this, [this, id] {
            m_doc->editParam(id, adjustParamInfo(id).defaultValue);
            m_doc->endGesture();
        });
    }
    auto* reset = new QPushButton(tr("Reset all"), this);
    reset->setObjectName("resetAdjustments");
    connect(reset, &QPushButton::clicked, m_doc, &Document::resetAdjustments);
    v->addWidget(reset);
    v->addStretch(1);
    connect(m_doc, &Document::adjustmentsChanged, this, &AdjustmentsPanel::syncFromDocument);
    syncFromDocument();
}

QSlider* AdjustmentsPanel::slider(AdjustParam id) const {
    return m_rows.at(id).slider;
}
QDoubleSpinBox* AdjustmentsPanel::spinBox(AdjustParam id) const {
    return m_rows.at(id).spin;
}

void AdjustmentsPanel::syncFromDocument() {
    for (auto& [id, row] : m_rows) {
        const AdjustParamInfo& info = adjustParamInfo(id);
        const double value = m_doc->param(id);
        QSignalBlocker b1(row.slider), b2(row.spin);
        // Do not yank a slider the user is dragging back to a rounded position.
        if (!row.slider->isSliderDown())
            row.slider->setValue(paramToSlider(info, value, kSteps));
        row.spin->setValue(value);
    }
}

} // namespace lut::gui
