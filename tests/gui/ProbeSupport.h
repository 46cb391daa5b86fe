// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor tests' repaint probe (RepaintProbe.h) in a window, what "no stall" means here, and
// waiting for a condition while the window's events run (tests that link lutkit_gui_widgets).
#include "MainWindow.h"
#include "RepaintProbe.h"
#include "TaskStatus.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QStatusBar>
#include <QToolButton>
#include <QtTest>

namespace lut::gui::test {

// The window's repaint probe, in the status bar where it is always visible.
inline RepaintProbe* probeIn(MainWindow& w) {
    auto* probe = new RepaintProbe(w.statusBar());
    w.statusBar()->addPermanentWidget(probe);
    QApplication::processEvents();
    return probe;
}

// No stall: the window's own gaps between repaints (RepaintProbe.h: the wall-clock gap less the
// time its thread waited for a CPU taken by other programs; on an idle machine the same) stay
// under 400 ms, and no gap reaches a second whatever the machine does. What this catches is work
// moved onto the window's thread: decoding the 8192x8192 picture or encoding the 4K preview there
// takes most of a second or more. The editor's own target, 100 ms, is a measurement (the probe's
// scripted mode, docs/editor.md), not asserted here: these tests run beside others on two cores,
// where the window's thread was seen to lose 130-200 ms of its own (its gaps idle: 7-45 ms), e.g.
// while a worker gives back the cancelled picture's gigabyte. `minPaints`: how many paints show
// that the probe watched the task (it repaints every 5 ms: a task that ends within 50 ms, as a
// small picture's may on an idle machine, gives fewer than 11; two give one gap).
inline bool noStall(const RepaintProbe& p, int minPaints = 11) {
    return p.paints() >= minPaints && p.longestOwnGapMs() < 400.0 && p.longestGapMs() < 1000.0;
}

inline QString stallText(const RepaintProbe& p) {
    return QStringLiteral("longest repaint gap %1 ms (own %2 ms) over %3 paints")
        .arg(p.longestGapMs(), 0, 'f', 1)
        .arg(p.longestOwnGapMs(), 0, 'f', 1)
        .arg(p.paints());
}

inline TaskStatus* statusOf(MainWindow& w, const char* name) {
    return w.statusBar()->findChild<TaskStatus*>(QString::fromLatin1(name));
}

// Processes events until `done` or `ms` pass.
template <class F> bool waitFor(F done, int ms) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > ms)
            return false;
        QApplication::processEvents(QEventLoop::AllEvents, 5);
        QTest::qWait(2);
    }
    return true;
}

} // namespace lut::gui::test
