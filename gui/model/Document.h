#pragma once
// The editor's document: a base LUT, the adjustments on top of it (the effective LUT is base +
// adjustments, what preview and export use), the undo stack and the modified state, plus the
// image being previewed. No widget code: QtCore for signals and QUndoStack (which Qt 6 keeps in
// QtGui, but it needs no windowing), so it is unit-tested without a display.
//
// Failure safety: every operation that reads a file builds the new state completely first and
// only then swaps it in, so a failed open throws lut::Error and leaves the document as it was.
#include "AdjustParam.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/Format.h"
#include "lut/ops/Adjust.h"

#include <QObject>
#include <QString>

#include <memory>

class QUndoStack;

namespace lut::gui {

// Whether a dropped/opened file is a LUT rather than a picture to preview: an extension only
// LUT formats claim, or an image whose size is exactly a LUT layout (strip N^2 x N, Hald L^3).
bool looksLikeLutFile(const QString& path);

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    // ---- LUT -------------------------------------------------------------------------------
    // Starts over from the neutral LUT of edge `size` (untitled, unmodified, empty undo stack).
    void newNeutral(int size = 33);
    // Reads a LUT in any registered format; throws lut::Error (document unchanged) on failure.
    void openLut(const QString& path);
    // Starts from a LUT obtained elsewhere (e.g. extracted from a screenshot). The document is
    // untitled and modified (it exists only in memory). `origin` names where it came from.
    void startFrom(Lut3D base, const QString& origin);
    // Starts from the LUT extracted from a screenshot that carries an embedded, edited patch
    // (lut/roundtrip/Extract.h, raw target). Returns the extractor's warnings to show. Throws
    // lut::Error (document unchanged) when the image cannot be read or holds no patch.
    QStringList startFromScreenshot(const QString& path);

    const Lut3D& baseLut() const { return *m_base; }
    const Lut3D& effectiveLut() const { return *m_effective; }
    // The effective LUT as an immutable shared object for the preview worker.
    std::shared_ptr<const Lut3D> effectiveLutShared() const { return m_effective; }
    QString lutPath() const { return m_lutPath; }  // "" = untitled
    QString lutOrigin() const { return m_origin; } // "neutral 33^3", the file, "extracted ..."
    QString displayName() const;                   // file name or "Untitled"
    QString lutFormat() const { return m_format; } // registry name of the format read

    // ---- adjustments (undoable) --------------------------------------------------------------
    const Adjustments& adjustments() const { return m_adjustments; }
    double param(AdjustParam id) const { return getParam(m_adjustments, id); }
    // Pushes an undo command; consecutive edits of the same parameter within one gesture merge
    // into one undo step. endGesture() closes the gesture (slider released).
    void editParam(AdjustParam id, double value);
    void endGesture() { ++m_gesture; }
    int gesture() const { return m_gesture; }
    void resetAdjustments(); // undoable
    // Sets adjustments without an undo entry: used by the undo commands themselves.
    void applyAdjustmentsState(const Adjustments& a);

    QUndoStack* undoStack() const { return m_undo; }
    bool isModified() const;

    // ---- saving ---------------------------------------------------------------------------
    // Writes the effective LUT with a registered format ("" = by extension); throws lut::Error.
    // Export never changes the document's path or modified state. smashCompensate writes the
    // game-compensated 16^3 LUT (lut::smashGameLut,
    // lut/pipeline/SmashCompensation.h) instead of the LUT as edited.
    Diagnostics exportLut(const QString& path, const QString& formatName = {},
                          const FormatOptions& options = {}, bool smashCompensate = false) const;
    // Save: export to path (format by extension), then path becomes the document's file and the
    // document is clean. Throws lut::Error (document unchanged).
    Diagnostics saveAs(const QString& path);

    // ---- image ----------------------------------------------------------------------------
    // Reads an image (anything OIIO reads); float files count as linear scene values. Throws
    // lut::Error (image unchanged) on failure.
    void openImage(const QString& path);
    bool hasImage() const { return m_image != nullptr; }
    QString imagePath() const { return m_imagePath; }
    // Stored pixel values (display-encoded for 8/16-bit files), and the prepared linear scene.
    std::shared_ptr<const Image> storedImage() const { return m_image; }
    std::shared_ptr<const Image> sceneImage() const { return m_scene; }
    bool imageIsLinear() const { return m_imageLinear; }
    const formats::ImageInfo& imageInfo() const { return m_imageInfo; }
    // An in-game screenshot already went through the game's grading: undo it (with the neutral
    // LUT) when making the scene frame, as `lutkit preview --from-screenshot` does.
    void setFromScreenshot(bool on);
    bool fromScreenshot() const { return m_fromScreenshot; }

signals:
    void lutReplaced();         // a different base LUT (open / new)
    void effectiveLutChanged(); // any change of the effective LUT
    void adjustmentsChanged();
    void modifiedChanged(bool modified);
    void imageChanged();
    void pathChanged();

private:
    void replaceLut(Lut3D base, const QString& path, const QString& origin, const QString& format,
                    bool modified);
    void rebuildEffective();
    void emitModifiedIfChanged();

    std::shared_ptr<const Lut3D> m_base;
    std::shared_ptr<const Lut3D> m_effective;
    Adjustments m_adjustments;
    QString m_lutPath;
    QString m_origin;
    QString m_format;
    bool m_unsavedOrigin = false; // a LUT that came from memory counts as modified until saved
    bool m_lastModified = false;
    int m_gesture = 0;
    QUndoStack* m_undo;

    std::shared_ptr<const Image> m_image;
    std::shared_ptr<const Image> m_scene;
    QString m_imagePath;
    bool m_imageLinear = false;
    bool m_fromScreenshot = false;
    formats::ImageInfo m_imageInfo;
};

} // namespace lut::gui
