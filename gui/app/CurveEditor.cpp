// SPDX-License-Identifier: Apache-2.0
#include "CurveEditor.h"

#include "HueRanges.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace lut::gui {

namespace {

constexpr double kMinGapTone = 0.01; // two points closer than this in x are not allowed
constexpr double kMinGapHue = 1.0;   // degrees

QColor curveColor(CurveId id) {
    switch (id) {
    case CurveId::Red:
        return QColor(235, 80, 80);
    case CurveId::Green:
        return QColor(90, 210, 90);
    case CurveId::Blue:
        return QColor(100, 140, 255);
    default:
        return QColor(230, 230, 230);
    }
}

} // namespace

CurveEditor::CurveEditor(Document* doc, CurveId id, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_id(id) {
    setMouseTracking(true);
    setObjectName("curveEditor");
    setToolTip(tr("Click to add a point and drag it (Shift: finer); double-click or right-click "
                  "a point to remove it"));
    connect(m_doc, &Document::adjustmentsChanged, this, qOverload<>(&QWidget::update));
}

void CurveEditor::setCurveId(CurveId id) {
    m_id = id;
    m_drag = -1;
    m_selectedX = -1;
    emit selectionChanged();
    update();
}

QString CurveEditor::curveName(CurveId id) {
    switch (id) {
    case CurveId::Master:
        return tr("Master");
    case CurveId::Red:
        return tr("Red");
    case CurveId::Green:
        return tr("Green");
    case CurveId::Blue:
        return tr("Blue");
    case CurveId::HueVsHue:
        return tr("Hue vs Hue");
    case CurveId::HueVsSat:
        return tr("Hue vs Sat");
    case CurveId::HueVsLum:
        return tr("Hue vs Lum");
    }
    return {};
}

void CurveEditor::select(double x) {
    if (x == m_selectedX)
        return;
    m_selectedX = x;
    emit selectionChanged();
    update();
}

int CurveEditor::selectedPoint() const {
    if (m_selectedX < 0)
        return -1;
    const auto pts = points();
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (pts[i].x == m_selectedX)
            return static_cast<int>(i);
    return -1;
}

glm::dvec2 CurveEditor::selectedPointValue() const {
    const int i = selectedPoint();
    return i < 0 ? glm::dvec2(0.0) : points()[static_cast<std::size_t>(i)];
}

void CurveEditor::setSelectedValue(double y) {
    const int i = selectedPoint();
    if (i < 0)
        return;
    auto pts = points();
    glm::dvec2 p = pts[static_cast<std::size_t>(i)];
    p.y = std::clamp(y, yMin(), yMax());
    if (isHueCurve()) {
        const Curve& curve = curveOf(m_doc->adjustments(), m_id);
        pts = withLocalPoint(
            pts, p, [&curve](double h) { return curve(h); }, nullptr);
    } else {
        pts[static_cast<std::size_t>(i)] = p;
    }
    commit(pts);
    m_doc->endGesture();
}

bool CurveEditor::selectHue(double hue) {
    if (!isHueCurve())
        return false;
    const Curve& curve = curveOf(m_doc->adjustments(), m_id);
    int index = -1;
    const auto pts = withLocalPoint(
        points(), {hue, std::clamp(curve(hue), yMin(), yMax())},
        [&curve](double h) { return curve(h); }, &index);
    if (pts != points()) {
        commit(pts);
        m_doc->endGesture();
    }
    select(index >= 0 ? pts[static_cast<std::size_t>(index)].x : -1);
    return true;
}

bool CurveEditor::isHueCurve() const {
    return m_id == CurveId::HueVsHue || m_id == CurveId::HueVsSat || m_id == CurveId::HueVsLum;
}

double CurveEditor::yMin() const {
    return !isHueCurve() ? 0.0 : m_id == CurveId::HueVsHue ? -90.0 : -1.0;
}

double CurveEditor::yMax() const {
    return !isHueCurve() ? 1.0 : m_id == CurveId::HueVsHue ? 90.0 : 1.0;
}

QRectF CurveEditor::plotRect() const {
    return QRectF(8, 8, width() - 16, height() - (isHueCurve() ? 30 : 16));
}

QPointF CurveEditor::toWidget(glm::dvec2 p) const {
    const QRectF r = plotRect();
    const double xMax = isHueCurve() ? 360.0 : 1.0;
    return {r.left() + p.x / xMax * r.width(),
            r.bottom() - (p.y - yMin()) / (yMax() - yMin()) * r.height()};
}

glm::dvec2 CurveEditor::fromWidget(QPointF q) const {
    const QRectF r = plotRect();
    const double xMax = isHueCurve() ? 360.0 : 1.0;
    return {std::clamp((q.x() - r.left()) / r.width(), 0.0, 1.0) * xMax,
            yMin() + std::clamp((r.bottom() - q.y()) / r.height(), 0.0, 1.0) * (yMax() - yMin())};
}

std::vector<glm::dvec2> CurveEditor::points() const {
    return curveOf(m_doc->adjustments(), m_id).points();
}

int CurveEditor::pointAt(QPointF pos) const {
    const auto pts = points();
    int best = -1;
    double bestD = 8.0; // pixels
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const QPointF w = toWidget(pts[i]);
        const double d = std::hypot(w.x() - pos.x(), w.y() - pos.y());
        if (d < bestD) {
            bestD = d;
            best = static_cast<int>(i);
        }
    }
    return best;
}

