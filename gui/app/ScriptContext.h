// SPDX-License-Identifier: Apache-2.0
#pragma once
// What one line of an editor script (ScriptRunner.h) runs with: the window, the line's arguments,
// the script's output and its session (the dialog responder, the repaint probe), and the helpers
// every command shares (an argument or a clear failure, the preview's options changed, "failed"
// or the window's new error). A command fails by throwing ScriptFailure: the runner prints
// "script:LINE: COMMAND: reason" and ends the run with 1.
#include "AdjustParam.h"
#include "Document.h"
#include "PreviewController.h"

#include <QStringList>
#include <QTextStream>

#include <functional>
#include <stdexcept>

namespace lut::gui {

class BackgroundTask;
class DialogResponder;
class MainWindow;
class RepaintProbe;
struct ExportChoice;

struct ScriptFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws ScriptFailure(why) unless ok.
void need(bool ok, const QString& why);
// "on" or "off", else a failure.
bool onOff(const QString& v);
QString onOffText(bool v);

// What lives from the script's first line to its last.
struct ScriptSession {
    MainWindow& window;
    QTextStream& out;
    DialogResponder& responder;
    RepaintProbe* probe = nullptr; // made by `probe on`, a child of the window's status bar
};

struct ScriptContext {
    ScriptContext(ScriptSession& session, QStringList arguments);

    ScriptSession& session;
    MainWindow& w;
    QTextStream& out;
    QStringList args;
    QString error0; // the window's last error before the command

    Document* doc() const;
    PreviewController* preview() const;
    // Argument i (from 0), else "missing argument i+1".
    QString arg(int i) const;
    // The preview's options, changed by `change`.
    void setOptions(const std::function<void(PreviewOptions&)>& change) const;
    // Fails unless ok, with the window's new error (else "failed").
    void noNewError(bool ok) const;
};

// Every long task finished and the preview current (what a user waits for before looking).
void settle(MainWindow& w);
// The long tasks by the names scripts use: compare, match, save-preview (load: FileLoader).
BackgroundTask* taskByName(MainWindow& w, const QString& name);
// "idle", "idle done|cancelled|failed" or "busy N %".
QString taskState(MainWindow& w, const QString& name);
const AdjustParamInfo& paramByKey(const QString& key);
CurveId curveByName(const QString& name);
// The visible (or visible in the window) widget of that object name.
QWidget* widgetByName(MainWindow& w, const QString& name);
// The export dialog's suggested path and choice for the document now.
QString suggestedExport(MainWindow& w, ExportChoice* choice);

} // namespace lut::gui
