// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the editor's actions (FileActions, WindowActions) ask of the window they run in: whether a
// person is there to answer questions, where errors, notes and status messages go, and the status
// bar's progress indicators. MainWindow implements it; the actions hold it beside the document and
// the preview controller (EditorContext) and reach the window through nothing else, so the same
// actions run under a test's prompts or a script's.
#include "ExportTarget.h"

#include "lut/LutPurpose.h"

#include <QString>
#include <QStringList>

#include <optional>

class QWidget;

namespace lut::gui {

class BackgroundTask;
class Document;
class PreviewController;
class TaskStatus;

class Prompts {
public:
    virtual ~Prompts() = default;

    // false: no question is asked, errors and notes go to stderr, no setting is written (tests,
    // --screenshot, --save-preview, scripts).
    virtual bool interactive() const = 0;
    // The parent of the dialogs the actions open (file choosers, questions, reports).
    virtual QWidget* dialogParent() = 0;
    // Shows (dialog or stderr) and remembers an error.
    virtual void reportError(const QString& title, const QString& message) = 0;
    // What a reader or writer noted (the notes bar; stderr when headless).
    virtual void showNotes(const QStringList& notes) = 0;
    // A passing message in the status bar.
    virtual void showStatus(const QString& message) = 0;
    // What a LUT file that does not say what it is for is taken for without asking (--lut-target,
    // the script command lut-target); nullopt: ask when interactive.
    virtual std::optional<LutPurpose> lutPurposeAnswer() const = 0;
    // The failing checks of the LUT `target` exports (lutkit check), one line each.
    virtual QStringList checkWarnings(ExportTarget target) const = 0;

    // The status bar's indicator of files being read (with Cancel).
    virtual TaskStatus* loadingStatus() const = 0;
    virtual void setLoading(bool busy) = 0;
    virtual void setLoadingText(const QString& text) = 0;
    // Shows a long task in the status bar while it runs: its label, progress and Cancel.
    virtual TaskStatus* watchTask(BackgroundTask* task, const QString& name) = 0;
};

// What the actions work on: the model (the document, the preview and its target's export) and the
// window's prompts.
struct EditorContext {
    Document* document = nullptr;
    PreviewController* preview = nullptr;
    Prompts* prompts = nullptr;
};

} // namespace lut::gui
