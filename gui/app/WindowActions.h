#pragma once
// The window's menus, toolbars and shortcuts: File (FileActions), Edit (undo/redo), View (zoom,
// split/after/before, docks), Preview (the PreviewController's options: preset, bloom, LUT,
// brighten, interpolation; the in-game-screenshot switch of the Document) and Help. The preview
// widgets show the controller's options and write them back; nothing here keeps state of its own.
#include "PreviewRenderer.h"

#include <QObject>

class QAction;
class QComboBox;
class QMenu;
class QToolBar;

namespace lut::gui {

class MainWindow;

class WindowActions : public QObject {
    Q_OBJECT
public:
    // Builds the menus and toolbars on `window` (after its docks exist: View lists them).
    explicit WindowActions(MainWindow* window);

    QAction* bloomAction() const { return m_bloom; }
    QAction* lutAction() const { return m_lut; }
    QAction* brightenAction() const { return m_brighten; }
    QAction* fromScreenshotAction() const { return m_fromScreenshot; }
    QComboBox* presetBox() const { return m_preset; }
    QComboBox* interpolationBox() const { return m_interp; }

private:
    void buildFileMenu();
    void buildEditMenu();
    void buildViewMenu();
    void buildPreviewMenu();
    void buildHelpMenu();
    void buildToolbars();
    // The options as the widgets show them, and the widgets from the options.
    PreviewOptions optionsFromWidgets() const;
    void showOptions(const PreviewOptions& options);

    MainWindow* m_window;
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
    // Preview options.
    QComboBox* m_preset = nullptr;
    QComboBox* m_interp = nullptr;
    QAction* m_bloom = nullptr;
    QAction* m_lut = nullptr;
    QAction* m_brighten = nullptr;
    QAction* m_fromScreenshot = nullptr;
};

} // namespace lut::gui