glm::dvec2 CurveEditor::constrain(glm::dvec2 p, int index,
                                  const std::vector<glm::dvec2>& pts) const {
    const double gap = isHueCurve() ? kMinGapHue : kMinGapTone;
    const double xMax = isHueCurve() ? 360.0 - gap : 1.0;
    double lo = 0.0, hi = xMax;
    if (index > 0)
        lo = pts[index - 1].x + gap;
    if (index + 1 < static_cast<int>(pts.size()))
        hi = pts[index + 1].x - gap;
    p.x = std::clamp(p.x, lo, std::max(lo, hi));
    p.y = std::clamp(p.y, yMin(), yMax());
    return p;
}

void CurveEditor::commit(std::vector<glm::dvec2> pts) {
    const CurveKind kind = isHueCurve() ? CurveKind::Hue : CurveKind::Tone;
    try {
        m_doc->editCurve(m_id, Curve(kind, std::move(pts)));
    } catch (const std::exception&) {
        // Two points at one x: the constraint keeps them apart, so this is not reached.
    }
}

void CurveEditor::removePoint(int index) {
    auto pts = points();
    if (index < 0 || index >= static_cast<int>(pts.size()))
        return;
    if (pts[static_cast<std::size_t>(index)].x == m_selectedX)
        select(-1);
    pts.erase(pts.begin() + index);
    // A tone curve with one point left is no curve: back to the identity.
    if (!isHueCurve() && pts.size() < 2)
        pts.clear();
    commit(std::move(pts));
    m_doc->endGesture();
}

void CurveEditor::mousePressEvent(QMouseEvent* e) {
    const QPointF pos = e->position();
    if (e->button() == Qt::RightButton) {
        removePoint(pointAt(pos));
        return;
    }
    if (e->button() != Qt::LeftButton)
        return;
    auto pts = points();
    int index = pointAt(pos);
    emit interactiveChanged(true);
    if (index < 0 && isHueCurve()) {
        // A new point with its hue range: only the hues near the click change.
        const Curve& curve = curveOf(m_doc->adjustments(), m_id);
        const glm::dvec2 p = constrain(fromWidget(pos), -1, {});
        pts = withLocalPoint(
            pts, p, [&curve](double h) { return curve(h); }, &index);
        commit(pts);
    } else if (index < 0) {
        // A new point on the click; a tone curve without points starts from its end points.
        if (pts.empty())
            pts = {{0.0, 0.0}, {1.0, 1.0}};
        glm::dvec2 p = fromWidget(pos);
        auto at = std::lower_bound(pts.begin(), pts.end(), p.x,
                                   [](const glm::dvec2& a, double x) { return a.x < x; });
        index = static_cast<int>(at - pts.begin());
        pts.insert(at, p);
        pts[index] = constrain(p, index, pts);
        // Too close to a neighbour to fit: no point.
        const double gap = isHueCurve() ? kMinGapHue : kMinGapTone;
        if ((index > 0 && pts[index].x - pts[index - 1].x < gap * 0.5) ||
            (index + 1 < int(pts.size()) && pts[index + 1].x - pts[index].x < gap * 0.5)) {
            emit interactiveChanged(false);
            return;
        }
        commit(pts);
    }
    if (index < 0 || index >= static_cast<int>(points().size())) {
        emit interactiveChanged(false);
        return;
    }
    m_drag = index;
    m_dragPoint = points()[index];
    m_lastPos = pos;
    select(m_dragPoint.x);
}

