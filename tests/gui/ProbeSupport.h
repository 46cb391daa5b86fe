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

// The probe watched the task: the window repainted all along it, at least `minPaints` times (it
// repaints every 5 ms while its thread is free: a task that ends within 50 ms, as a small
// picture's may on an idle machine, gives fewer than 11; two give one gap). How long the longest
// gap was is a measurement, not asserted in a test (no time is: two cores shared with other
// tests): the tests log it (stallText), and bench/editor_probe.sh measures it alone on the machine
// against the editor's target, 100 ms of the window's own. A task moved onto the window's thread
// (decoding the 8192x8192 picture, encoding the 4K preview) shows there as gaps of most of a
// second, and here as too few paints.
inline bool repaintedThroughout(const RepaintProbe& p, int minPaints = 11) {
    return p.paints() >= minPaints;
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
