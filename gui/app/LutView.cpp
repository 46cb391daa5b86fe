// SPDX-License-Identifier: Apache-2.0
#include "LutView.h"

#include "PreviewFrame.h"

#include "lut/Version.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

#include <cmath>

namespace lut::gui {

// Draws the strip scaled to the widget width, nearest neighbour, keeping its aspect.
class StripWidget : public QWidget {
public:
    explicit StripWidget(QWidget* parent) : QWidget(parent) {
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
        setMinimumHeight(40);
    }
    void setImage(QImage img) {
        m_image = std::move(img);
        updateGeometry();
        update();
    }
    const QImage& image() const { return m_image; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override {
        if (m_image.isNull())
            return 40;
        return std::max(
            24, static_cast<int>(std::lround(double(w) * m_image.height() / m_image.width())));
    }
    QSize sizeHint() const override { return {320, heightForWidth(320)}; }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.fillRect(rect(), QColor(0x20, 0x20, 0x20));
        if (m_image.isNull())
            return;
        const double s =
            std::min(double(width()) / m_image.width(), double(height()) / m_image.height());
        const QSizeF sz(m_image.width() * s, m_image.height() * s);
        const QRectF r(QPointF((width() - sz.width()) / 2, (height() - sz.height()) / 2), sz);
        p.setRenderHint(QPainter::SmoothPixmapTransform, false);
        p.drawImage(r, m_image);
    }

private:
    QImage m_image;
};

LutView::LutView(QWidget* parent) : QWidget(parent) {
    auto* v = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_layout = new QComboBox(this);
    for (LutLayout l : allLayouts())
        if (layoutFixedSize(l) == 0) // reshade, unity-32: unreal's and unity's pixels at 32^3
            m_layout->addItem(QString::fromLatin1(toString(l)), int(l));
    m_layout->setToolTip(tr("Layout of the slices (see %1/docs/specs/strip-layouts.md)")
                             .arg(QStringLiteral(LUTKIT_DOC_DIR)));
    form->addRow(tr("Layout"), m_layout);
    m_wrap = new QCheckBox(tr("Show slices as a grid"), this);
    m_wrap->setChecked(true);
    m_wrap->setToolTip(tr("Display only: the exported strip is one row of slices"));
    form->addRow(QString(), m_wrap);
    connect(m_wrap, &QCheckBox::toggled, this, [this] { refresh(); });
    v->addLayout(form);
    m_strip = new StripWidget(this);
    v->addWidget(m_strip);
    m_info = new QLabel(this);
    m_info->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_info->setWordWrap(true);
    v->addWidget(m_info);
    v->addStretch(1);
    connect(m_layout, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
}

void LutView::setFileLayout(std::optional<LutLayout> layout) {
    if (!layout)
        return;
    const int i = m_layout->findData(int(layoutPlacement(*layout)));
    if (i >= 0)
        m_layout->setCurrentIndex(i);
}

LutLayout LutView::layout() const {
    return static_cast<LutLayout>(m_layout->currentData().toInt());
}

const QImage& LutView::stripImage() const {
    return m_strip->image();
}

void LutView::setLut(const Lut3D& lut, const QString& origin, const QString& extraHtml) {
    m_lut = lut;
    m_origin = origin;
    m_extra = extraHtml;
    refresh();
}

QImage LutView::wrapSlices(const QImage& strip, int n) {
    if (n <= 0 || strip.width() != n * n || strip.height() != n)
        return strip;
    const int cols = static_cast<int>(std::ceil(std::sqrt(double(n))));
    const int rows = (n + cols - 1) / cols;
    const int gap = 1;
    QImage out(cols * (n + gap) - gap, rows * (n + gap) - gap, strip.format());
    out.fill(QColor(0x20, 0x20, 0x20));
    QPainter p(&out);
    for (int k = 0; k < n; ++k)
        p.drawImage(QPoint((k % cols) * (n + gap), (k / cols) * (n + gap)), strip,
                    QRect(k * n, 0, n, n));
    return out;
}

void LutView::refresh() {
    if (m_lut.empty()) {
        m_strip->setImage({});
        m_info->clear();
        return;
    }
    QString note;
    try {
        QImage img = toDisplayImage(lutToImage(m_lut, layout()));
        if (m_wrap->isChecked() && layout() != LutLayout::Hald)
            img = wrapSlices(img, m_lut.size());
        m_strip->setImage(img);
    } catch (const std::exception& e) { // Hald needs N = L^2
        m_strip->setImage({});
        note = QStringLiteral("<br><i>%1</i>").arg(QString::fromUtf8(e.what()).toHtmlEscaped());
    }
    const glm::vec3 dmin = m_lut.domainMin(), dmax = m_lut.domainMax();
    const auto range = m_lut.valueRange();
    const float dev = m_lut.maxDeviationFromIdentity();
    const int n = m_lut.size();
    m_info->setText(
        tr("<b>Size</b> %1 (%2 entries)<br><b>Domain</b> [%3 %4 %5] .. [%6 %7 %8]<br>"
           "<b>Title</b> %9<br><b>Neutral</b> %10<br><b>Values</b> %11 .. %12<br><b>From</b> %13")
            .arg(QString::number(n) + QChar(0x00B3))
            .arg(qulonglong(m_lut.entryCount()))
            .arg(dmin.x)
            .arg(dmin.y)
            .arg(dmin.z)
            .arg(dmax.x)
            .arg(dmax.y)
            .arg(dmax.z)
            .arg(m_lut.title().empty() ? tr("(none)")
                                       : QString::fromStdString(m_lut.title()).toHtmlEscaped())
            .arg(dev <= 1e-6f ? tr("yes") : tr("no (max deviation %1)").arg(double(dev), 0, 'g', 3))
            .arg(double(range.first), 0, 'g', 4)
            .arg(double(range.second), 0, 'g', 4)
            .arg(m_origin.toHtmlEscaped()) +
        (m_extra.isEmpty() ? QString() : QStringLiteral("<br>") + m_extra) + note);
}

} // namespace lut::gui
