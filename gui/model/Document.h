// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor's document: a base LUT, the adjustments on top of it (the effective LUT is base +
// adjustments), the undo stack and the modified state, plus the picture being previewed. No
// widget code: QtCore for signals and QUndoStack (which Qt 6 keeps in QtGui, but it needs no
// windowing), so it is unit-tested without a display.
//
// The base is for a purpose (lut/LutPurpose.h): an edit (raw: a LUT on display colours, .cube,
// strips, neutral...) or the game's LUT (smash: what Smash Ultimate applies in its grading pass,
// brighten included: a .nutexb, a file that says so, or one the user said is). The Smash export
// of an edit is the game LUT that shows it; of a game LUT with adjustments, the game LUT whose
// picture is the adjusted picture of the base; the other exports of a game LUT, the edit it makes
// with the adjustments on it (lutSource(), ExportTarget.h).
//
// Files are read elsewhere (FileLoader, on a worker): the read results are adopted here. Every
// adopt builds the new state completely first and only then swaps it in, so a failure throws
// lut::Error and leaves the document as it was.
#include "AdjustParam.h"
#include "ExportTarget.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/LutPurpose.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/Format.h"
#include "lut/ops/Adjust.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

class QUndoStack;

namespace lut::gui {

// Whether a dropped/opened file is a LUT rather than a picture to preview: an extension only
// LUT formats claim, or an image whose size is exactly a LUT layout (strip N^2 x N, Hald L^3).
bool looksLikeLutFile(const QString& path);
// Whether a LUT picture's size fits more than one strip layout (a layout choice is worth asking).
bool stripLayoutIsAmbiguous(const QString& path);

// Which curve of lut::Adjustments a curve editor edits.
enum class CurveId { Master, Red, Green, Blue, HueVsHue, HueVsSat, HueVsLum };
// A curve as the undo text and the History name it ("red curve", "hue vs saturation").
const char* curveLabel(CurveId id);
Curve& curveOf(Adjustments& a, CurveId id);
const Curve& curveOf(const Adjustments& a, CurveId id);

// The export "format" that adds the LUT as a row of an atlas (not a registered format).
inline constexpr const char* kAtlasFormat = "atlas";

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    // ---- LUT -------------------------------------------------------------------------------
    // Starts over from the neutral LUT of edge `size` (untitled, unmodified, empty undo stack).
    void newNeutral(int size = 33);
    // Reads a LUT in any registered format (on the calling thread; FileLoader reads on a
    // worker and calls adoptLut). Returns the reader's notes. Throws lut::Error, document
    // unchanged.
    QStringList openLut(const QString& path, const FormatOptions& options = {});
    // Takes a LUT file read elsewhere as the new document; returns the reader's notes to show.
    // `answer` is what the user said the file is for (it counts only when the file does not say:
    // lut::decidePurpose); without one, a file that does not say is taken as an edit and a note
    // says so.
    QStringList adoptLut(const LutFile& file, const QString& path,
                         std::optional<LutPurpose> answer = std::nullopt);
    // Starts from a LUT obtained elsewhere (e.g. extracted from a screenshot). The document is
    // untitled and modified (it exists only in memory). `origin` names where it came from.
    void startFrom(Lut3D base, const QString& origin);
    // Starts from the LUT extracted from a screenshot that carries an embedded, edited patch
    // (lut/roundtrip/Extract.h, raw target). Returns the extractor's warnings to show. Throws
    // lut::Error (document unchanged) when the image cannot be read or holds no patch.
    QStringList startFromScreenshot(const QString& path);
    // Replaces the LUT by one made from the document (Tools > Match to Reference) as one undo
    // step: the LUT becomes an untitled, modified edit with neutral adjustments; Undo gives back
    // the LUT, adjustments, file and purpose it had. `origin` names where it came from, `text`
    // the undo step. Throws lut::Error (an empty LUT), document unchanged.
    void replaceLutUndoable(Lut3D base, const QString& origin, const QString& text);

    // Everything a LUT replacement changes (ReplaceLutCommand keeps one before and one after).
    struct LutState {
        std::shared_ptr<const Lut3D> base;
        Adjustments adjustments;
        LutPurpose purpose = LutPurpose::Raw;
        bool purposeKnown = false;
        QString path, origin, format;
        QStringList notes;
        bool unsavedOrigin = false, savedOnce = false;
        std::optional<LutLayout> layout;
    };
    LutState lutState() const;
    void restoreLutState(const LutState& state); // no undo entry (the command's undo and redo)

    // ---- what the document is made for ------------------------------------------------------
    // The export target (ExportTarget.h): the game's LUT, an engine strip or a grading .cube.
    // The preview grades with its export and the window's exports default to it. A choice of
    // output, not an edit: no undo step, and opening another LUT or picture keeps it.
    ExportTarget target() const { return m_target; }
    void setTarget(ExportTarget target); // targetChanged() when it differs

