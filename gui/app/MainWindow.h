#pragma once
// The editor window: preview (centre), adjustments / LUT / history docks, status bar. The state
// lives in the model (Document: the LUT and the image; PreviewController: the preview); the
// window lays out the widgets and wires them to the model. Menus and toolbars are WindowActions,
// opening and writing files is FileActions.
#include "PreviewController.h"

#include "lut/io/Format.h"

#include <QMainWindow>

#include <memory>

class QLabel;
class QUndoView;

namespace lut::gui {

class AdjustmentsPanel;
class Document;
class FileActions;
class LutView;
class PreviewView;
class WindowActions;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return m_doc; }
    PreviewController* preview() const { return m_preview; }
    FileActions* fileActions() const { return m_files; }
    WindowActions* windowActions() const { return m_actions; }
    AdjustmentsPanel* adjustmentsPanel() const { return m_adjust; }
    PreviewView* previewView() const { return m_view; }
    LutView* lutView() const { return m_lutView; }

    // false: errors go to stderr and lastError() instead of a dialog, no question is asked and
    // no setting is written (tests, --screenshot, --save-preview).
    void setInteractiveErrors(bool on) { m_interactiveErrors = on; }
    bool interactiveErrors() const { return m_interactiveErrors; }
    QString lastError() const { return m_lastError; }
    // Shows (dialog or stderr) and remembers an error.
    void reportError(const QString& title, const QString& message);
    void setVerbose(bool on) { m_verbose = on; }

    // The file operations (FileActions); each returns false after reporting the error and
    // leaves the document as it was.
    bool openImageFile(const QString& path);
    bool openLutFile(const QString& path);
    bool openScreenshotLut(const QString& path);
    bool exportLut(const QString& path, const QString& format, const FormatOptions& options,
                   bool smashCompensate);
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

    // Window geometry and dock layout from the last session (not used by headless modes, so
    // screenshots do not depend on the user's settings).
    void restoreWindowState();

protected:
    void closeEvent(QCloseEvent*) override;
    void dragEnterEvent(QDragEnterEvent*) override;
    void dropEvent(QDropEvent*) override;

private:
    void buildDocks();
    void buildStatusBar();
    void updateTitle();
    void onSceneChanged();
    void onFrame(const std::shared_ptr<const PreviewFrame>& frame);
    void onHover(int x, int y);

    Document* m_doc;
    PreviewController* m_preview;
    PreviewView* m_view;
    LutView* m_lutView = nullptr;
    AdjustmentsPanel* m_adjust = nullptr;
    QUndoView* m_undoView = nullptr;
    FileActions* m_files = nullptr;
    WindowActions* m_actions = nullptr;

    QLabel* m_pixelLabel = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_zoomLabel = nullptr;

    bool m_interactiveErrors = true;
    bool m_verbose = false;
    QString m_lastError;
};

} // namespace lut::gui
