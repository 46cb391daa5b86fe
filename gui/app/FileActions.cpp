// SPDX-License-Identifier: Apache-2.0
#include "FileActions.h"

#include "BackgroundTask.h"
#include "BuiltinNames.h"
#include "Document.h"
#include "ErrorText.h"
#include "ExportDialog.h"
#include "FileLoader.h"
#include "OpenLutQuestion.h"
#include "PreviewController.h"
#include "Prompts.h"
#include "RecentFiles.h"
#include "TaskStatus.h"

#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"
#include "lut/io/Layout.h"

#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include <cstdio>

namespace lut::gui {

namespace {

const char* kRecentImagesKey = "recent/images";
const char* kRecentLutsKey = "recent/luts";

QString human(const std::exception& e) {
    return QString::fromStdString(humanErrorText(e));
}

} // namespace

FileActions::FileActions(const EditorContext& context, QObject* parent)
    : QObject(parent), m_doc(context.document), m_preview(context.preview),
      m_prompts(context.prompts), m_loader(new FileLoader(this)),
      m_saveTask(new BackgroundTask(this)) {
    connect(m_loader, &FileLoader::imageLoaded, this,
            [this](const QString& path, std::shared_ptr<formats::LoadedImage> image) {
                m_lastDone = path;
                m_lastOk = false;
                try {
                    m_doc->adoptImage(std::move(*image), path);
                } catch (const std::exception& e) {
                    m_prompts->reportError(tr("Cannot open image"), human(e));
                    return;
                }
                m_lastOk = true;
                addRecent(kRecentImagesKey, path);
            });
    connect(m_loader, &FileLoader::lutLoaded, this,
            [this](const QString& path, std::shared_ptr<LutFile> file) {
                m_lastDone = path;
                m_lastOk = false;
                // A file that does not say what it is for: remembered, told or asked (once).
                std::optional<LutPurpose> answer;
                if (!file->purpose) {
                    bool cancelled = false;
                    answer = purposeFor(path, *file, &cancelled);
                    if (cancelled) {
                        showStatus(tr("Not opened: %1").arg(QFileInfo(path).fileName()));
                        return;
                    }
                }
                QStringList notes;
                try {
                    notes = m_doc->adoptLut(*file, path, answer);
                } catch (const std::exception& e) {
                    m_prompts->reportError(tr("Cannot open LUT"), human(e));
                    return;
                }
                m_lastOk = true;
                m_prompts->showNotes(notes);
                addRecent(kRecentLutsKey, path);
            });
    connect(m_loader, &FileLoader::failed, this,
            [this](const QString& path, const QString& message, bool isLut) {
                m_lastDone = path;
                m_lastOk = false;
                m_prompts->reportError(isLut ? tr("Cannot open LUT") : tr("Cannot open image"),
                                       message);
            });
    connect(m_loader, &FileLoader::busyChanged, this,
            [this](bool busy) { m_prompts->setLoading(busy); });
    connect(m_loader, &FileLoader::progressChanged, m_prompts->loadingStatus(),
            &TaskStatus::setFraction);
    connect(m_prompts->loadingStatus(), &TaskStatus::cancelRequested, m_loader,
            &FileLoader::cancel);
    m_prompts->watchTask(m_saveTask, QStringLiteral("task.savePreview"));
}

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
    m_prompts->showStatus(message);
}

// ---- recent files ---------------------------------------------------------------------------

void FileActions::setRecentMenus(QMenu* images, QMenu* luts) {
    m_recentImages = images;
    m_recentLuts = luts;
    updateRecentMenus();
}

void FileActions::addRecent(const char* key, const QString& path) {
    if (!m_prompts->interactive())
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
            const QString shown = builtinLutTitle(p); // a built-in LUT by its name, else p
            menu->addAction(
                shown != p
                    ? shown
                    : QFileInfo(p).fileName() + QStringLiteral("  (") + QFileInfo(p).path() + ')',
                this, [this, p, lut] { lut ? (void)openLutAsking(p) : (void)startOpenImage(p); });
        }
        menu->setEnabled(!list.isEmpty());
    };
    fill(m_recentImages, kRecentImagesKey, false);
    fill(m_recentLuts, kRecentLutsKey, true);
}

