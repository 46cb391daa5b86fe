// SPDX-License-Identifier: Apache-2.0
#pragma once
// The window's menus, toolbars and shortcuts: File (FileActions), Edit (undo/redo, reset), View
// (zoom, split/after/before, clipping overlay, docks), Preview (the PreviewController's options),
// Tools (the LUT plot and the comparison with a LUT file: PlotDialog, CompareDialog) and Help. The
// preview toolbar shows the one choice that drives preview and export, the target (Smash Ultimate,
// an engine strip, a .cube), and what the picture is (an in-game screenshot or a linear scene:
// detected on open, switchable here), then the chain, bloom, LUT and interpolation. The widgets
// show the controller's options and write them back; nothing here keeps state of its own. Shortcuts
// work from every widget of the window (ShortcutGuard).
#include "PreviewRenderer.h"

#include <QObject>
#include <QPointer>

#include <memory>

class QAction;
class QComboBox;
class QMainWindow;
class QMenu;
class QToolBar;

namespace lut::gui {

class BackgroundTask;
class CompareDialog;
struct Comparison;
class Document;
class FileActions;
class MatchDialog;
class PreviewController;
class PreviewView;
class Prompts;
struct EditorContext;

class WindowActions : public QObject {
    Q_OBJECT
public:
    // Builds the menus and toolbars on `window` (after its docks exist: View lists them), over
    // the context's document and preview; File runs `files`, View zooms `view`, errors and long
    // tasks go to the context's prompts.
    WindowActions(QMainWindow* window, const EditorContext& context, FileActions* files,
                  PreviewView* view);

    QAction* bloomAction() const { return m_bloom; }
    QAction* lutAction() const { return m_lut; }
    QAction* brightenAction() const { return m_brighten; }
    QAction* clippingAction() const { return m_clipping; }
    QAction* undoAction() const { return m_undo; }
    QAction* redoAction() const { return m_redo; }
    QAction* exportAction() const { return m_export; }
    QAction* saveAction() const { return m_save; }
    QComboBox* targetBox() const { return m_target; }
    QComboBox* inputBox() const { return m_input; }
    QComboBox* chainBox() const { return m_chain; }
    QComboBox* interpolationBox() const { return m_interp; }
    // Tools > Compare with LUT File on a worker (progress and Cancel in the status bar); the
    // report opens beside the window when it is done.
    void startCompare(const QString& path);
    BackgroundTask* compareTask() const { return m_compareTask; }
    std::shared_ptr<const Comparison> lastComparison() const { return m_lastComparison; }
    CompareDialog* compareDialog() const; // the last report, while it is open
    // Tools > Match to Reference with `referencePath`: the reference read and the match fitted on
    // a worker (progress and Cancel in the status bar, the window repainting), then the dialog
    // opens (window-modal) to set its amounts. Opening another picture cancels it.
    void startMatch(const QString& referencePath);
    BackgroundTask* matchTask() const { return m_matchTask; }
    MatchDialog* matchDialog() const; // while it is open

private:
    void buildFileMenu();
    void buildEditMenu();
    void buildViewMenu();
    void buildPreviewMenu();
    void buildToolsMenu();
    void buildHelpMenu();
    void showPlot();
    void compareWithFile();
    void matchToReference();
    void buildToolbars();
    // The options as the widgets show them, and the widgets from the options.
    PreviewOptions optionsFromWidgets() const;
    void showOptions(const PreviewOptions& options);
    void applyWidgets();

    QMainWindow* m_window;
    Document* m_doc;
    PreviewController* m_preview;
    Prompts* m_prompts;
    FileActions* m_files;
    PreviewView* m_view;
    BackgroundTask* m_compareTask;
    BackgroundTask* m_matchTask;
    QPointer<MatchDialog> m_matchDialog;
    std::shared_ptr<const Comparison> m_lastComparison;
    QPointer<CompareDialog> m_compareDialog;
    // For the toolbars.
    QAction* m_openImage = nullptr;
    QAction* m_openLut = nullptr;
    QAction* m_save = nullptr;
    QAction* m_export = nullptr;
    QAction* m_undo = nullptr;
    QAction* m_redo = nullptr;
    QAction* m_fit = nullptr;
    QAction* m_actualSize = nullptr;
    QAction* m_modes[3] = {};
    QAction* m_clipping = nullptr;
    // Preview options.
    QComboBox* m_target = nullptr;
    QComboBox* m_input = nullptr;
    QComboBox* m_chain = nullptr;
    QComboBox* m_interp = nullptr;
    QAction* m_bloom = nullptr;
    QAction* m_lut = nullptr;
    QAction* m_brighten = nullptr;
};

} // namespace lut::gui
