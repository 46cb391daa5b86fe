// SPDX-License-Identifier: Apache-2.0
#include "PreviewView.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lut::gui {

namespace {
// The After side while its frame is being graded: the window's background, a shade lighter.
const QColor kPendingColour(0x33, 0x33, 0x36);
} // namespace

PreviewView::PreviewView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(320, 240);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::StrongFocus);
}

void PreviewView::setImageSize(QSize size) {
    const bool changed = size != m_imageSize;
    m_imageSize = size;
    if (changed)
        zoomToFit();
    update();
}

void PreviewView::setBefore(const QImage& image) {
    m_before = image;
    update();
}

void PreviewView::setAfter(const QImage& image, const QImage& clipOverlay) {
    m_after = image;
    m_clip = clipOverlay;
    update();
}

void PreviewView::setHighlight(const QImage& overlay) {
    m_highlight = overlay;
    update();
}

void PreviewView::setShowClipping(bool on) {
    m_showClipping = on;
    update();
}

void PreviewView::clear() {
    m_before = {};
    m_after = {};
    m_clip = {};
    m_highlight = {};
    m_imageSize = {};
    update();
}

void PreviewView::setMode(Mode mode) {
    const bool changed = mode != m_mode;
    m_mode = mode;
    update();
    if (changed)
        emit modeChanged(mode);
}

void PreviewView::setSplit(double fraction) {
    m_split = std::clamp(fraction, 0.0, 1.0);
    update();
}

double PreviewView::zoom() const {
    if (!m_fit || m_imageSize.isEmpty())
        return m_scale;
    const double sx = (width() - 16.0) / m_imageSize.width();
    const double sy = (height() - 16.0) / m_imageSize.height();
    return std::max(1e-3, std::min(sx, sy));
}

QRectF PreviewView::imageRect() const {
    if (m_imageSize.isEmpty())
        return {};
    const double s = zoom();
    const QSizeF sz(m_imageSize.width() * s, m_imageSize.height() * s);
    if (m_fit)
        return QRectF(QPointF(std::round((width() - sz.width()) / 2),
                              std::round((height() - sz.height()) / 2)),
                      sz);
    return QRectF(m_offset, sz);
}

void PreviewView::zoomToFit() {
    m_fit = true;
    update();
    emit zoomChanged(zoom());
}

void PreviewView::zoomTo(double scale, QPointF anchor) {
    if (m_imageSize.isEmpty())
        return;
    scale = std::clamp(scale, 0.02, 64.0);
    if (anchor.x() < 0)
        anchor = QPointF(width() / 2.0, height() / 2.0);
    const QRectF r = imageRect();
    // Keep the image point under the anchor in place.
    const QPointF imgPt = (anchor - r.topLeft()) / zoom();
    m_fit = false;
    m_scale = scale;
    m_offset = anchor - imgPt * scale;
    clampOffset();
    update();
    emit zoomChanged(m_scale);
}

void PreviewView::zoomBy(double factor) {
    zoomTo(zoom() * factor);
}

void PreviewView::clampOffset() {
    if (m_fit || m_imageSize.isEmpty())
        return;
    const double w = m_imageSize.width() * m_scale, h = m_imageSize.height() * m_scale;
    // Centre an axis that fits; otherwise keep the image covering the view.
    if (w <= width())
        m_offset.setX((width() - w) / 2);
    else
        m_offset.setX(std::clamp(m_offset.x(), width() - w, 0.0));
    if (h <= height())
        m_offset.setY((height() - h) / 2);
    else
        m_offset.setY(std::clamp(m_offset.y(), height() - h, 0.0));
    // Whole-pixel offsets: at 100 % every image pixel lands on exactly one screen pixel.
    m_offset = QPointF(std::round(m_offset.x()), std::round(m_offset.y()));
}

double PreviewView::dividerX() const {
    const QRectF r = imageRect();
    return r.left() + m_split * r.width();
}

bool PreviewView::nearDivider(QPointF p) const {
    return m_mode == Mode::Split && !m_imageSize.isEmpty() && std::abs(p.x() - dividerX()) < 6 &&
           imageRect().adjusted(0, -1, 0, 1).contains(QPointF(dividerX(), p.y()));
}

