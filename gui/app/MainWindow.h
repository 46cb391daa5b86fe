#pragma once
// The editor window: preview (centre), adjustments / LUT / history docks, toolbars, status bar.
// All state lives in the Document; the window wires it to widgets and to the preview worker.
#include "PreviewRenderer.h"
#include "PreviewScheduler.h"

#include "lut/io/Format.h"

#include <QMainWindow>

#include <memory>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QUndoView;

namespace lut::gui {

class AdjustmentsPanel;
class Document;
class LutView;
class PreviewView;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return m_doc; }
    AdjustmentsPanel* adjustmentsPanel() const { return m_adjust; }
    PreviewView* previewView() const { return m_view; }
    LutView* lutView() const { return m_lutView; }
    PreviewScheduler* scheduler() const { return m_scheduler; }

    // false: errors go to stderr and lastError() instead of a dialog (tests, --screenshot).
    void setInteractiveErrors(bool on) { m_interactiveErrors = on; }
    QString lastError() const { return m_lastError; }
    void setVerbose(bool on) { m_verbose = on; }

    // Each returns false (after reporting the error) and leaves the document as it was.
    bool openImageFile(const QString& path);
    bool openLutFile(const QString& path);
    bool openScreenshotLut(const QString& path);
    bool exportLut(const QString& path, const QString& format, const FormatOptions& options,
                   bool smashCompensate);
    // Renders the full-resolution preview with the current settings and writes it the way
    // `lutkit preview` does (lut::formats::writeImage, 8-bit unless the extension is float).
    bool savePreviewImage(const QString& path);
    bool saveDocument();
    bool saveDocumentAs(const QString& path);

    PreviewOptions previewOptions() const;
    void setPreviewOptions(const PreviewOptions& options);
    // Waits until the worker has delivered a full-resolution frame for the current state.
    void waitForPreview();
    std::shared_ptr<const PreviewFrame> currentFrame() const { return m_frame; }
    // The last full-resolution preview update times (ms), for logging and benchmarks.
    const QList<double>& previewTimes() const { return m_times; }
    void setInteractive(bool on); // proxy previews while true (a slider is held)
    // Window geometry and dock layout from the last session (not used by headless modes, so
    // screenshots do not depend on the user's settings).
    void restoreWindowState();

protected:
    void closeEvent(QCloseEvent*) override;
    void dragEnterEvent(QDragEnterEvent*) override;
    void dropEvent(QDropEvent*) override;

private:
    void buildActions();
    void buildDocks();
    void buildStatusBar();
    void updateTitle();
    void updateRecentMenus();
    void addRecent(const QString& key, const QString& path);
    void reportError(const QString& title, const QString& message);
    bool maybeSave();
    void requestPreview();
    void onFrame(std::shared_ptr<const PreviewFrame> frame);
    void onHover(int x, int y);
    void rebuildProxyAndBefore();
    void newNeutral(int size);
    void openImageDialog();
    void openLutDialog();
    void openScreenshotDialog();
    void exportDialog();
    void savePreviewDialog();
    void saveAsDialog();

    Document* m_doc;
    PreviewScheduler* m_scheduler;
    PreviewView* m_view;
    LutView* m_lutView;
    AdjustmentsPanel* m_adjust;
    QUndoView* m_undoView;

    QComboBox* m_preset;
    QComboBox* m_interp;
    QAction* m_bloomAct;
    QAction* m_lutAct;
    QAction* m_brightenAct;
    QMenu* m_recentImages;
    QMenu* m_recentLuts;
    QMenu* m_viewMenu;
    QLabel* m_pixelLabel;
    QLabel* m_timeLabel;
    QLabel* m_zoomLabel;

    std::shared_ptr<const PreviewFrame> m_frame;
    std::shared_ptr<const Image> m_proxyScene;
    // The last before-LUT frames the worker made for the full scene [0] and the proxy [1]
    // (each frame says which scene and options it belongs to).
    std::shared_ptr<const PreviewFrame> m_beforeLutSource[2];
    int m_proxyFactor = 1;
    bool m_interactive = false;
    bool m_interactiveErrors = true;
    bool m_verbose = false;
    QString m_lastError;
    QList<double> m_times;
};

} // namespace lut::gui
