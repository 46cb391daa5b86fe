#include "FileActions.h"

#include "Document.h"
#include "ExportDialog.h"
#include "MainWindow.h"
#include "RecentFiles.h"

#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"

#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

#include <cstdio>

namespace lut::gui {

namespace {

const char* kRecentImagesKey = "recent/images";
const char* kRecentLutsKey = "recent/luts";

// A wait cursor for the lifetime of the object.
struct WaitCursor {
    WaitCursor() { QApplication::setOverrideCursor(Qt::WaitCursor); }
    ~WaitCursor() { QApplication::restoreOverrideCursor(); }
    WaitCursor(const WaitCursor&) = delete;
    WaitCursor& operator=(const WaitCursor&) = delete;
};

} // namespace

FileActions::FileActions(MainWindow* window) : QObject(window), m_window(window) {}

QString FileActions::imageFilter() {
    return tr("Images (*.png *.exr *.tif *.tiff *.jpg *.jpeg *.bmp *.tga *.hdr *.webp);;"
              "All files (*)");
}

QString FileActions::lutFilter() {
    formats::registerBuiltinFormats();
    QStringList patterns;
    for (const Format* f : FormatRegistry::instance().all()) {
        if (!f->canRead())
            continue;
        for (const auto& e : f->extensions()) {
            const QString p = QStringLiteral("*") + QString::fromStdString(e);
            if (!patterns.contains(p))
                patterns << p;
        }
    }
    return tr("LUT files (%1);;All files (*)").arg(patterns.join(' '));
}

void FileActions::showStatus(const QString& message) {
    m_window->statusBar()->showMessage(message, 5000);
}

// ---- recent files ---------------------------------------------------------------------------

void FileActions::setRecentMenus(QMenu* images, QMenu* luts) {
    m_recentImages = images;
    m_recentLuts = luts;
    updateRecentMenus();
}

void FileActions::addRecent(const char* key, const QString& path) {
    if (!m_window->interactiveErrors())
        return; // headless runs (tests, --screenshot) leave settings alone
    QSettings settings;
    settings.setValue(key, addRecentFile(settings.value(key).toStringList(), path));
    updateRecentMenus();
}

void FileActions::updateRecentMenus() {
    QSettings settings;
    auto fill = [&](QMenu* menu, const char* key, bool lut) {
        if (!menu)
            return;
        menu->clear();
        const QStringList list = settings.value(key).toStringList();
        for (const QString& p : list) {
            menu->addAction(QFileInfo(p).fileName() + QStringLiteral("  (") + QFileInfo(p).path() +
                                ')',
                            this, [this, p, lut] { lut ? (void)openLut(p) : (void)openImage(p); });
        }
        menu->setEnabled(!list.isEmpty());
    };
    fill(m_recentImages, kRecentImagesKey, false);
    fill(m_recentLuts, kRecentLutsKey, true);
}

// ---- opening --------------------------------------------------------------------------------

bool FileActions::openImage(const QString& path) {
    try {
        WaitCursor wait;
        m_window->document()->openImage(path);
    } catch (const std::exception& e) {
        m_window->reportError(tr("Cannot open image"), QString::fromUtf8(e.what()));
        return false;
    }
    addRecent(kRecentImagesKey, path);
    return true;
}

bool FileActions::openLut(const QString& path) {
    if (!maybeSave())
        return false;
    try {
        m_window->document()->openLut(path);
    } catch (const std::exception& e) {
        m_window->reportError(tr("Cannot open LUT"), QString::fromUtf8(e.what()));
        return false;
    }
    addRecent(kRecentLutsKey, path);
    return true;
}

bool FileActions::openScreenshotLut(const QString& path) {
    if (!maybeSave())
        return false;
    QStringList notes;
    try {
        notes = m_window->document()->startFromScreenshot(path);
    } catch (const std::exception& e) {
        m_window->reportError(tr("Cannot extract a LUT"), QString::fromUtf8(e.what()));
        return false;
    }
    if (!notes.isEmpty()) {
        if (m_window->interactiveErrors())
            QMessageBox::information(m_window, tr("LUT extracted"), notes.join('\n'));
        else
            std::fprintf(stderr, "%s\n", qPrintable(notes.join('\n')));
    }
    return true;
}

void FileActions::newNeutral(int size) {
    if (!maybeSave())
        return;
    m_window->document()->newNeutral(size);
}

// ---- writing --------------------------------------------------------------------------------

bool FileActions::exportLut(const QString& path, const QString& format,
                            const FormatOptions& options, bool smashCompensate) {
    try {
        const Diagnostics d =
            m_window->document()->exportLut(path, format, options, smashCompensate);
        QStringList lines;
        for (const auto& x : d)
            lines << QString::fromStdString(x.str());
        showStatus(tr("Exported %1").arg(QFileInfo(path).fileName()));
        if (!lines.isEmpty() && m_window->interactiveErrors())
            QMessageBox::information(m_window, tr("Exported with notes"), lines.join('\n'));
    } catch (const std::exception& e) {
        m_window->reportError(tr("Export failed"), QString::fromUtf8(e.what()));
        return false;
    }
    return true;
}

bool FileActions::saveAs(const QString& path) {
    try {
        m_window->document()->saveAs(path);
    } catch (const std::exception& e) {
        m_window->reportError(tr("Save failed"), QString::fromUtf8(e.what()));
        return false;
    }
    addRecent(kRecentLutsKey, path);
    showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
    return true;
}

bool FileActions::save() {
    Document* doc = m_window->document();
    const QString path = doc->lutPath();
    bool writable = false;
    if (!path.isEmpty()) {
        for (const Format* f : FormatRegistry::instance().forExtension(path.toStdString()))
            writable = writable || f->canWrite();
    }
    if (!writable) {
        saveAsDialog();
        return !doc->isModified();
    }
    return saveAs(path);
}

bool FileActions::savePreviewImage(const QString& path) {
    Document* doc = m_window->document();
    if (!doc->hasImage()) {
        m_window->reportError(tr("Save preview image"), tr("No image is open."));
        return false;
    }
    try {
        WaitCursor wait;
        // The current full-resolution frame, or a fresh render of it: the view may show a proxy.
        const Image image = m_window->preview()->renderFullResolution();
        const formats::ImageWriteOptions o =
            formats::renderedImageWriteOptions(doc->imageInfo(), path.toStdString());
        formats::writeImage(path.toStdString(), image, o);
    } catch (const std::exception& e) {
        m_window->reportError(tr("Cannot save the preview"), QString::fromUtf8(e.what()));
        return false;
    }
    showStatus(tr("Saved preview %1").arg(QFileInfo(path).fileName()));
    return true;
}

bool FileActions::maybeSave() {
    Document* doc = m_window->document();
    if (!doc->isModified())
        return true;
    if (!m_window->interactiveErrors())
        return true; // headless: never block on a question
    const auto answer = QMessageBox::warning(
        m_window, tr("Unsaved changes"),
        tr("The LUT \"%1\" has unsaved changes. Save them?").arg(doc->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

// ---- dialogs --------------------------------------------------------------------------------

void FileActions::openImageDialog() {
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open Image"), QString(), imageFilter());
    if (!path.isEmpty())
        openImage(path);
}

void FileActions::openLutDialog() {
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open LUT"), QString(), lutFilter());
    if (!path.isEmpty())
        openLut(path);
}

void FileActions::openScreenshotDialog() {
    const QString path = QFileDialog::getOpenFileName(m_window, tr("LUT from Edited Screenshot"),
                                                      QString(), imageFilter());
    if (!path.isEmpty())
        openScreenshotLut(path);
}

void FileActions::saveAsDialog() {
    QString base = m_window->document()->lutPath();
    if (base.isEmpty())
        base = QStringLiteral("grade.cube");
    const QString path = QFileDialog::getSaveFileName(m_window, tr("Save LUT"), base,
                                                      tr("Cube LUT (*.cube);;All files (*)"));
    if (!path.isEmpty())
        saveAs(path);
}

void FileActions::exportDialog() {
    QString base = m_window->document()->lutPath();
    base = base.isEmpty() ? QStringLiteral("grade")
                          : QFileInfo(base).path() + '/' + QFileInfo(base).completeBaseName();
    ExportDialog dlg(base, m_window);
    if (dlg.exec() != QDialog::Accepted || dlg.path().isEmpty())
        return;
    exportLut(dlg.path(), dlg.choice().format, dlg.options(), dlg.smashCompensate());
}

void FileActions::savePreviewDialog() {
    Document* doc = m_window->document();
    if (!doc->hasImage()) {
        m_window->reportError(tr("Save preview image"), tr("Open an image first."));
        return;
    }
    const QString base = QFileInfo(doc->imagePath()).path() + '/' +
                         QFileInfo(doc->imagePath()).completeBaseName() +
                         QStringLiteral("_preview.png");
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Save Preview Image"), base, imageFilter());
    if (!path.isEmpty())
        savePreviewImage(path);
}

} // namespace lut::gui