// ---- what a LUT is for ----------------------------------------------------------------------

namespace {
const char* kPurposesKey = "lutPurposes"; // absolute path -> "raw" / "smash"
}

std::optional<LutPurpose> FileActions::rememberedPurpose(const QString& path) {
    const QVariantMap map = QSettings().value(kPurposesKey).toMap();
    const QString said = map.value(QFileInfo(path).absoluteFilePath()).toString();
    if (said == QLatin1String("raw") || said == QLatin1String("smash")) // else nothing kept
        return parseLutPurpose(said.toStdString());
    return std::nullopt;
}

void FileActions::rememberPurpose(const QString& path, LutPurpose purpose) {
    QSettings settings;
    QVariantMap map = settings.value(kPurposesKey).toMap();
    map.insert(QFileInfo(path).absoluteFilePath(), QString::fromLatin1(toString(purpose)));
    settings.setValue(kPurposesKey, map);
}

std::optional<LutPurpose> FileActions::purposeFor(const QString& path, const LutFile& file,
                                                  bool* cancelled) {
    *cancelled = false;
    if (const auto p = m_prompts->lutPurposeAnswer()) // said on the command line, by a script
        return p;
    if (!m_prompts->interactive())
        return std::nullopt; // headless: taken as the library decides, with a note
    if (const auto p = rememberedPurpose(path))
        return p;
    // As Open LUT asks a strip's layout: once, and the answer is kept for this file. Its content
    // may say it is the game's LUT (lut::gameLutEvidence): said, and that answer pre-selected.
    const auto answer = askLutPurpose(m_prompts->dialogParent(), QFileInfo(path).fileName(),
                                      QString::fromStdString(decidePurpose(file).evidence));
    if (!answer) {
        *cancelled = true;
        return std::nullopt;
    }
    rememberPurpose(path, *answer);
    return answer;
}

// ---- opening --------------------------------------------------------------------------------

bool FileActions::startOpenImage(const QString& path) {
    m_prompts->setLoadingText(tr("Opening %1…").arg(QFileInfo(path).fileName()));
    m_loader->loadImage(path);
    return true;
}

bool FileActions::startOpenLut(const QString& path, const FormatOptions& options) {
    if (!maybeSave())
        return false;
    m_prompts->setLoadingText(tr("Opening %1…").arg(QFileInfo(path).fileName()));
    m_loader->loadLut(path, options);
    return true;
}

bool FileActions::openImage(const QString& path) {
    if (!startOpenImage(path))
        return false;
    m_loader->waitForIdle();
    return m_lastDone == path && m_lastOk;
}

bool FileActions::openLut(const QString& path, const FormatOptions& options) {
    if (!startOpenLut(path, options))
        return false;
    m_loader->waitForIdle();
    return m_lastDone == path && m_lastOk;
}

bool FileActions::openScreenshotLut(const QString& path) {
    if (!maybeSave())
        return false;
    QStringList notes;
    try {
        notes = m_doc->startFromScreenshot(path);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot extract a LUT"), human(e));
        return false;
    }
    m_prompts->showNotes(notes);
    return true;
}

void FileActions::newNeutral(int size) {
    if (!maybeSave())
        return;
    m_doc->newNeutral(size);
}

// ---- writing --------------------------------------------------------------------------------

bool FileActions::confirmReplace(const QString& path, bool original) {
    if (!m_prompts->interactive())
        return false; // headless: an existing file is replaced only when told (overwrite)
    // The full path: one name (color_grading_lut.nutexb) is every stage's LUT, so the folder is
    // what tells them apart.
    const QString where = QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath());
    QMessageBox box(
        QMessageBox::Warning, tr("Replace file?"),
        original ? tr("%1 is the LUT you opened. Replace it? The original is lost.").arg(where)
                 : tr("%1 already exists. Replace it?").arg(where),
        QMessageBox::NoButton, m_prompts->dialogParent());
    box.setInformativeText(tr("Keep the file to choose another name."));
    QPushButton* replace = box.addButton(tr("Replace"), QMessageBox::DestructiveRole);
    QPushButton* keep = box.addButton(tr("Keep the file"), QMessageBox::RejectRole);
    box.setDefaultButton(keep);
    box.setEscapeButton(keep);
    box.exec();
    return box.clickedButton() == replace;
}

