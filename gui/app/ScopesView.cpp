#include "ScopesView.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace lut::gui {

ScopesView::ScopesView(QWidget* parent) : QWidget(parent) {
    setObjectName("scopes");
    setMinimumSize(200, 180);
}

void ScopesView::setScopes(const Scopes& scopes) {
    m_scopes = scopes;
    update();
}

void ScopesView::clear() {
    m_scopes = Scopes{};
    update();
}

QString ScopesView::clipText() const {
    if (!m_scopes.pixels)
        return tr("no picture");
    const double n = double(m_scopes.pixels);
    return tr("clipped: %1 % at 255, %2 % at 0")
        .arg(100.0 * m_scopes.clippedHigh / n, 0, 'f', 2)
        .arg(100.0 * m_scopes.clippedLow / n, 0, 'f', 2);
}

void ScopesView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(0x18, 0x18, 0x1a));
    const int textH = 18;
    const int h = (height() - textH) / 2;
    const QRectF hist(4, 4, width() - 8, h - 8);
    const QRectF parade(4, h + 4, width() - 8, h - 8);
    p.setPen(QColor(60, 60, 64));
    p.drawRect(hist);
    p.drawRect(parade);
    if (m_scopes.pixels) {
        // Histogram: square-root scale so the small bins show next to a large one.
        std::uint32_t peak = 1;
        for (int c = 0; c < 4; ++c)
            for (int i = 1; i < 255; ++i) // the end bins (clipping) would flatten the rest
                peak = std::max(peak, m_scopes.histogram[c][i]);
        const QColor colors[4] = {QColor(255, 70, 70, 150), QColor(70, 230, 70, 150),
                                  QColor(90, 120, 255, 150), QColor(230, 230, 230, 200)};
        p.setRenderHint(QPainter::Antialiasing);
        for (int c = 0; c < 4; ++c) {
            QPainterPath path(QPointF(hist.left(), hist.bottom()));
            for (int i = 0; i < 256; ++i) {
                const double v = std::sqrt(std::min(1.0, double(m_scopes.histogram[c][i]) / peak));
                path.lineTo(hist.left() + hist.width() * (i + 0.5) / 256,
                            hist.bottom() - v * hist.height());
            }
            path.lineTo(hist.right(), hist.bottom());
            if (c < 3) {
                p.setPen(Qt::NoPen);
                p.setBrush(colors[c]);
            } else {
                p.setPen(QPen(colors[c], 1));
                p.setBrush(Qt::NoBrush);
            }
            p.drawPath(path);
        }
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(parade.adjusted(1, 1, -1, -1), m_scopes.parade);
    }
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(4, height() - textH, width() - 8, textH), Qt::AlignLeft | Qt::AlignVCenter,
               clipText());
}

} // namespace lut::gui
