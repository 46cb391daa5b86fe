// SPDX-License-Identifier: Apache-2.0
#pragma once
// Edits one curve of the document's adjustments (lut/ops/Curve.h) with the mouse: a click adds a
// point and drags it, a point drags (Shift: ten times finer), a double-click or right-click on a
// point removes it. Tone curves (master, red, green, blue) map encoded input to output over
// [0,1]; hue curves (hue vs hue, saturation, luminance) are periodic over 0..360 degrees with 0
// = no change, and a point added to one comes with its hue range (HueRanges.h: neutral anchors
// 60 degrees either side unless a point is nearer), so it changes only the hues near it. Every
// press..release is one undo step (Document::editCurve merges within the gesture); while a point
// is held the preview renders proxies (interactiveChanged).
//
// The curve being edited is the one drawn bright and thick, named in the top left corner; the
// other tone curves that are not neutral are drawn thin and dim behind it. The selected point
// (the last one added, clicked or chosen by hue range) is ringed; setSelectedValue() moves it.
#include "Document.h"

#include <QWidget>

#include <vector>

namespace lut::gui {

class CurveEditor : public QWidget {
    Q_OBJECT
public:
    CurveEditor(Document* doc, CurveId id, QWidget* parent = nullptr);
    void setCurveId(CurveId id);
    CurveId curveId() const { return m_id; }
    bool isHueCurve() const;
    // The y range the editor shows: [0,1] for tone curves, +-90 degrees or +-1 for hue curves.
    double yMin() const;
    double yMax() const;
    // Curve coordinates <-> widget pixels (tests drive the editor through these).
    QPointF toWidget(glm::dvec2 p) const;
    glm::dvec2 fromWidget(QPointF p) const;
    // The curve's name as the editor shows it ("Hue vs Sat").
    static QString curveName(CurveId id);

    // The selected point (-1: none) and its value; setting the value is one undo step.
    int selectedPoint() const;
    glm::dvec2 selectedPointValue() const;
    void setSelectedValue(double y);
    // Hue curves: selects the point at `hue` (within a degree), adding it with its hue range at
    // the curve's current value when there is none (one undo step). False on a tone curve.
    bool selectHue(double hue);

    QSize sizeHint() const override { return {300, 240}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

signals:
    void interactiveChanged(bool interactive);
    void selectionChanged();

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void mouseDoubleClickEvent(QMouseEvent*) override;

private:
    QRectF plotRect() const;
    std::vector<glm::dvec2> points() const;
    int pointAt(QPointF pos) const;
    void commit(std::vector<glm::dvec2> pts);
    void select(double x);
    void removePoint(int index);
    glm::dvec2 constrain(glm::dvec2 p, int index, const std::vector<glm::dvec2>& pts) const;

    Document* m_doc;
    CurveId m_id;
    int m_drag = -1;
    double m_selectedX = -1; // x of the selected point (-1: none); kept by x across edits
    QPointF m_lastPos;
    glm::dvec2 m_dragPoint{0.0};
};

} // namespace lut::gui