bool FileActions::isOpenedLut(const QString& path) const {
    const QString opened = m_doc->lutPath();
    return !opened.isEmpty() &&
           QFileInfo(path).absoluteFilePath() == QFileInfo(opened).absoluteFilePath();
}

bool FileActions::exportLut(const QString& path, const QString& format,
                            const FormatOptions& options, ExportTarget target, bool overwrite,
                            const StrengthOptions& strength) {
    const bool addsRow = format == QLatin1String(kAtlasFormat); // keeps the atlas's rows
    if (QFileInfo::exists(path) && !overwrite && !addsRow &&
        !confirmReplace(path, isOpenedLut(path))) {
        m_prompts->reportError(
            tr("Export"), tr("%1 exists and was not replaced.")
                              .arg(QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath())));
        return false;
    }
    try {
        QDir().mkpath(QFileInfo(path).absolutePath()); // the "edited" folder beside an original
        const Diagnostics d = m_doc->exportLut(path, format, options, target, strength);
        QStringList lines;
        for (const auto& x : d)
            lines << QString::fromStdString(x.str());
        lines << m_prompts->checkWarnings(target); // lutkit check's failing checks, if any
        showStatus(tr("Exported %1").arg(QDir::toNativeSeparators(path)));
        m_prompts->showNotes(lines);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Export failed"), human(e));
        return false;
    }
    return true;
}

bool FileActions::saveAs(const QString& path) {
    try {
        m_doc->saveAs(path);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Save failed"), human(e));
        return false;
    }
    addRecent(kRecentLutsKey, path);
    showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
    return true;
}

bool FileActions::save() {
    Document* doc = m_doc;
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
    // The first save over the file the user opened asks: it replaces their original.
    if (doc->savingReplacesOriginal() && m_prompts->interactive() && !confirmReplace(path, true)) {
        saveAsDialog();
        return !doc->isModified();
    }
    return saveAs(path);
}

bool FileActions::startSavePreview(const QString& path) {
    Document* doc = m_doc;
    if (!doc->hasImage()) {
        m_prompts->reportError(tr("Save preview image"), tr("No image is open."));
        return false;
    }
    // Rendered (unless the current frame is the full-resolution preview) and written on a
    // worker: a 4K picture takes seconds to encode and check. The window stays live, the status
    // bar shows the progress with Cancel; a cancelled write leaves any old file as it was.
    const PreviewController* preview = m_preview;
    const double renderShare = preview->hasFullResolutionFrame() ? 0.0 : 0.4;
    m_saveTask->start(
        tr("Saving %1…").arg(QFileInfo(path).fileName()),
        [this, path, renderShare, render = preview->fullResolutionRenderer(),
         options = formats::renderedImageWriteOptions(doc->imageInfo(), path.toStdString())](
            const Progress& progress) mutable {
            const Progress renderPart(progress, 0.0, renderShare);
            const Progress writePart(progress, renderShare, 1.0);
            const Image image = render(renderPart);
            options.progress = &writePart;
            formats::writeImage(path.toStdString(), image, options);
            return BackgroundTask::Delivery([this, path] {
                showStatus(tr("Saved preview %1").arg(QDir::toNativeSeparators(path)));
            });
        },
        [this](const QString& message) {
            m_prompts->reportError(tr("Cannot save the preview"), message);
        });
    return true;
}

bool FileActions::savePreviewImage(const QString& path) {
    if (!startSavePreview(path))
        return false;
    m_saveTask->waitForIdle();
    return m_saveTask->lastOutcome() == BackgroundTask::Outcome::Done;
}

