// SPDX-License-Identifier: Apache-2.0
#pragma once
// The curves dock: a curve editor (CurveEditor) with a choice of curve: tone curves master, R,
// G, B and the hue curves hue vs hue, hue vs saturation, hue vs luminance. The chosen curve's
// button is lit (the highlight colour) and the editor names it. For the hue curves, six range
// buttons (reds, yellows, greens, cyans, blues, magentas: HueRanges.h) select the point at that
// hue, added with its hue range when missing, and "Amount" sets the selected point's value
// (degrees of hue shift, or the saturation / luminance change: -1 .. 1). "Reset curve" puts the
// chosen curve back to neutral. Each change is one undo step.
#include "Document.h"

#include <QWidget>

class QButtonGroup;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace lut::gui {

class CurveEditor;

class CurvesPanel : public QWidget {
    Q_OBJECT
public:
    explicit CurvesPanel(Document* doc, QWidget* parent = nullptr);
    CurveEditor* editor() const { return m_editor; }
    void showCurve(CurveId id);
    CurveId shownCurve() const;
    QPushButton* curveButton(CurveId id) const;
    // Hue curves: the range button `key` ("reds", ...) and the amount box.
    QPushButton* rangeButton(const char* key) const;
    QDoubleSpinBox* amountBox() const { return m_amount; }

signals:
    void interactiveChanged(bool interactive);

private:
    void updateHueRow();

    Document* m_doc;
    CurveEditor* m_editor;
    QButtonGroup* m_choice;
    QWidget* m_hueRow = nullptr;
    QLabel* m_pointLabel = nullptr;
    QDoubleSpinBox* m_amount = nullptr;
};

} // namespace lut::gui
