// SPDX-License-Identifier: Apache-2.0
#include "RepaintProbe.h"

#include <QPainter>

#include <algorithm>
#include <cstdio>

namespace lut::gui {

namespace {

// Time the calling thread has waited for a CPU (ms), 0 where the kernel does not say.
double runQueueWaitMs() {
    std::FILE* f = std::fopen("/proc/thread-self/schedstat", "r");
    if (!f)
        return 0.0;
    unsigned long long onCpu = 0, waiting = 0;
    const int n = std::fscanf(f, "%llu %llu", &onCpu, &waiting);
    std::fclose(f);
    return n == 2 ? static_cast<double>(waiting) / 1e6 : 0.0;
}

} // namespace

RepaintProbe::RepaintProbe(QWidget* host, int intervalMs) : QWidget(host) {
    setObjectName("repaintProbe");
    setFixedSize(6, 6);
    m_timer.setInterval(intervalMs);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, qOverload<>(&QWidget::update));
}

void RepaintProbe::start() {
    m_last = -1;
    m_longest = 0;
    m_longestOwn = 0;
    m_paints = 0;
    m_running = true;
    m_clock.start();
    m_timer.start();
    show();
    update();
}

void RepaintProbe::stop() {
    m_running = false;
    m_timer.stop();
    // The gap up to now counts too: a stall that is still going on is a stall.
    if (m_last >= 0) {
        const double gap = m_clock.nsecsElapsed() / 1e6 - m_last;
        m_longest = std::max(m_longest, gap);
        m_longestOwn = std::max(m_longestOwn, gap - (runQueueWaitMs() - m_lastWait));
    }
}

void RepaintProbe::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), (m_paints & 1) ? QColor(0x30, 0x30, 0x34) : QColor(0x38, 0x38, 0x3c));
    if (!m_running)
        return;
    const double now = m_clock.nsecsElapsed() / 1e6, wait = runQueueWaitMs();
    if (m_last >= 0) {
        m_longest = std::max(m_longest, now - m_last);
        m_longestOwn = std::max(m_longestOwn, now - m_last - (wait - m_lastWait));
    }
    m_last = now;
    m_lastWait = wait;
    ++m_paints;
}

} // namespace lut::gui