bool FileActions::savePicture(const QString& path, const Image& image, bool overwrite) {
    if (QFileInfo::exists(path) && !overwrite && !confirmReplace(path, false)) {
        m_prompts->reportError(tr("Save picture"), tr("%1 exists and was not replaced.")
                                                       .arg(QDir::toNativeSeparators(
                                                           QFileInfo(path).absoluteFilePath())));
        return false;
    }
    try {
        formats::ImageWriteOptions o;
        o.bitDepth = 8;
        o.alpha = false;
        formats::writeImage(path.toStdString(), image, o);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot save the picture"), human(e));
        return false;
    }
    showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
    return true;
}

bool FileActions::saveAdjustments(const QString& path) {
    try {
        m_doc->saveAdjustmentList(path);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot save the adjustments"), human(e));
        return false;
    }
    showStatus(tr("Saved adjustments %1").arg(QFileInfo(path).fileName()));
    return true;
}

bool FileActions::loadAdjustments(const QString& path) {
    try {
        m_doc->loadAdjustmentList(path);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot load the adjustments"), human(e));
        return false;
    }
    return true;
}

bool FileActions::maybeSave() {
    Document* doc = m_doc;
    if (!doc->isModified())
        return true;
    if (!m_prompts->interactive())
        return true; // headless: never block on a question
    // No default that loses anything: Cancel is the default (and Escape); saving over the
    // opened original is not offered here (Save As is), unless it was replaced already.
    const bool canSave = !doc->lutPath().isEmpty() && !doc->savingReplacesOriginal();
    QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"),
                    tr("The LUT \"%1\" has unsaved changes.").arg(doc->displayName()),
                    QMessageBox::NoButton, m_prompts->dialogParent());
    box.setInformativeText(canSave ? tr("Save them, discard them, or go back?")
                                   : tr("Save them to a new file, discard them, or go back?"));
    QPushButton* save =
        box.addButton(canSave ? tr("Save") : tr("Save As…"), QMessageBox::AcceptRole);
    save->setObjectName("save");
    QPushButton* discard = box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
    discard->setObjectName("discard");
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == save) {
        if (canSave)
            return this->save();
        saveAsDialog();
        return !doc->isModified();
    }
    return box.clickedButton() == discard;
}

// ---- dialogs --------------------------------------------------------------------------------

void FileActions::openImageDialog() {
    const QString path = QFileDialog::getOpenFileName(m_prompts->dialogParent(), tr("Open Image"),
                                                      QString(), imageFilter());
    if (!path.isEmpty())
        startOpenImage(path);
}

void FileActions::openLutDialog() {
    const QString path = QFileDialog::getOpenFileName(m_prompts->dialogParent(), tr("Open LUT"),
                                                      QString(), lutFilter());
    if (!path.isEmpty())
        openLutAsking(path);
}

bool FileActions::askStripLayout(const QString& path, FormatOptions& options) {
    if (!m_prompts->interactive() || !stripLayoutIsAmbiguous(path))
        return true;
    // A 256x16 picture fits several strip layouts: detection usually knows, the user may not
    // agree (a heavy grade can fool it). What it is for, when nothing says, is asked in the same
    // dialog (and remembered, so the read does not ask again).
    QStringList items = {tr("Detect automatically")};
    const formats::ImageInfo info = formats::readImageInfo(path.toStdString());
    for (const LayoutFit& f : layoutsForImageSize(info.width, info.height))
        items << QString::fromLatin1(toString(f.layout));
    PurposeDecision read; // a strip is small; unreadable: the read that follows says why
    try {
        read = decidePurpose(formats::readLut(path.toStdString()));
    } catch (const std::exception&) {
    }
    const bool askPurpose =
        !read.said && !m_prompts->lutPurposeAnswer() && !rememberedPurpose(path);
    const auto answer = askOpenLut(m_prompts->dialogParent(), QFileInfo(path).fileName(), items,
                                   askPurpose, QString::fromStdString(read.evidence));
    if (!answer)
        return false;
    options.layout = parseOptionalLayout(answer->layout == items[0] ? std::string()
                                                                    : answer->layout.toStdString());
    if (answer->purpose)
        rememberPurpose(path, *answer->purpose);
    return true;
}

