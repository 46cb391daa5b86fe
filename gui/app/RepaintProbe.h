// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measures how long the window's thread goes without painting: a small widget asks to be
// repainted every few milliseconds and records the longest gap between two of its paint events.
// Work on the UI thread (a file decoded there, a picture scaled at every paint, a wait for a
// worker) shows as a gap; work on a worker does not. The tests and the scripted mode
// (`probe on|off`) use it to check that no long task stalls the window for more than 100 ms.
//
// Two figures: the wall-clock gap, and the window's own gap, the same less the time its thread
// spent waiting for a CPU while other programs had them (the run-queue wait of
// /proc/thread-self/schedstat; Linux only, else the two are equal). On an idle machine they are
// the same; on a shared one (the CI's two cores with eight builds) the own gap is what the editor
// did, the rest is the machine.
#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

namespace lut::gui {

class RepaintProbe : public QWidget {
    Q_OBJECT
public:
    // A child of `host` (put it where it is visible: a status bar, a corner of the window).
    explicit RepaintProbe(QWidget* host, int intervalMs = 5);
    void start(); // forgets what was measured
    void stop();
    double longestGapMs() const { return m_longest; }
    double longestOwnGapMs() const { return m_longestOwn; }
    int paints() const { return m_paints; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_last = -1;
    double m_lastWait = 0; // run-queue wait of this thread at the last paint (ms)
    double m_longest = 0;
    double m_longestOwn = 0;
    int m_paints = 0;
    bool m_running = false;
};

} // namespace lut::gui
