// SPDX-License-Identifier: Apache-2.0
#pragma once
// A lift, gamma or gain colour wheel: dragging the puck away from the centre tints that range
// towards the hue under it, by an amount that grows with the distance (Shift: ten times finer);
// a double-click resets it. The wheel sets the three per-channel values of the document's lift
// (or gamma, gain) through lut::colorWheelOffset, which moves the channels without changing
// luminance; the per-channel sliders show the same numbers. One drag is one undo step.
#include "Document.h"

#include <QWidget>

namespace lut::gui {

class ColorWheel : public QWidget {
    Q_OBJECT
public:
    enum class Range { Lift, Gamma, Gain };

    ColorWheel(Document* doc, Range range, QWidget* parent = nullptr);
    Range range() const { return m_range; }
    // The channel offset the wheel reads from/writes to the adjustments (lift: the per-channel
    // lift; gamma, gain: the per-channel factor - 1), and the largest it sets.
    glm::dvec3 offset() const;
    double maxAmount() const;
    // The puck for an offset: hue in degrees and amount (the largest channel movement).
    static void puckFor(glm::dvec3 offset, double& hueDegrees, double& amount);
    // Widget position of a (hue, amount) and back.
    QPointF toWidget(double hueDegrees, double amount) const;

    QSize sizeHint() const override { return {120, 140}; }

signals:
    void interactiveChanged(bool interactive);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void mouseDoubleClickEvent(QMouseEvent*) override;

private:
    QPointF centre() const;
    double radius() const;
    void setFromPuck(QPointF puck);

    Document* m_doc;
    Range m_range;
    bool m_dragging = false;
    QPointF m_puck; // widget position while dragging
    QPointF m_lastPos;
};

} // namespace lut::gui
