// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sliders (with spin boxes) for every adjustment parameter, bound to a Document: moving a slider
// pushes undoable edits that merge for the duration of the drag; the panel follows the document
// on undo/redo. The sliders are FineSlider (Shift: ten times finer) spanning each parameter's
// useful range over the dock's width; the spin boxes take any value in the parameter's range.
#include "AdjustParam.h"

#include <QWidget>

#include <map>

class QSlider;
class QDoubleSpinBox;

namespace lut::gui {

class Document;

class AdjustmentsPanel : public QWidget {
    Q_OBJECT
public:
    static constexpr int kSteps = 10000;

    AdjustmentsPanel(Document* doc, QWidget* parent = nullptr);
    QSlider* slider(AdjustParam id) const;
    QDoubleSpinBox* spinBox(AdjustParam id) const;

signals:
    // True while a slider is held down: the preview renders a proxy meanwhile.
    void interactiveChanged(bool interactive);

private:
    void syncFromDocument();

    struct Row {
        QSlider* slider;
        QDoubleSpinBox* spin;
    };
    Document* m_doc;
    std::map<AdjustParam, Row> m_rows;
    int m_pressed = 0;
};

} // namespace lut::gui
