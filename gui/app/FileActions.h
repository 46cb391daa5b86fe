#pragma once
// What the File menu does: open an image, a LUT or an edited screenshot, start from neutral,
// save, export, save the preview image, the recent-file lists, and the unsaved-changes question.
// Each operation reports its error through the window (dialog, or stderr when headless) and
// returns false, leaving the document as it was; the *Dialog slots ask for a path first.
#include "lut/io/Format.h"

#include <QObject>
#include <QString>

class QMenu;

namespace lut::gui {

class MainWindow;

class FileActions : public QObject {
    Q_OBJECT
public:
    explicit FileActions(MainWindow* window);

    bool openImage(const QString& path);
    bool openLut(const QString& path);
    bool openScreenshotLut(const QString& path);
    void newNeutral(int size);
    bool save(); // to the LUT's file, or Save As when it has none or its format cannot write
    bool saveAs(const QString& path);
    bool exportLut(const QString& path, const QString& format, const FormatOptions& options,
                   bool smashCompensate);
    // The full-resolution preview with the current settings, written the way `lutkit preview`
    // does (lut::formats::renderedImageWriteOptions: 8-bit unless the extension is float).
    bool savePreviewImage(const QString& path);
    // Asks Save / Discard / Cancel when the document is modified; true = go on. Headless runs
    // never ask.
    bool maybeSave();

    // The menus the recent files go into (filled now and after every open or save).
    void setRecentMenus(QMenu* images, QMenu* luts);

    void openImageDialog();
    void openLutDialog();
    void openScreenshotDialog();
    void saveAsDialog();
    void exportDialog();
    void savePreviewDialog();

    // File dialog filters: the picture formats, and every extension a LUT format reads.
    static QString imageFilter();
    static QString lutFilter();

private:
    void addRecent(const char* key, const QString& path);
    void updateRecentMenus();
    void showStatus(const QString& message);

    MainWindow* m_window;
    QMenu* m_recentImages = nullptr;
    QMenu* m_recentLuts = nullptr;
};

} // namespace lut::gui