void CurveEditor::mouseMoveEvent(QMouseEvent* e) {
    if (m_drag < 0) {
        setCursor(pointAt(e->position()) >= 0 ? Qt::SizeAllCursor : Qt::CrossCursor);
        return;
    }
    auto pts = points();
    if (m_drag >= static_cast<int>(pts.size()))
        return;
    // Relative movement, scaled with Shift: precise placement on a small plot.
    const double scale = (e->modifiers() & Qt::ShiftModifier) ? 0.1 : 1.0;
    const QPointF delta = (e->position() - m_lastPos) * scale;
    m_lastPos = e->position();
    const QPointF w = toWidget(m_dragPoint) + delta;
    const glm::dvec2 p = fromWidget(w);
    m_dragPoint = constrain(p, m_drag, pts);
    if (isHueCurve()) {
        // The point keeps its hue range as it moves: a point without a neighbour within 60
        // degrees (a lone point, an anchor) gets its anchors at the first move.
        const Curve& curve = curveOf(m_doc->adjustments(), m_id);
        pts.erase(pts.begin() + m_drag);
        pts = withLocalPoint(
            pts, m_dragPoint, [&curve](double h) { return curve(h); }, &m_drag);
    } else {
        pts[m_drag] = m_dragPoint;
    }
    m_selectedX = m_dragPoint.x; // the selection follows the point (no signal: same point)
    commit(pts);
    emit selectionChanged();
}

void CurveEditor::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton || m_drag < 0)
        return;
    m_drag = -1;
    m_doc->endGesture();
    emit interactiveChanged(false);
}

void CurveEditor::mouseDoubleClickEvent(QMouseEvent* e) {
    removePoint(pointAt(e->position()));
}

void CurveEditor::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(0x22, 0x22, 0x24));
    const QRectF r = plotRect();
    p.setRenderHint(QPainter::Antialiasing);
    if (isHueCurve()) {
        // The hues along the bottom, so a point's x reads as a colour.
        QLinearGradient g(r.left(), 0, r.right(), 0);
        for (int h = 0; h <= 360; h += 30)
            g.setColorAt(h / 360.0, QColor::fromHsv(h % 360, 200, 230));
        p.fillRect(QRectF(r.left(), r.bottom() + 6, r.width(), 12), g);
    }
    p.setPen(QPen(QColor(70, 70, 74), 1));
    for (int i = 1; i < 4; ++i) {
        p.drawLine(QPointF(r.left() + r.width() * i / 4, r.top()),
                   QPointF(r.left() + r.width() * i / 4, r.bottom()));
        p.drawLine(QPointF(r.left(), r.top() + r.height() * i / 4),
                   QPointF(r.right(), r.top() + r.height() * i / 4));
    }
    p.drawRect(r);
    p.setPen(QPen(QColor(110, 110, 116), 1, Qt::DashLine));
    if (isHueCurve())
        p.drawLine(toWidget({0.0, 0.0}), toWidget({360.0, 0.0}));
    else
        p.drawLine(toWidget({0.0, 0.0}), toWidget({1.0, 1.0}));

    const int n = std::max(2, static_cast<int>(r.width()));
    auto pathOf = [&](const Curve& curve) {
        QPainterPath path;
        for (int i = 0; i <= n; ++i) {
            const double x = (isHueCurve() ? 360.0 : 1.0) * i / n;
            double y = curve.empty() ? (isHueCurve() ? 0.0 : x) : curve(x);
            y = std::clamp(y, yMin(), yMax());
            const QPointF w = toWidget({x, y});
            if (i == 0)
                path.moveTo(w);
            else
                path.lineTo(w);
        }
        return path;
    };
    p.setBrush(Qt::NoBrush);
    if (!isHueCurve()) {
        // The other tone curves that do something, thin and dim: the active one stands out.
        for (CurveId other : {CurveId::Master, CurveId::Red, CurveId::Green, CurveId::Blue}) {
            const Curve& c = curveOf(m_doc->adjustments(), other);
            if (other == m_id || c.isNeutral())
                continue;
            QColor dim = curveColor(other);
            dim.setAlpha(90);
            p.setPen(QPen(dim, 1));
            p.drawPath(pathOf(c));
        }
    }
    const QColor color = curveColor(m_id);
    p.setPen(QPen(color, 2.5));
    p.drawPath(pathOf(curveOf(m_doc->adjustments(), m_id)));
    p.setBrush(color);
    p.setPen(QPen(Qt::black, 1));
    const int selected = selectedPoint();
    const auto pts = points();
    for (std::size_t i = 0; i < pts.size(); ++i) {
        p.drawEllipse(toWidget(pts[i]), 4.5, 4.5);
        if (static_cast<int>(i) == selected) {
            p.save();
            p.setBrush(Qt::NoBrush);
            p.setPen(QPen(Qt::white, 1.5));
            p.drawEllipse(toWidget(pts[i]), 8.0, 8.0);
            p.restore();
        }
    }
    // The curve's name, so which one is being edited never depends on reading the buttons.
    QFont f = font();
    f.setBold(true);
    p.setFont(f);
    p.setPen(color);
    p.drawText(r.adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::AlignTop, curveName(m_id));
}

} // namespace lut::gui
