// SPDX-License-Identifier: Apache-2.0
#include "ScopesView.h"

#include <QHBoxLayout>
#include <QPainter>
#include <QPainterPath>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lut::gui {

namespace {

constexpr int kButtonRow = 24; // the toggle buttons' strip on top
constexpr int kTextRow = 18;   // the clipping line at the bottom

} // namespace

ScopesView::ScopesView(QWidget* parent) : QWidget(parent) {
    setObjectName("scopes");
    setMinimumSize(200, 180);
    auto* row = new QHBoxLayout;
    row->setContentsMargins(4, 2, 4, 0);
    row->setSpacing(2);
    const char* names[4] = {"scope.histogram", "scope.parade", "scope.waveform",
                            "scope.vectorscope"};
    const QString labels[4] = {tr("Histogram"), tr("Parade"), tr("Waveform"), tr("Vectorscope")};
    const QString tips[4] = {
        tr("Counts of each level of R, G, B and luma"),
        tr("R, G and B levels across the picture, side by side"),
        tr("Luma levels across the picture (Rec. 709), with 0, 25, 50, 75 and 100 % lines"),
        tr("Hue and saturation (Rec. 709 Cb, Cr): the 75 % colour targets and the skin-tone "
           "line, where faces fall")};
    for (int i = 0; i < 4; ++i) {
        auto* b = new QToolButton(this);
        b->setObjectName(QString::fromLatin1(names[i]));
        b->setText(labels[i]);
        b->setToolTip(tips[i]);
        b->setCheckable(true);
        b->setChecked(i >= 2); // the waveform and the vectorscope, as grading tools open
        b->setAutoRaise(true);
        b->setStyleSheet(QStringLiteral("QToolButton:checked { background: #3d8ee6; color: white; "
                                        "border-radius: 3px; }"));
        connect(b, &QToolButton::toggled, this, qOverload<>(&QWidget::update));
        row->addWidget(b);
        m_buttons[i] = b;
    }
    row->addStretch(1);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addLayout(row);
    v->addStretch(1);
}

void ScopesView::setScopes(const Scopes& scopes) {
    m_scopes = scopes;
    update();
}

void ScopesView::clear() {
    m_scopes = Scopes{};
    update();
}

void ScopesView::setShown(Kind kind, bool on) {
    m_buttons[static_cast<int>(kind)]->setChecked(on);
}

bool ScopesView::isShown(Kind kind) const {
    return m_buttons[static_cast<int>(kind)]->isChecked();
}

QString ScopesView::clipText() const {
    if (!m_scopes.pixels)
        return tr("no picture");
    const double n = double(m_scopes.pixels);
    return tr("clipped: %1 % at 255, %2 % at 0")
        .arg(100.0 * m_scopes.clippedHigh / n, 0, 'f', 2)
        .arg(100.0 * m_scopes.clippedLow / n, 0, 'f', 2);
}

QRectF ScopesView::canvas() const {
    return QRectF(4, kButtonRow + 4, width() - 8, height() - kButtonRow - kTextRow - 8);
}

void ScopesView::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    update();
}

QRectF ScopesView::scopeRect(Kind kind) const {
    if (!isShown(kind))
        return {};
    // The shown scopes share the canvas: side by side when it is wide, else stacked; the
    // vectorscope keeps its square, centred in its share.
    int count = 0;
    for (int k = 0; k < 4; ++k)
        count += isShown(static_cast<Kind>(k));
    const QRectF c = canvas();
    const bool across = c.width() > c.height() * 1.6;
    const double gap = 6;
    // The vectorscope takes the square it needs (at most an even share), the others the rest.
    const bool vector = isShown(Kind::Vectorscope);
    const double length = (across ? c.width() : c.height()) - gap * (count - 1);
    const double vectorLength =
        !vector      ? 0.0
        : count == 1 ? length
                     : std::min(across ? c.height() : c.width(), length * (count == 2 ? 0.5 : 0.4));
    const double other =
        count > (vector ? 1 : 0) ? (length - vectorLength) / (count - (vector ? 1 : 0)) : 0.0;
    double start = 0.0;
    for (int k = 0; k < 4 && k < static_cast<int>(kind); ++k)
        if (isShown(static_cast<Kind>(k)))
            start += (static_cast<Kind>(k) == Kind::Vectorscope ? vectorLength : other) + gap;
    const double size = kind == Kind::Vectorscope ? vectorLength : other;
    QRectF r = across ? QRectF(c.left() + start, c.top(), size, c.height())
                      : QRectF(c.left(), c.top() + start, c.width(), size);
    if (kind == Kind::Vectorscope) {
        const double side = std::min(r.width(), r.height()) - 2;
        r = QRectF(r.center().x() - side / 2, r.center().y() - side / 2, side, side);
    }
    return r;
}

QPointF ScopesView::vectorscopePoint(double cb, double cr) const {
    const QRectF r = scopeRect(Kind::Vectorscope);
    return {r.left() + (cb + 0.5) * r.width(), r.top() + (0.5 - cr) * r.height()};
}