void PreviewView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(0x2b, 0x2b, 0x2b));
    if (m_imageSize.isEmpty()) {
        p.setPen(QColor(0x9a, 0x9a, 0x9a));
        p.drawText(rect(), Qt::AlignCenter,
                   tr("Open a screenshot or render (File > Open Image, or drop it here)"));
        return;
    }
    const QRectF r = imageRect();
    const bool smooth = zoom() < 1.0;
    p.setRenderHint(QPainter::SmoothPixmapTransform, smooth);
    auto drawClipped = [&](const QImage& img, const QRectF& clip) {
        if (img.isNull() || clip.isEmpty())
            return;
        p.save();
        p.setClipRect(clip);
        p.drawImage(r, img);
        p.restore();
    };
    // Until the graded frame is there (a picture just opened), the After side is a plain
    // placeholder, never the ungraded picture: it would flash the wrong look for a moment.
    const QImage& after = m_after;
    const QImage& clip = m_showClipping && !m_after.isNull() ? m_clip : QImage();
    auto placeholder = [&](const QRectF& area) {
        if (!m_after.isNull() || area.isEmpty())
            return;
        p.fillRect(area.intersected(QRectF(rect())), kPendingColour);
    };
    switch (m_mode) {
    case Mode::After:
        placeholder(r);
        drawClipped(after, r);
        drawClipped(clip, r);
        drawClipped(m_highlight, r);
        break;
    case Mode::Before:
        drawClipped(m_before, r);
        drawClipped(m_highlight, r);
        break;
    case Mode::Split: {
        const double dx = dividerX();
        drawClipped(m_before, QRectF(r.topLeft(), QPointF(dx, r.bottom())));
        placeholder(QRectF(QPointF(dx, r.top()), r.bottomRight()));
        drawClipped(after, QRectF(QPointF(dx, r.top()), r.bottomRight()));
        drawClipped(clip, QRectF(QPointF(dx, r.top()), r.bottomRight()));
        drawClipped(m_highlight, r);
        p.setRenderHint(QPainter::Antialiasing);
        const double top = std::max(0.0, r.top()), bottom = std::min<double>(height(), r.bottom());
        p.setPen(QPen(QColor(255, 255, 255, 220), 1.5));
        p.drawLine(QPointF(dx, top), QPointF(dx, bottom));
        // Handle and labels.
        const QPointF c(dx, (top + bottom) / 2);
        p.setBrush(QColor(255, 255, 255, 230));
        p.setPen(QPen(QColor(0, 0, 0, 120), 1));
        p.drawEllipse(c, 9, 9);
        p.setPen(QColor(40, 40, 40));
        p.drawText(QRectF(c.x() - 9, c.y() - 9, 18, 18), Qt::AlignCenter, QStringLiteral("↔"));
        QFont f = font();
        f.setBold(true);
        p.setFont(f);
        auto label = [&](const QString& text, double x, Qt::Alignment align) {
            const QRectF box(align & Qt::AlignRight ? x - 90 : x + 6, top + 6, 84, 20);
            p.setPen(Qt::NoPen);
            p.setBrush(QColor(0, 0, 0, 140));
            p.drawRoundedRect(box, 4, 4);
            p.setPen(Qt::white);
            p.drawText(box, Qt::AlignCenter, text);
        };
        if (dx - r.left() > 100)
            label(tr("Before"), dx - 6, Qt::AlignRight);
        if (r.right() - dx > 100)
            label(tr("After"), dx + 6, Qt::AlignLeft);
        break;
    }
    }
}

void PreviewView::resizeEvent(QResizeEvent*) {
    clampOffset();
    if (m_fit)
        emit zoomChanged(zoom());
}

void PreviewView::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    if (steps == 0)
        return;
    zoomTo(zoom() * std::pow(1.25, steps), e->position());
    e->accept();
}

void PreviewView::mousePressEvent(QMouseEvent* e) {
    m_dragStart = e->position();
    if (e->button() == Qt::LeftButton && nearDivider(e->position())) {
        m_drag = Drag::Divider;
    } else if (e->button() == Qt::LeftButton || e->button() == Qt::MiddleButton) {
        if (m_fit) { // start panning from the fitted position
            m_scale = zoom();
            m_offset = imageRect().topLeft();
            m_fit = false;
        }
        m_drag = Drag::Pan;
        m_offsetStart = m_offset;
        setCursor(Qt::ClosedHandCursor);
    }
}

void PreviewView::mouseMoveEvent(QMouseEvent* e) {
    const QPointF p = e->position();
    if (m_drag == Drag::Divider) {
        const QRectF r = imageRect();
        if (r.width() > 0)
            setSplit((p.x() - r.left()) / r.width());
    } else if (m_drag == Drag::Pan) {
        m_offset = m_offsetStart + (p - m_dragStart);
        clampOffset();
        update();
    } else {
        setCursor(nearDivider(p) ? Qt::SplitHCursor : Qt::CrossCursor);
    }
    const QRectF r = imageRect();
    if (r.contains(p)) {
        const double s = zoom();
        emit hoverPixel(
            std::clamp(static_cast<int>((p.x() - r.left()) / s), 0, m_imageSize.width() - 1),
            std::clamp(static_cast<int>((p.y() - r.top()) / s), 0, m_imageSize.height() - 1));
    } else {
        emit hoverPixel(-1, -1);
    }
}

void PreviewView::mouseReleaseEvent(QMouseEvent*) {
    m_drag = Drag::None;
    unsetCursor();
}

void PreviewView::leaveEvent(QEvent*) {
    emit hoverPixel(-1, -1);
}

} // namespace lut::gui
