// SPDX-License-Identifier: Apache-2.0
#include "Document.h"

#include "AtlasExport.h"
#include "BuiltinNames.h"
#include "ReplaceLutCommand.h"
#include "SetAdjustmentsCommand.h"

#include "lut/Error.h"
#include "lut/formats/ExtractFile.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/BuiltinLut.h"
#include "lut/io/FileNames.h"
#include "lut/io/Layout.h"
#include "lut/ops/AdjustmentList.h"
#include "lut/ops/Lattice.h"
#include "lut/roundtrip/Extract.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

namespace lut::gui {

namespace {

bool hasPictureExtension(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr" || ext == ".jpg" ||
           ext == ".jpeg" || ext == ".bmp" || ext == ".tga" || ext == ".webp" || ext == ".hdr" ||
           ext == ".dpx";
}

// Merge keys: a parameter's id, a curve's 100 + id (AdjustmentsPanel and the curve editors).
constexpr int kCurveKeyBase = 100;

} // namespace

const char* curveLabel(CurveId id) {
    switch (id) {
    case CurveId::Master:
        return "master curve";
    case CurveId::Red:
        return "red curve";
    case CurveId::Green:
        return "green curve";
    case CurveId::Blue:
        return "blue curve";
    case CurveId::HueVsHue:
        return "hue vs hue";
    case CurveId::HueVsSat:
        return "hue vs saturation";
    case CurveId::HueVsLum:
        return "hue vs luminance";
    }
    return "curve";
}

bool looksLikeLutFile(const QString& path) {
    formats::registerBuiltinFormats();
    const std::string p = path.toStdString();
    if (isBuiltinLutName(p)) // builtin:smash-default ...: a LUT known by name
        return true;
    if (!hasPictureExtension(p))
        return !FormatRegistry::instance().forExtension(p).empty();
    try {
        const formats::ImageInfo info = formats::readImageInfo(p);
        return !layoutsForImageSize(info.width, info.height).empty();
    } catch (const std::exception&) {
        return false;
    }
}

bool stripLayoutIsAmbiguous(const QString& path) {
    const std::string p = path.toStdString();
    if (!hasPictureExtension(p))
        return false;
    try {
        const formats::ImageInfo info = formats::readImageInfo(p);
        return layoutsForImageSize(info.width, info.height).size() > 1;
    } catch (const std::exception&) {
        return false;
    }
}

Curve& curveOf(Adjustments& a, CurveId id) {
    switch (id) {
    case CurveId::Master:
        return a.curveMaster;
    case CurveId::Red:
        return a.curveRed;
    case CurveId::Green:
        return a.curveGreen;
    case CurveId::Blue:
        return a.curveBlue;
    case CurveId::HueVsHue:
        return a.hueVsHue;
    case CurveId::HueVsSat:
        return a.hueVsSat;
    case CurveId::HueVsLum:
        return a.hueVsLum;
    }
    return a.curveMaster;
}

const Curve& curveOf(const Adjustments& a, CurveId id) {
    return curveOf(const_cast<Adjustments&>(a), id);
}

Document::Document(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this)) {
    connect(m_undo, &QUndoStack::cleanChanged, this, [this] { emitModifiedIfChanged(); });
    replaceLut(Lut3D::identity(33), {}, tr("neutral 33^3"), {}, false, LutPurpose::Raw, {});
}

Document::~Document() = default;

void Document::setTarget(ExportTarget target) {
    if (target == m_target)
        return;
    m_target = target;
    emit targetChanged();
}

QString Document::displayName() const {
    if (m_lutPath.isEmpty() && m_format == QLatin1String("builtin"))
        return m_origin; // a built-in LUT by its name (BuiltinNames.h); Save asks where
    return m_lutPath.isEmpty() ? tr("Untitled") : QFileInfo(m_lutPath).fileName();
}

bool Document::isModified() const {
    return m_unsavedOrigin || !m_undo->isClean();
}

void Document::emitModifiedIfChanged() {
    const bool now = isModified();
    if (now != m_lastModified) {
        m_lastModified = now;
        emit modifiedChanged(now);
    }
}

LutSource Document::lutSource() const {
    LutSource s;
    s.effective = m_effective;
    if (m_purpose == LutPurpose::Smash) {
        s.gameBase = m_base;
        s.adjustments = m_adjustmentsShared;
    }
    return s;
}

void Document::replaceLut(Lut3D base, const QString& path, const QString& origin,
                          const QString& format, bool modified, LutPurpose purpose,
                          QStringList notes) {
    auto baseShared = std::make_shared<const Lut3D>(std::move(base));
    m_base = baseShared;
    m_effective = baseShared; // neutral adjustments: the effective LUT is the base itself
    m_adjustments = Adjustments{};
    m_adjustmentsShared = std::make_shared<const Adjustments>();
    m_purpose = purpose;
    m_lutPath = path;
    m_origin = origin;
    m_format = format;
    m_notes = std::move(notes);
    m_unsavedOrigin = modified;
    m_savedOnce = false;
    ++m_gesture;
    m_undo->clear();
    m_undo->setClean();
    emit lutReplaced();
    emit adjustmentsChanged();
    emit effectiveLutChanged();
    emit pathChanged();
    emitModifiedIfChanged();
}

