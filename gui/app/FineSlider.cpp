// SPDX-License-Identifier: Apache-2.0
#include "FineSlider.h"

#include <QMouseEvent>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lut::gui {

FineSlider::FineSlider(Qt::Orientation orientation, QWidget* parent)
    : QSlider(orientation, parent) {
    setFocusPolicy(Qt::StrongFocus); // focus by click or Tab, never by the wheel
}

double FineSlider::valuePerPixel() const {
    QStyleOptionSlider opt;
    initStyleOption(&opt);
    const QRect handle =
        style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, this);
    const int span = std::max(1, width() - handle.width());
    return double(maximum() - minimum()) / span;
}

int FineSlider::valueAt(QPoint pos) const {
    QStyleOptionSlider opt;
    initStyleOption(&opt);
    const QRect handle =
        style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, this);
    const int span = std::max(1, width() - handle.width());
    return QStyle::sliderValueFromPosition(minimum(), maximum(), pos.x() - handle.width() / 2, span,
                                           opt.upsideDown);
}

void FineSlider::setExact(double v) {
    m_exact = std::clamp(v, double(minimum()), double(maximum()));
    setValue(static_cast<int>(std::lround(m_exact)));
}

void FineSlider::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton || orientation() != Qt::Horizontal) {
        QSlider::mousePressEvent(e);
        return;
    }
    e->accept();
    m_dragging = true;
    m_lastX = e->position().x();
    m_exact = value();
    setSliderDown(true); // sliderPressed: the gesture starts before the value moves
    QStyleOptionSlider opt;
    initStyleOption(&opt);
    const QRect handle =
        style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, this);
    // A click on the track jumps there (not with Shift: a fine drag starts where the value is).
    if (!handle.contains(e->position().toPoint()) && !(e->modifiers() & Qt::ShiftModifier))
        setExact(valueAt(e->position().toPoint()));
}

void FineSlider::mouseMoveEvent(QMouseEvent* e) {
    if (!m_dragging) {
        QSlider::mouseMoveEvent(e);
        return;
    }
    e->accept();
    const double dx = e->position().x() - m_lastX;
    m_lastX = e->position().x();
    const double scale = (e->modifiers() & Qt::ShiftModifier) ? kFineFactor : 1.0;
    setExact(m_exact + dx * valuePerPixel() * scale);
}

void FineSlider::mouseReleaseEvent(QMouseEvent* e) {
    if (!m_dragging) {
        QSlider::mouseReleaseEvent(e);
        return;
    }
    e->accept();
    m_dragging = false;
    setSliderDown(false); // sliderReleased: the gesture ends
}

void FineSlider::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    if (steps == 0 || !hasFocus()) { // unfocused: the wheel scrolls the dock behind it
        e->ignore();
        return;
    }
    e->accept();
    const double scale = (e->modifiers() & Qt::ShiftModifier) ? kFineFactor : 1.0;
    m_wheelRest += steps * singleStep() * scale;
    const int whole = static_cast<int>(m_wheelRest);
    m_wheelRest -= whole;
    if (whole != 0)
        setValue(value() + whole);
}

} // namespace lut::gui
