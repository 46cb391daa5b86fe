// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the File menu does: open a picture, a LUT or an edited screenshot, start from neutral,
// save, export, save the preview image, save and load the adjustment list, the recent-file
// lists, and the questions that keep the user's files: unsaved changes (no default that loses
// anything), replacing an existing file, replacing the opened original.
//
// Pictures and LUTs are read on a worker (FileLoader): start* returns at once with a progress
// indicator in the status bar, and the document takes the file when it arrives; the other forms
// wait for it (processing events) and say whether it worked. Each operation reports its error
// through the prompts (Prompts.h: a dialog, or stderr when headless) and leaves the document as it
// was.
#include "ExportTarget.h"

#include "lut/Image.h"
#include "lut/LutPurpose.h"
#include "lut/io/Format.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>

class QMenu;

namespace lut::gui {

class BackgroundTask;
class Document;
class FileLoader;
class PreviewController;
class Prompts;
struct EditorContext;

class FileActions : public QObject {
    Q_OBJECT
public:
    // Works on the context's document and preview; asks and reports through its prompts.
    FileActions(const EditorContext& context, QObject* parent);

    FileLoader* loader() const { return m_loader; }
    // Reading on the worker; false when nothing started (the user kept unsaved changes).
    bool startOpenImage(const QString& path);
    bool startOpenLut(const QString& path, const FormatOptions& options = {});
    // As File > Open LUT does (and a drop): a picture that fits several strip layouts (256x16)
    // is asked its layout first (interactive only; headless: detected). false: the user cancelled.
    bool openLutAsking(const QString& path);
    // The same, waiting for the file: true when the document took it.
    bool openImage(const QString& path);
    bool openLut(const QString& path, const FormatOptions& options = {});
    bool openScreenshotLut(const QString& path);
    void newNeutral(int size);
    // Save: to the LUT's file (asking first when that would replace the opened original), or
    // Save As when it has none or its format cannot write.
    bool save();
    bool saveAs(const QString& path);
    // Writes the table `target` exports in `format`. An existing file is replaced only when
    // `overwrite` is true or the user says so (headless: refused). `strength`: the edit blended
    // with neutral first (lut/ops/Strength.h).
    bool exportLut(const QString& path, const QString& format, const FormatOptions& options,
                   ExportTarget target, bool overwrite = false,
                   const StrengthOptions& strength = {});
    // The full-resolution preview with the current settings, written the way `lutkit preview`
    // does (lut::formats::renderedImageWriteOptions: 8-bit unless the extension is float), on a
    // worker (saveTask: progress and Cancel in the status bar). start* returns at once; the
    // other form waits and says whether the file was written.
    bool startSavePreview(const QString& path);
    bool savePreviewImage(const QString& path);
    BackgroundTask* saveTask() const { return m_saveTask; }
    // A picture made by the tools (the LUT plot, a heat map), written the way lutkit plot and
    // lutkit diff write theirs (8-bit RGB; the format by extension). An existing file is
    // replaced only when `overwrite` is true or the user says so (headless: refused).
    bool savePicture(const QString& path, const Image& image, bool overwrite = false);
    bool saveAdjustments(const QString& path);
    bool loadAdjustments(const QString& path);
    // Asks Save As (Save once the original was replaced in this session) / Discard / Cancel
    // when the document is modified; Cancel is the default. true = go on. Headless: no question.
    bool maybeSave();

    // The menus the recent files go into (filled now and after every open or save).
    void setRecentMenus(QMenu* images, QMenu* luts);

    void openImageDialog();
    void openLutDialog();
    void openScreenshotDialog();
    void saveAsDialog();
    void exportDialog();
    void savePreviewDialog();
    void saveAdjustmentsDialog();
    void loadAdjustmentsDialog();

    // File dialog filters: the picture formats, and every extension a LUT format reads.
    static QString imageFilter();
    static QString lutFilter();

    // What a LUT file that does not say what it is for (lut/LutPurpose.h) is taken for: the
    // window's answer (--lut-target, scripts), else the answer remembered for that file, else
    // the user's, asked once (interactive only) and remembered per file; nullopt: taken as an
    // edit with a note. *cancelled: the user cancelled the question (the file is not opened).
    std::optional<LutPurpose> purposeFor(const QString& path, const LutFile& file, bool* cancelled);
    // The answers remembered, by absolute path (none when headless: settings are left alone).
    static std::optional<LutPurpose> rememberedPurpose(const QString& path);
    static void rememberPurpose(const QString& path, LutPurpose purpose);

private:
    // Asks whether to replace `path` (named in full); `original` says it is the opened LUT.
    bool confirmReplace(const QString& path, bool original);
    bool isOpenedLut(const QString& path) const;
    // The layout question of Open LUT; false when the user cancelled it.
    bool askStripLayout(const QString& path, FormatOptions& options);
    void addRecent(const char* key, const QString& path);
    void updateRecentMenus();
    void showStatus(const QString& message);

    Document* m_doc;
    PreviewController* m_preview;
    Prompts* m_prompts;
    FileLoader* m_loader;
    BackgroundTask* m_saveTask;
    QMenu* m_recentImages = nullptr;
    QMenu* m_recentLuts = nullptr;
    // The result of the last read that finished, for the waiting forms.
    QString m_lastDone;
    bool m_lastOk = false;
};

} // namespace lut::gui
