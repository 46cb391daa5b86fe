// SPDX-License-Identifier: Apache-2.0
#include "ColorWheel.h"

#include <QConicalGradient>
#include <QMouseEvent>
#include <QPainter>
#include <QRadialGradient>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lut::gui {

ColorWheel::ColorWheel(Document* doc, Range range, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_range(range) {
    setObjectName(range == Range::Lift    ? "wheel.lift"
                  : range == Range::Gamma ? "wheel.gamma"
                                          : "wheel.gain");
    setMinimumSize(90, 110);
    setToolTip(tr("Drag to tint (Shift: finer); double-click to reset"));
    connect(m_doc, &Document::adjustmentsChanged, this, qOverload<>(&QWidget::update));
}

double ColorWheel::maxAmount() const {
    return m_range == Range::Lift ? 0.15 : 0.4;
}

glm::dvec3 ColorWheel::offset() const {
    const Adjustments& a = m_doc->adjustments();
    switch (m_range) {
    case Range::Lift:
        return a.lift;
    case Range::Gamma:
        return a.gamma - glm::dvec3(1.0);
    case Range::Gain:
        return a.gain - glm::dvec3(1.0);
    }
    return glm::dvec3(0.0);
}

void ColorWheel::puckFor(glm::dvec3 o, double& hue, double& amount) {
    amount = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
    hue = 0.0;
    if (amount < 1e-12)
        return;
    // colorWheelOffset has no closed-form inverse here: search the hue (1 degree, then 0.01).
    auto err = [&](double h) {
        const glm::dvec3 d = colorWheelOffset(h, amount) - o;
        return d.x * d.x + d.y * d.y + d.z * d.z;
    };
    double best = 0.0, bestErr = err(0.0);
    for (int h = 1; h < 360; ++h)
        if (const double e = err(h); e < bestErr) {
            bestErr = e;
            best = h;
        }
    hue = best;
    for (double h = best - 1.0; h <= best + 1.0; h += 0.01)
        if (const double e = err(h); e < bestErr) {
            bestErr = e;
            hue = h;
        }
    hue = std::fmod(hue + 360.0, 360.0);
}

QPointF ColorWheel::centre() const {
    return {width() / 2.0, (height() - 20) / 2.0};
}

double ColorWheel::radius() const {
    return std::max(10.0, std::min(width(), height() - 20) / 2.0 - 4.0);
}

QPointF ColorWheel::toWidget(double hue, double amount) const {
    const double t = std::clamp(amount / maxAmount(), 0.0, 1.0) * radius();
    const double a = hue * std::numbers::pi / 180.0;
    // Hue 0 (red) to the right, counter-clockwise like a colour wheel (screen y points down).
    return centre() + QPointF(std::cos(a) * t, -std::sin(a) * t);
}

void ColorWheel::setFromPuck(QPointF puck) {
    const QPointF d = puck - centre();
    const double dist = std::min(std::hypot(d.x(), d.y()), radius());
    const double amount = dist / radius() * maxAmount();
    const double hue = std::atan2(-d.y(), d.x()) * 180.0 / std::numbers::pi;
    const glm::dvec3 o = amount > 0 ? colorWheelOffset(hue, amount) : glm::dvec3(0.0);
    Adjustments a = m_doc->adjustments();
    const char* what = "lift wheel";
    switch (m_range) {
    case Range::Lift:
        a.lift = o;
        break;
    case Range::Gamma:
        a.gamma = glm::dvec3(1.0) + o;
        what = "gamma wheel";
        break;
    case Range::Gain:
        a.gain = glm::dvec3(1.0) + o;
        what = "gain wheel";
        break;
    }
    m_doc->editAdjustments(a, 200 + static_cast<int>(m_range),
                           tr("Move %1").arg(QString::fromLatin1(what)));
}

void ColorWheel::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton)
        return;
    double hue, amount;
    puckFor(offset(), hue, amount);
    m_puck = toWidget(hue, amount);
    m_lastPos = e->position();
    m_dragging = true;
    emit interactiveChanged(true);
    // A press away from the puck moves it there (not with Shift: a fine drag from where it is).
    const QPointF d = e->position() - m_puck;
    if (std::hypot(d.x(), d.y()) > 8 && !(e->modifiers() & Qt::ShiftModifier)) {
        m_puck = e->position();
        setFromPuck(m_puck);
    }
}

void ColorWheel::mouseMoveEvent(QMouseEvent* e) {
    if (!m_dragging)
        return;
    const double scale = (e->modifiers() & Qt::ShiftModifier) ? 0.1 : 1.0;
    m_puck += (e->position() - m_lastPos) * scale;
    m_lastPos = e->position();
    setFromPuck(m_puck);
}

void ColorWheel::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton || !m_dragging)
        return;
    m_dragging = false;
    m_doc->endGesture();
    emit interactiveChanged(false);
}

void ColorWheel::mouseDoubleClickEvent(QMouseEvent*) {
    setFromPuck(centre());
    m_doc->endGesture();
}

void ColorWheel::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPointF c = centre();
    const double r = radius();
    QConicalGradient hues(c, 0);
    for (int h = 0; h <= 360; h += 30)
        hues.setColorAt(h / 360.0, QColor::fromHsv(h % 360, 150, 200));
    p.setPen(Qt::NoPen);
    p.setBrush(hues);
    p.drawEllipse(c, r, r);
    QRadialGradient fade(c, r);
    fade.setColorAt(0, QColor(60, 60, 60, 255));
    fade.setColorAt(1, QColor(60, 60, 60, 0));
    p.setBrush(fade);
    p.drawEllipse(c, r, r);
    p.setPen(QPen(QColor(20, 20, 20), 1));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(c, r, r);
    p.drawLine(c - QPointF(4, 0), c + QPointF(4, 0));
    p.drawLine(c - QPointF(0, 4), c + QPointF(0, 4));
    double hue, amount;
    puckFor(offset(), hue, amount);
    const QPointF puck = toWidget(hue, amount);
    p.setPen(QPen(Qt::black, 1.5));
    p.setBrush(Qt::white);
    p.drawEllipse(puck, 5, 5);
    const QString name = m_range == Range::Lift    ? tr("Lift")
                         : m_range == Range::Gamma ? tr("Gamma")
                                                   : tr("Gain");
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(0, height() - 18, width(), 18), Qt::AlignCenter, name);
}

} // namespace lut::gui