bool FileActions::openLutAsking(const QString& path) {
    FormatOptions options;
    if (!askStripLayout(path, options))
        return false;
    return startOpenLut(path, options);
}

void FileActions::openScreenshotDialog() {
    const QString path = QFileDialog::getOpenFileName(
        m_prompts->dialogParent(), tr("LUT from Edited Screenshot"), QString(), imageFilter());
    if (!path.isEmpty())
        openScreenshotLut(path);
}

void FileActions::saveAsDialog() {
    Document* doc = m_doc;
    QString base = doc->lutPath();
    if (base.isEmpty())
        base = doc->hasImage() ? QFileInfo(doc->imagePath()).absolutePath() + QStringLiteral("/") +
                                     QFileInfo(doc->imagePath()).completeBaseName() +
                                     QStringLiteral("_grade.cube")
                               : QStringLiteral("grade.cube");
    const QString path = QFileDialog::getSaveFileName(m_prompts->dialogParent(), tr("Save LUT"),
                                                      base, tr("Cube LUT (*.cube);;All files (*)"));
    if (!path.isEmpty())
        saveAs(path); // the file dialog asked before replacing
}

void FileActions::exportDialog() {
    Document* doc = m_doc;
    ExportNameInput naming;
    naming.lutPath = doc->lutPath();
    naming.imagePath = doc->imagePath();
    naming.fallbackFolder = QDir::homePath();
    ExportDialog dlg(doc->target(), naming, m_prompts->dialogParent());
    // "Keep the file" in the replace question returns here, with every setting as it was, to
    // choose another name or folder.
    while (dlg.exec() == QDialog::Accepted && !dlg.path().isEmpty()) {
        const QString path = dlg.path();
        // An atlas that exists gets a row (its rows kept): nothing to replace.
        const bool addsRow = dlg.choice().format == QLatin1String(kAtlasFormat);
        if (QFileInfo::exists(path) && !addsRow && !confirmReplace(path, isOpenedLut(path)))
            continue;
        exportLut(path, dlg.choice().format, dlg.options(), dlg.target(), true, dlg.strength());
        return;
    }
}

void FileActions::savePreviewDialog() {
    Document* doc = m_doc;
    if (!doc->hasImage()) {
        m_prompts->reportError(tr("Save preview image"), tr("Open an image first."));
        return;
    }
    const QString base = QFileInfo(doc->imagePath()).path() + '/' +
                         QFileInfo(doc->imagePath()).completeBaseName() +
                         QStringLiteral("_preview.png");
    const QString path = QFileDialog::getSaveFileName(
        m_prompts->dialogParent(), tr("Save Preview Image"), base, imageFilter());
    if (!path.isEmpty())
        savePreviewImage(path);
}

void FileActions::saveAdjustmentsDialog() {
    Document* doc = m_doc;
    const QString from = !doc->lutPath().isEmpty() ? doc->lutPath() : doc->imagePath();
    const QString base = from.isEmpty() ? QStringLiteral("adjustments.txt")
                                        : QFileInfo(from).absolutePath() + '/' +
                                              QFileInfo(from).completeBaseName() +
                                              QStringLiteral("_adjustments.txt");
    const QString path =
        QFileDialog::getSaveFileName(m_prompts->dialogParent(), tr("Save Adjustments"), base,
                                     tr("Adjustment lists (*.txt);;All files (*)"));
    if (!path.isEmpty())
        saveAdjustments(path);
}

void FileActions::loadAdjustmentsDialog() {
    const QString path =
        QFileDialog::getOpenFileName(m_prompts->dialogParent(), tr("Load Adjustments"), QString(),
                                     tr("Adjustment lists (*.txt);;All files (*)"));
    if (!path.isEmpty())
        loadAdjustments(path);
}

} // namespace lut::gui
