// SPDX-License-Identifier: Apache-2.0
#include "TaskStatus.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace lut::gui {

TaskStatus::TaskStatus(const QString& name, QWidget* parent)
    : QWidget(parent), m_label(new QLabel(this)), m_bar(new QProgressBar(this)),
      m_cancel(new QToolButton(this)) {
    setObjectName(name);
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    h->setSpacing(4);
    m_bar->setObjectName(name + QStringLiteral(".bar"));
    m_bar->setRange(0, 0);
    m_bar->setMaximumWidth(90);
    m_bar->setMaximumHeight(16);
    m_bar->setTextVisible(false);
    m_cancel->setObjectName(name + QStringLiteral(".cancel"));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setAutoRaise(true);
    m_cancel->setToolTip(tr("Stop this task: nothing is written or changed"));
    h->addWidget(m_label);
    h->addWidget(m_bar);
    h->addWidget(m_cancel);
    connect(m_cancel, &QToolButton::clicked, this, &TaskStatus::cancelRequested);
    hide();
}

void TaskStatus::setBusy(bool busy) {
    if (!busy)
        setFraction(0.0);
    setVisible(busy);
}

void TaskStatus::setText(const QString& text) {
    // A long file name is elided in the middle to keep the status bar's other fields; the
    // tooltip has it whole.
    m_text = text;
    m_label->setText(m_label->fontMetrics().elidedText(text, Qt::ElideMiddle, 180));
    m_label->setToolTip(text);
}

QString TaskStatus::text() const {
    return m_text;
}

void TaskStatus::setFraction(double fraction) {
    if (!(fraction > 0.0)) {
        if (m_bar->maximum() != 0)
            m_bar->setRange(0, 0); // busy: nothing reported yet
        return;
    }
    if (m_bar->maximum() != 1000) {
        m_bar->setRange(0, 1000);
        m_bar->setTextVisible(true);
    }
    m_bar->setValue(static_cast<int>(std::lround(std::min(1.0, fraction) * 1000)));
    m_bar->setFormat(QStringLiteral("%1 %").arg(static_cast<int>(std::min(1.0, fraction) * 100)));
}

} // namespace lut::gui