    const Lut3D& baseLut() const { return *m_base; }
    const Lut3D& effectiveLut() const { return *m_effective; }
    std::shared_ptr<const Lut3D> effectiveLutShared() const { return m_effective; }
    // What the base is for, and how that was decided (the file, its format, the user).
    LutPurpose lutPurpose() const { return m_purpose; }
    // What exports and the preview are made from (ExportTarget.h).
    LutSource lutSource() const;
    QString lutPath() const { return m_lutPath; }  // "" = untitled
    QString lutOrigin() const { return m_origin; } // "neutral 33^3", the file, "extracted ..."
    QString displayName() const;                   // file name or "Untitled"
    QString lutFormat() const { return m_format; } // registry name of the format read
    // The strip layout the LUT was read in (a strip file: the layout named or detected), else
    // none: the LUT dock shows the slices in it.
    std::optional<LutLayout> lutLayout() const { return m_layout; }
    QStringList lutNotes() const { return m_notes; } // what the reader said about the file

    // ---- adjustments (undoable) --------------------------------------------------------------
    const Adjustments& adjustments() const { return m_adjustments; }
    double param(AdjustParam id) const { return getParam(m_adjustments, id); }
    // Pushes an undo command; consecutive edits with the same merge key within one gesture merge
    // into one undo step. endGesture() closes the gesture (slider released).
    void editParam(AdjustParam id, double value);
    void editCurve(CurveId id, const Curve& curve);
    // Any edit of the adjustments; mergeKey < 0 never merges.
    void editAdjustments(const Adjustments& after, int mergeKey, const QString& text);
    void endGesture() { ++m_gesture; }
    int gesture() const { return m_gesture; }
    void resetAdjustments(); // undoable
    // Sets adjustments without an undo entry: used by the undo commands themselves.
    void applyAdjustmentsState(const Adjustments& a);

    // The adjustment list (lut/ops/AdjustmentList.h): what `lutkit` can apply to a LUT. Loading
    // replaces the adjustments in one undo step. Both throw lut::Error naming the file.
    void saveAdjustmentList(const QString& path) const;
    void loadAdjustmentList(const QString& path);

    QUndoStack* undoStack() const { return m_undo; }
    bool isModified() const;
    // Whether saving would replace a file that was opened and not yet saved in this session.
    bool savingReplacesOriginal() const { return !m_lutPath.isEmpty() && !m_savedOnce; }

    // ---- saving ---------------------------------------------------------------------------
    // Writes the table `target` exports (exportTable) with a registered format ("" = by
    // extension), or as a row of an atlas (format kAtlasFormat, options.layout its rows' layout:
    // AtlasExport.h); throws lut::Error. Never changes the document's path or modified state.
    // `strength`: the edit blended with neutral first (lut/ops/Strength.h, lutkit --strength).
    Diagnostics exportLut(const QString& path, const QString& formatName,
                          const FormatOptions& options, ExportTarget target,
                          const StrengthOptions& strength = {}) const;
    // Save: writes the document's LUT (the look, or for a game LUT the game LUT with the edit,
    // as the Smash export), then path becomes the document's file and the document is clean.
    // Throws lut::Error (document unchanged).
    Diagnostics saveAs(const QString& path);

    // ---- image ----------------------------------------------------------------------------
    // Reads an image on the calling thread (FileLoader reads on a worker and calls adoptImage).
    // Throws lut::Error, image unchanged.
    void openImage(const QString& path);
    void adoptImage(formats::LoadedImage image, const QString& path);
    bool hasImage() const { return m_image != nullptr; }
    QString imagePath() const { return m_imagePath; }
    // Stored pixel values (display-encoded for 8/16-bit files).
    std::shared_ptr<const Image> storedImage() const { return m_image; }
    const formats::ImageInfo& imageInfo() const { return m_imageInfo; }

signals:
    void lutReplaced();         // a different base LUT (open / new)
    void effectiveLutChanged(); // any change of the effective LUT
    void adjustmentsChanged();
    void modifiedChanged(bool modified);
    void imageChanged();
    void pathChanged();
    void targetChanged();

private:
    void replaceLut(Lut3D base, const QString& path, const QString& origin, const QString& format,
                    bool modified, LutPurpose purpose, QStringList notes);
    void rebuildEffective();
    void emitModifiedIfChanged();

    std::shared_ptr<const Lut3D> m_base;
    std::shared_ptr<const Lut3D> m_effective;
    std::shared_ptr<const Adjustments> m_adjustmentsShared;
    Adjustments m_adjustments;
    LutPurpose m_purpose = LutPurpose::Raw;
    ExportTarget m_target = ExportTarget::Smash;
    bool m_purposeKnown = false; // said by the file or the user (else assumed: not written)
    QString m_lutPath;
    QString m_origin;
    QString m_format;
    QStringList m_notes;
    std::optional<LutLayout> m_layout;
    bool m_unsavedOrigin = false; // a LUT that came from memory counts as modified until saved
    bool m_savedOnce = false;     // saved to m_lutPath in this session
    bool m_lastModified = false;
    int m_gesture = 0;
    QUndoStack* m_undo;

    std::shared_ptr<const Image> m_image;
    QString m_imagePath;
    formats::ImageInfo m_imageInfo;
};

} // namespace lut::gui
