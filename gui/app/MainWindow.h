// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor window: preview (centre) under a notes bar, adjustments / curves / wheels / LUT /
// scopes / history docks, status bar. The state lives in the model (Document: the LUT and the
// picture; PreviewController: the preview and the target's export); the window lays out the
// widgets and wires them to the model. Menus and toolbars are WindowActions, opening and writing
// files is FileActions; both work on the model and ask and report through the window's Prompts
// (Prompts.h), never through the window itself.
#include "PreviewController.h"
#include "Prompts.h"

#include "lut/LutPurpose.h"
#include "lut/io/Format.h"
#include "lut/ops/Strength.h"

#include <QMainWindow>
#include <QStringList>

#include <memory>
#include <optional>

class QLabel;
class QProgressBar;
class QToolButton;
class QUndoView;

namespace lut::gui {

class AdjustmentsPanel;
class BackgroundTask;
class TaskStatus;
class CheckModel;
class CheckPanel;
class CurvesPanel;
class Document;
class FileActions;
class LutView;
class PreviewView;
class ScopesView;
class WheelsPanel;
class WindowActions;

class MainWindow : public QMainWindow, public Prompts {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return m_doc; }
    PreviewController* preview() const { return m_preview; }
    FileActions* fileActions() const { return m_files; }
    WindowActions* windowActions() const { return m_actions; }
    AdjustmentsPanel* adjustmentsPanel() const { return m_adjust; }
    CurvesPanel* curvesPanel() const { return m_curves; }
    WheelsPanel* wheelsPanel() const { return m_wheels; }
    PreviewView* previewView() const { return m_view; }
    LutView* lutView() const { return m_lutView; }
    ScopesView* scopesView() const { return m_scopes; }
    CheckPanel* checkPanel() const { return m_check; }
    // The failing checks of the LUT the preview's target exports (lutkit check), one line each:
    // what an export of that target warns about.
    QStringList checkWarnings(ExportTarget target) const override;

    // false: errors go to stderr and lastError() instead of a dialog, no question is asked and
    // no setting is written (tests, --screenshot, --save-preview, scripts).
    void setInteractiveErrors(bool on) { m_interactiveErrors = on; }
    bool interactiveErrors() const { return m_interactiveErrors; }
    // Prompts: the window answers for its actions.
    bool interactive() const override { return m_interactiveErrors; }
    QWidget* dialogParent() override { return this; }
    void showStatus(const QString& message) override;
    QString lastError() const { return m_lastError; }
    // What a LUT file that does not say what it is for is taken for, without asking
    // (lutkit-editor --lut-target, the script command lut-target); nullopt: ask (interactive),
    // else take it as an edit.
    void setLutPurposeAnswer(std::optional<LutPurpose> answer) { m_purposeAnswer = answer; }
    std::optional<LutPurpose> lutPurposeAnswer() const override { return m_purposeAnswer; }
    // Shows (dialog or stderr) and remembers an error.
    void reportError(const QString& title, const QString& message) override;
    // Shows what a reader or writer noted (the notes bar; stderr when headless).
    void showNotes(const QStringList& notes) override;
    QString notesText() const;
    void setVerbose(bool on) { m_verbose = on; }
    // The status bar's progress indicator while files load on the worker (with Cancel).
    void setLoading(bool busy) override;
    void setLoadingText(const QString& text) override;
    bool isLoading() const;
    // Shows a long task in the status bar while it runs: its label, progress and Cancel.
    TaskStatus* watchTask(BackgroundTask* task, const QString& name) override;
    TaskStatus* loadingStatus() const override { return m_loading; }
    // Processes events until the file reads in flight are done and adopted.
    void waitForLoads();

    // The file operations (FileActions); the open forms wait for the worker's read. Each returns
    // false after reporting the error and leaves the document as it was.
    bool openImageFile(const QString& path);
    bool openLutFile(const QString& path, const FormatOptions& options = {});
    bool openScreenshotLut(const QString& path);
    bool exportLut(const QString& path, const QString& format, const FormatOptions& options,
                   ExportTarget target, bool overwrite = false,
                   const StrengthOptions& strength = {});
    bool savePreviewImage(const QString& path);
    bool saveDocument();
    bool saveDocumentAs(const QString& path);

    // The preview (PreviewController).
    PreviewOptions previewOptions() const;
    void setPreviewOptions(const PreviewOptions& options);
    // Waits until the worker has delivered a full-resolution frame for the current state.
    void waitForPreview();
    std::shared_ptr<const PreviewFrame> currentFrame() const;
    // The last full-resolution preview update times (ms), for logging and benchmarks.
    const QList<double>& previewTimes() const;
    void setInteractive(bool on); // proxy previews while true (a slider is held)
    // What the status bar says about the export's entries outside [0, 1] (live).
    QString clipText() const;

    // Window geometry and dock layout from the last session (not used by headless modes, so
    // screenshots do not depend on the user's settings).
    void restoreWindowState();

protected:
    void closeEvent(QCloseEvent*) override;
    void dragEnterEvent(QDragEnterEvent*) override;
    void dropEvent(QDropEvent*) override;

private:
    void buildCentre();
    void buildDocks();
    void buildStatusBar();
    void updateTitle();
    void onImageChanged();
    void onFrame(const std::shared_ptr<const PreviewFrame>& frame);
    void onTargetLut(const std::shared_ptr<const TargetLut>& target);
    void onHover(int x, int y);
    void updateExportState();

    Document* m_doc;
    PreviewController* m_preview;
    PreviewView* m_view = nullptr;
    QWidget* m_notesBar = nullptr;
    QLabel* m_notesLabel = nullptr;
    LutView* m_lutView = nullptr;
    AdjustmentsPanel* m_adjust = nullptr;
    CurvesPanel* m_curves = nullptr;
    WheelsPanel* m_wheels = nullptr;
    ScopesView* m_scopes = nullptr;
    QUndoView* m_undoView = nullptr;
    CheckModel* m_checkModel = nullptr;
    CheckPanel* m_check = nullptr;
    FileActions* m_files = nullptr;
    WindowActions* m_actions = nullptr;

    QLabel* m_pixelLabel = nullptr;
    TaskStatus* m_loading = nullptr;
    QLabel* m_exportLabel = nullptr;
    QLabel* m_clipLabel = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_zoomLabel = nullptr;

    bool m_interactiveErrors = true;
    std::optional<LutPurpose> m_purposeAnswer;
    bool m_verbose = false;
    QString m_lastError;
};

} // namespace lut::gui