void ScopesView::drawHistogram(QPainter& p, const QRectF& hist) const {
    // Square-root scale so the small bins show next to a large one.
    std::uint32_t peak = 1;
    for (int c = 0; c < 4; ++c)
        for (int i = 1; i < 255; ++i) // the end bins (clipping) would flatten the rest
            peak = std::max(peak, m_scopes.histogram[c][i]);
    const QColor colors[4] = {QColor(255, 70, 70, 150), QColor(70, 230, 70, 150),
                              QColor(90, 120, 255, 150), QColor(230, 230, 230, 200)};
    p.save();
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
    p.restore();
}

void ScopesView::drawParade(QPainter& p, const QRectF& r) const {
    p.save();
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(r.adjusted(1, 1, -1, -1), m_scopes.parade);
    p.restore();
}

void ScopesView::drawWaveform(QPainter& p, const QRectF& r) const {
    p.save();
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    if (!m_scopes.waveformImage.isNull())
        p.drawImage(r.adjusted(1, 1, -1, -1), m_scopes.waveformImage);
    // 0, 25, 50, 75, 100 % of the 8-bit range.
    QFont f = font();
    f.setPointSizeF(std::max(6.0, f.pointSizeF() * 0.75));
    p.setFont(f);
    for (int q = 0; q <= 4; ++q) {
        const double y = r.bottom() - 1 - (r.height() - 2) * q / 4.0;
        p.setPen(QPen(QColor(255, 255, 255, q == 0 || q == 4 ? 70 : 40), 1, Qt::DashLine));
        p.drawLine(QPointF(r.left() + 1, y), QPointF(r.right() - 1, y));
        p.setPen(QColor(200, 200, 200, 150));
        p.drawText(QPointF(r.left() + 3, q == 4 ? y + 10 : y - 2), QString::number(q * 25));
    }
    p.restore();
}

void ScopesView::drawVectorscope(QPainter& p, const QRectF& r) const {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.setBrush(QColor(0x10, 0x10, 0x12));
    p.setPen(QPen(QColor(70, 70, 76), 1));
    p.drawEllipse(r);
    if (!m_scopes.vectorscopeImage.isNull()) {
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(r, m_scopes.vectorscopeImage);
    }
    const QPointF centre = vectorscopePoint(0, 0);
    p.setPen(QPen(QColor(120, 120, 128), 1));
    p.drawLine(vectorscopePoint(-0.5, 0), vectorscopePoint(0.5, 0));
    p.drawLine(vectorscopePoint(0, -0.5), vectorscopePoint(0, 0.5));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(centre, r.width() / 4, r.height() / 4);
    // The skin-tone line, from the centre to the edge.
    const double a = kSkinToneDegrees * std::numbers::pi / 180.0;
    p.setPen(QPen(QColor(255, 200, 150), 1.5));
    p.drawLine(centre, vectorscopePoint(0.5 * std::cos(a), 0.5 * std::sin(a)));
    // The 75 % primaries and secondaries: where pure colours of the picture fall.
    struct Target {
        int r, g, b;
        const char* label;
    };
    const Target targets[] = {{191, 0, 0, "R"},    {191, 191, 0, "Yl"}, {0, 191, 0, "G"},
                              {0, 191, 191, "Cy"}, {0, 0, 191, "B"},    {191, 0, 191, "Mg"}};
    QFont f = font();
    f.setPointSizeF(std::max(6.0, f.pointSizeF() * 0.75));
    p.setFont(f);
    for (const Target& t : targets) {
        double cb, cr;
        vectorscopeCbCr(t.r, t.g, t.b, &cb, &cr);
        const QPointF at = vectorscopePoint(cb, cr);
        const QColor c(std::max(t.r, 90), std::max(t.g, 90), std::max(t.b, 90));
        p.setPen(QPen(c, 1));
        p.drawRect(QRectF(at.x() - 4, at.y() - 4, 8, 8));
        p.drawText(at + QPointF(6, 4), QString::fromLatin1(t.label));
    }
    p.restore();
}

void ScopesView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(0x18, 0x18, 0x1a));
    const bool any = m_scopes.pixels != 0;
    for (int k = 0; k < 4; ++k) {
        const Kind kind = static_cast<Kind>(k);
        const QRectF r = scopeRect(kind);
        if (r.isEmpty())
            continue;
        if (kind != Kind::Vectorscope) {
            p.setPen(QColor(60, 60, 64));
            p.setBrush(Qt::NoBrush);
            p.drawRect(r);
        }
        if (!any && kind != Kind::Vectorscope)
            continue;
        switch (kind) {
        case Kind::Histogram:
            drawHistogram(p, r);
            break;
        case Kind::Parade:
            drawParade(p, r);
            break;
        case Kind::Waveform:
            drawWaveform(p, r);
            break;
        case Kind::Vectorscope:
            drawVectorscope(p, r);
            break;
        }
    }
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(4, height() - kTextRow, width() - 8, kTextRow),
               Qt::AlignLeft | Qt::AlignVCenter, clipText());
}

} // namespace lut::gui