void Document::newNeutral(int size) {
    Lut3D lut = Lut3D::identity(size); // throws for a bad size before anything changes
    m_layout.reset();
    replaceLut(std::move(lut), {}, tr("neutral %1^3").arg(size), {}, false, LutPurpose::Raw, {});
    m_purposeKnown = false;
}

QStringList Document::openLut(const QString& path, const FormatOptions& options) {
    return adoptLut(formats::readLut(path.toStdString(), options), path);
}

QStringList Document::adoptLut(const LutFile& file, const QString& path,
                               std::optional<LutPurpose> answer) {
    QStringList notes;
    for (const Diagnostic& d : file.diagnostics)
        notes << QString::fromStdString(d.str());
    Lut3D lut;
    if (file.shaper) {
        // The editor works on one table: the shaper then the table sampled at its lattice over
        // the shaper's range, with what that costs between lattice points (never silently).
        LatticeResult r = sampleOnLattice(file);
        r.error.seconds = 0.0;
        notes << tr("%1: its 1D shaper and table taken as one %2^3 table over the shaper's range: "
                    "%3 on %4 inputs between lattice points")
                     .arg(path)
                     .arg(r.lut.size())
                     .arg(QString::fromStdString(r.error.str()))
                     .arg(r.heldOut);
        lut = std::move(r.lut);
    } else {
        lut = file.toLut3D();
    }
    // What the file says first (a built-in game LUT says it is one, as a .nutexb does); the
    // user's answer only where it says nothing.
    const PurposeDecision purpose =
        decidePurpose(file, file.purpose ? std::nullopt : answer, LutPurpose::Raw);
    if (purpose.source == PurposeSource::Content)
        notes << tr("%1 does not say what it is for: taken as the game's LUT, as its content says "
                    "(%2); open it again and answer, or lutkit-editor --lut-target raw, if it is "
                    "an edit")
                     .arg(QFileInfo(path).fileName(), QString::fromStdString(purpose.evidence));
    if (purpose.source == PurposeSource::Assumed)
        notes << tr("%1 does not say what it is for: taken as an edit (raw); open it again and "
                    "answer, or lutkit-editor --lut-target smash, if it is the game's LUT")
                     .arg(QFileInfo(path).fileName());
    // A built-in LUT is no file: the document is untitled (Save asks where), named by its origin.
    const bool builtin = file.format == "builtin";
    m_layout = file.format == "strip" ? parseOptionalLayout(file.dialect) : std::nullopt;
    replaceLut(std::move(lut), builtin ? QString() : path, builtin ? builtinLutTitle(path) : path,
               QString::fromStdString(file.format), false, purpose.purpose, notes);
    m_purposeKnown = purpose.source != PurposeSource::Assumed;
    return notes;
}

void Document::startFrom(Lut3D base, const QString& origin) {
    if (base.empty())
        throw Error("the LUT is empty");
    m_layout.reset();
    replaceLut(std::move(base), {}, origin, {}, true, LutPurpose::Raw, {});
    m_purposeKnown = true; // made here as an edit
}

void Document::replaceLutUndoable(Lut3D base, const QString& origin, const QString& text) {
    if (base.empty())
        throw Error("the LUT is empty");
    LutState after;
    after.base = std::make_shared<const Lut3D>(std::move(base));
    after.purposeKnown = true; // made here as an edit
    after.origin = origin;
    after.unsavedOrigin = true; // it exists only in memory until saved
    ++m_gesture;
    m_undo->push(new ReplaceLutCommand(this, lutState(), std::move(after), text));
}

Document::LutState Document::lutState() const {
    return LutState{m_base,   m_adjustments, m_purpose,       m_purposeKnown, m_lutPath, m_origin,
                    m_format, m_notes,       m_unsavedOrigin, m_savedOnce,    m_layout};
}

void Document::restoreLutState(const LutState& s) {
    m_base = s.base;
    m_adjustments = s.adjustments;
    m_adjustmentsShared = std::make_shared<const Adjustments>(s.adjustments);
    rebuildEffective();
    m_purpose = s.purpose;
    m_purposeKnown = s.purposeKnown;
    m_lutPath = s.path;
    m_origin = s.origin;
    m_format = s.format;
    m_notes = s.notes;
    m_unsavedOrigin = s.unsavedOrigin;
    m_savedOnce = s.savedOnce;
    m_layout = s.layout;
    emit lutReplaced();
    emit adjustmentsChanged();
    emit effectiveLutChanged();
    emit pathChanged();
    emitModifiedIfChanged();
}

