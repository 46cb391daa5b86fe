// SPDX-License-Identifier: Apache-2.0
#pragma once
// A slider for precise values on a short track: a click jumps to the position, a drag follows
// the mouse relative to where it was (no jump), ten times finer while Shift is held; the wheel
// steps by the single step (Shift: a tenth of it, accumulated) once the slider has the focus
// (a click or Tab: FocusWheel.h), else it scrolls what is behind. Emits QSlider's signals
// (sliderPressed/valueChanged/sliderReleased), so undo merging per drag works as with QSlider.
#include <QSlider>

namespace lut::gui {

class FineSlider : public QSlider {
    Q_OBJECT
public:
    static constexpr double kFineFactor = 0.1; // movement scale with Shift held

    explicit FineSlider(Qt::Orientation orientation, QWidget* parent = nullptr);

protected:
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

private:
    double valuePerPixel() const;
    int valueAt(QPoint pos) const;
    void setExact(double v);

    bool m_dragging = false;
    double m_exact = 0.0; // the value with the fraction fine moves accumulate
    double m_lastX = 0.0;
    double m_wheelRest = 0.0;
};

} // namespace lut::gui
