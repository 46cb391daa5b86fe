#pragma once
// Edits one curve of the document's adjustments (lut/ops/Curve.h) with the mouse: a click adds a
// point and drags it, a point drags (Shift: ten times finer), a double-click or right-click on a
// point removes it. Tone curves (master, red, green, blue) map encoded input to output over
// [0,1]; hue curves (hue vs hue, saturation, luminance) are periodic over 0..360 degrees with 0
// = no change. Every press..release is one undo step (Document::editCurve merges within the
// gesture); while a point is held the preview renders proxies (interactiveChanged).
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

    QSize sizeHint() const override { return {300, 240}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

signals:
    void interactiveChanged(bool interactive);

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
    void removePoint(int index);
    glm::dvec2 constrain(glm::dvec2 p, int index, const std::vector<glm::dvec2>& pts) const;

    Document* m_doc;
    CurveId m_id;
    int m_drag = -1;
    QPointF m_lastPos;
    glm::dvec2 m_dragPoint{0.0};
};

} // namespace lut::gui
