// SPDX-License-Identifier: Apache-2.0
#include "CheckPanel.h"

#include "CheckModel.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace lut::gui {

namespace {

QColor statusColour(CheckStatus s) {
    return s == CheckStatus::Fail   ? QColor(0xf0, 0x60, 0x60)
           : s == CheckStatus::Warn ? QColor(0xf0, 0xb0, 0x40)
                                    : QColor(0x70, 0xd0, 0x80);
}

QString upper(const char* s) {
    return QString::fromLatin1(s).toUpper();
}

} // namespace

CheckPanel::CheckPanel(CheckModel* model, QWidget* parent) : QWidget(parent), m_model(model) {
    setObjectName("checkPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);
    m_verdict = new QLabel(tr("Checking…"), this);
    m_verdict->setObjectName("checkVerdict");
    m_verdict->setWordWrap(true);
    m_checks = new QLabel(this);
    m_checks->setObjectName("checkSummary");
    m_checks->setTextFormat(Qt::RichText);
    m_checks->setWordWrap(true);
    m_list = new QListWidget(this);
    m_list->setObjectName("checkFindings");
    m_list->setWordWrap(true);
    m_list->setToolTip(tr("Click a finding to highlight its colours on the picture"));
    m_overPicture = new QCheckBox(tr("Over the picture's colours"), this);
    m_overPicture->setObjectName("checkOverPicture");
    m_overPicture->setToolTip(tr("Weigh every finding by the picture's pixels and leave out what "
                                 "no pixel of it shows (lutkit check --image)"));
    m_highlightText = new QLabel(this);
    m_highlightText->setObjectName("checkHighlight");
    m_highlightText->setWordWrap(true);
    m_clear = new QPushButton(tr("Clear highlight"), this);
    m_clear->setEnabled(false);
    auto* h = new QHBoxLayout;
    h->addWidget(m_highlightText, 1);
    h->addWidget(m_clear);
    v->addWidget(m_verdict);
    v->addWidget(m_checks);
    v->addWidget(m_overPicture);
    v->addWidget(m_list, 1);
    v->addLayout(h);

    connect(m_model, &CheckModel::reportChanged, this, &CheckPanel::showReport);
    connect(m_model, &CheckModel::highlightReady, this, &CheckPanel::showHighlight);
    connect(m_list, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { onClicked(m_list->row(item)); });
    connect(m_clear, &QPushButton::clicked, this, [this] {
        m_list->clearSelection();
        m_model->requestHighlight(-1);
    });
    connect(m_overPicture, &QCheckBox::toggled, m_model, &CheckModel::setOverPicture);
}

QString CheckPanel::verdictText() const {
    return m_verdict->text();
}

void CheckPanel::showReport() {
    const auto report = m_model->report();
    m_list->clear();
    if (!report)
        return;
    const CheckStatus s = report->status();
    QStringList failing;
    for (const CheckSummary& c : report->checks)
        if (c.status != CheckStatus::Pass && c.kind != CheckKind::Neutral)
            failing << QString::fromLatin1(toString(c.kind));
    m_verdict->setText(
        s == CheckStatus::Pass
            ? tr("PASS: every check passes (%1)").arg(QString::fromStdString(report->description))
            : tr("%1: %2 (%3)")
                  .arg(upper(toString(s)), failing.join(QStringLiteral(", ")),
                       QString::fromStdString(report->description)));
    m_verdict->setStyleSheet(
        QStringLiteral("font-weight: bold; color: %1;").arg(statusColour(s).name()));
    // Two columns of "STATUS check"; the figures in the tooltip.
    QString rows = QStringLiteral("<table cellspacing='2'><tr>");
    QString tip;
    int column = 0;
    for (const CheckSummary& c : report->checks) {
        const bool info = c.kind == CheckKind::Neutral;
        rows += QStringLiteral("<td><span style='color:%1'>%2</span> %3&nbsp;&nbsp;</td>")
                    .arg(info ? QStringLiteral("#9a9a9a") : statusColour(c.status).name(),
                         info ? QStringLiteral("INFO") : upper(toString(c.status)),
                         QString::fromLatin1(toString(c.kind)));
        if (++column % 2 == 0)
            rows += QStringLiteral("</tr><tr>");
        tip += QStringLiteral("<b>%1</b> %2<br>")
                   .arg(QString::fromLatin1(toString(c.kind)),
                        QString::fromStdString(c.text).toHtmlEscaped());
    }
    m_checks->setText(rows + QStringLiteral("</tr></table>"));
    m_checks->setToolTip(tip);
    for (std::size_t i = 0; i < report->findings.size(); ++i) {
        const CheckFinding& f = report->findings[i];
        auto* item = new QListWidgetItem(
            QStringLiteral("%1  %2  %3 %4 %5 %6")
                .arg(i + 1)
                .arg(upper(toString(f.severity)), QString::fromLatin1(toString(f.kind)))
                .arg(f.size, 0, 'g', 3)
                .arg(QString::fromLatin1(toString(f.unit)), QString::fromStdString(f.where)),
            m_list);
        item->setForeground(statusColour(f.severity));
        item->setToolTip(QString::fromStdString(f.text(report->image)));
    }
    if (report->findingsLeftOut)
        new QListWidgetItem(
            tr("… and %1 more (lutkit check -v lists them)").arg(report->findingsLeftOut), m_list);
}

void CheckPanel::onClicked(int row) {
    const auto report = m_model->report();
    if (!report || row < 0 || row >= static_cast<int>(report->findings.size()))
        return;
    if (row == m_model->highlightedFinding()) { // a second click takes it away
        m_list->clearSelection();
        m_model->requestHighlight(-1);
        return;
    }
    m_highlightText->setText(tr("Finding the colours of %1…").arg(row + 1));
    m_model->requestHighlight(row);
}

void CheckPanel::showHighlight() {
    const int index = m_model->highlightedFinding();
    m_clear->setEnabled(index >= 0);
    if (index < 0)
        m_highlightText->clear();
    else
        m_highlightText->setText(tr("%1: %2 pixels of the picture highlighted")
                                     .arg(index + 1)
                                     .arg(m_model->highlightedPixels()));
    emit highlightChanged(m_model->highlight());
}

} // namespace lut::gui