QStringList Document::startFromScreenshot(const QString& path) {
    // The library reads it as lutkit extract does (a patch, a graded strip, a Smush-LUT strip),
    // and makes the edit of it.
    formats::ExtractFileOptions options;
    options.extract.target = LutPurpose::Raw;
    formats::ExtractFileResult result = formats::extractLutFromFile(path.toStdString(), options);
    QStringList notes;
    if (result.extract)
        for (const Diagnostic& d : result.extract->diagnostics)
            notes << QString::fromStdString(d.str());
    if (result.image)
        for (const Diagnostic& d : result.image->diagnostics)
            notes << QString::fromStdString(d.str());
    startFrom(std::move(result.lut), tr("extracted from %1").arg(QFileInfo(path).fileName()));
    return notes;
}

void Document::editParam(AdjustParam id, double value) {
    Adjustments a = m_adjustments;
    setParam(a, id, value);
    editAdjustments(a, static_cast<int>(id),
                    tr("Set %1").arg(QString::fromStdString(adjustParamInfo(id).label)));
}

void Document::editCurve(CurveId id, const Curve& curve) {
    Adjustments a = m_adjustments;
    curveOf(a, id) = curve;
    editAdjustments(a, kCurveKeyBase + static_cast<int>(id),
                    tr("Edit %1").arg(QString::fromLatin1(curveLabel(id))));
}

void Document::editAdjustments(const Adjustments& after, int mergeKey, const QString& text) {
    if (after == m_adjustments)
        return;
    m_undo->push(new SetAdjustmentsCommand(this, m_adjustments, after, mergeKey, m_gesture, text));
}

void Document::resetAdjustments() {
    if (m_adjustments == Adjustments{})
        return;
    editAdjustments(Adjustments{}, -1, tr("Reset adjustments"));
    ++m_gesture;
}

void Document::applyAdjustmentsState(const Adjustments& a) {
    if (a == m_adjustments)
        return;
    m_adjustments = a;
    m_adjustmentsShared = std::make_shared<const Adjustments>(a);
    rebuildEffective();
    emit adjustmentsChanged();
    emit effectiveLutChanged();
}

void Document::rebuildEffective() {
    if (m_adjustments.isNeutral())
        m_effective = m_base;
    else
        m_effective = std::make_shared<const Lut3D>(applyAdjustments(*m_base, m_adjustments));
}

void Document::saveAdjustmentList(const QString& path) const {
    const std::string text = formatAdjustmentList(m_adjustments);
    writeFileAtomically(path.toStdString(), text);
}

void Document::loadAdjustmentList(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        throw Error(path.toStdString() + ": cannot read: " + f.errorString().toStdString());
    const QByteArray bytes = f.readAll();
    const Adjustments a = parseAdjustmentList(
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
        path.toStdString());
    editAdjustments(a, -1, tr("Load adjustments %1").arg(QFileInfo(path).fileName()));
    ++m_gesture;
}

Diagnostics Document::exportLut(const QString& path, const QString& formatName,
                                const FormatOptions& options, ExportTarget target,
                                const StrengthOptions& strength) const {
    LutFile file;
    file.cube = exportTable(lutSource(), target, strength);
    file.purpose = exportTargetInfo(target).purpose; // the file says what it is for
    if (formatName == QLatin1String(kAtlasFormat))   // a row of an atlas (AtlasExport.h)
        return exportAtlasRow(*file.cube, *file.purpose, path,
                              options.layout.value_or(LutLayout::Reshade))
            .diagnostics;
    return formats::writeLut(path.toStdString(), file, options, formatName.toStdString());
}

Diagnostics Document::saveAs(const QString& path) {
    Diagnostics d;
    if (m_purpose == LutPurpose::Smash) {
        d = exportLut(path, {}, {}, ExportTarget::Smash);
    } else {
        LutFile file;
        file.cube = *m_effective;
        // An edit saved says so when that is known (an assumption is not turned into a tag).
        if (m_purposeKnown)
            file.purpose = LutPurpose::Raw;
        d = formats::writeLut(path.toStdString(), file, {}, {});
    }
    m_lutPath = path;
    m_origin = path;
    m_unsavedOrigin = false;
    m_savedOnce = true;
    m_undo->setClean();
    emit pathChanged();
    emitModifiedIfChanged();
    return d;
}

void Document::openImage(const QString& path) {
    adoptImage(formats::readImage(path.toStdString()), path);
}

void Document::adoptImage(formats::LoadedImage loaded, const QString& path) {
    if (loaded.image.empty())
        throw Error(path.toStdString() + ": the image is empty");
    m_image = std::make_shared<const Image>(std::move(loaded.image));
    m_imagePath = path;
    m_imageInfo = loaded.info;
    emit imageChanged();
}

} // namespace lut::gui
