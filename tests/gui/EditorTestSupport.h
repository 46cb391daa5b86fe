// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the editor tests that drive the window (lutkit_gui_widgets) share: a program run to the end
// (the CLI, lutkit-editor, xvfb-run), an editor script written and run, a dialog answered as a
// user does, the window made active again (GuiTestSupport.h: what the model tests share too).
#include "TestPaths.h"

#include <QApplication>
#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QStringList>
#include <QTemporaryDir>
#include <QTimer>
#include <QWidget>

namespace lut::gui::test {

struct Run {
    int code = -1; // -1: crashed or timed out
    QString out, err;
};

// Runs `program` to its end (4 minutes at most).
inline Run run(const QString& program, const QStringList& args,
               const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment()) {
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, args);
    Run r;
    if (!p.waitForFinished(240000)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timed out");
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromLocal8Bit(p.readAllStandardOutput());
    r.err = QString::fromLocal8Bit(p.readAllStandardError());
    return r;
}

// An editor script (gui/app/ScriptRunner.h) of `lines` in dir/name; returns its path.
inline QString writeScript(const QTemporaryDir& dir, const QString& name,
                           const QStringList& lines) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly | QIODevice::Text))
        f.write(lines.join('\n').toUtf8() + "\n");
    return path;
}

// lutkit-editor --script (offscreen, as ctest runs it) over `lines`, `files` opened first.
inline Run runEditorScript(const QTemporaryDir& dir, const QStringList& lines,
                           const QStringList& files = {}) {
    return run(QString::fromUtf8(LUTKIT_EDITOR),
               QStringList{"--script", writeScript(dir, QStringLiteral("script.txt"), lines)} +
                   files);
}

inline QByteArray fileBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Runs `check` on the next visible top-level widget of type T (polling the event loop), as a
// user answers a dialog; one never shown within `withinMs` is not waited for (so a later test's
// dialog is not answered).
template <class T, class F> void onNextDialog(F check, int withinMs = 8000) {
    auto* timer = new QTimer;
    timer->setInterval(20);
    auto* expiry = new QElapsedTimer;
    expiry->start();
    QObject::connect(timer, &QTimer::timeout, [timer, expiry, check, withinMs] {
        if (expiry->elapsed() > withinMs) {
            timer->stop();
            timer->deleteLater();
            delete expiry;
            return;
        }
        for (QWidget* top : QApplication::topLevelWidgets())
            if (auto* d = qobject_cast<T*>(top); d && d->isVisible()) {
                timer->stop();
                timer->deleteLater();
                delete expiry;
                check(d);
                return;
            }
    });
    timer->start();
}

// After a modal dialog the window manager gives the main window the focus back; offscreen there
// is none, so the tests do it.
inline void activate(QWidget& w) {
    QApplication::setActiveWindow(&w);
    QApplication::processEvents();
}

} // namespace lut::gui::test
