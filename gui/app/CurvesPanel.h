#pragma once
// The curves dock: a curve editor (CurveEditor) with a choice of curve: tone curves master, R,
// G, B and the hue curves hue vs hue, hue vs saturation, hue vs luminance; "Reset curve" puts the
// chosen one back to neutral (one undo step).
#include "Document.h"

#include <QWidget>

class QButtonGroup;

namespace lut::gui {

class CurveEditor;

class CurvesPanel : public QWidget {
    Q_OBJECT
public:
    explicit CurvesPanel(Document* doc, QWidget* parent = nullptr);
    CurveEditor* editor() const { return m_editor; }
    void showCurve(CurveId id);

signals:
    void interactiveChanged(bool interactive);

private:
    Document* m_doc;
    CurveEditor* m_editor;
    QButtonGroup* m_choice;
};

} // namespace lut::gui
