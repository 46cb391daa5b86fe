#include "Document.h"

#include "PreviewRenderer.h"
#include "ResetAdjustmentsCommand.h"
#include "SetAdjustmentCommand.h"

#include "lut/Error.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/Layout.h"
#include "lut/pipeline/SmashCompensation.h"
#include "lut/roundtrip/Extract.h"

#include <QFileInfo>
#include <QUndoStack>

namespace lut::gui {

bool looksLikeLutFile(const QString& path) {
    formats::registerBuiltinFormats();
    const std::string p = path.toStdString();
    const std::string ext = extensionOf(p);
    const bool pictureExt = ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr" ||
                            ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tga" ||
                            ext == ".webp" || ext == ".hdr" || ext == ".dpx";
    if (!pictureExt)
        return !FormatRegistry::instance().forExtension(p).empty();
    try {
        const formats::ImageInfo info = formats::readImageInfo(p);
        return !layoutsForImageSize(info.width, info.height).empty();
    } catch (const std::exception&) {
        return false;
    }
}

Document::Document(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this)) {
    connect(m_undo, &QUndoStack::cleanChanged, this, [this] { emitModifiedIfChanged(); });
    replaceLut(Lut3D::identity(33), {}, tr("neutral 33^3"), {}, false);
}

Document::~Document() = default;

QString Document::displayName() const {
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

void Document::replaceLut(Lut3D base, const QString& path, const QString& origin,
                          const QString& format, bool modified) {
    auto baseShared = std::make_shared<const Lut3D>(std::move(base));
    m_base = baseShared;
    m_effective = baseShared; // neutral adjustments: the effective LUT is the base itself
    m_adjustments = Adjustments{};
    m_lutPath = path;
    m_origin = origin;
    m_format = format;
    m_unsavedOrigin = modified;
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
    replaceLut(std::move(lut), {}, tr("neutral %1^3").arg(size), {}, false);
}

void Document::openLut(const QString& path) {
    const LutFile file = formats::readLut(path.toStdString());
    Lut3D lut = file.toLut3D();
    replaceLut(std::move(lut), path, path, QString::fromStdString(file.format), false);
}

void Document::startFrom(Lut3D base, const QString& origin) {
    if (base.empty())
        throw Error("the LUT is empty");
    replaceLut(std::move(base), {}, origin, {}, true);
}

QStringList Document::startFromScreenshot(const QString& path) {
    formats::LoadedImage loaded = formats::readImage(path.toStdString());
    ExtractOptions options;
    options.target = ExtractTarget::Raw;
    ExtractResult result = extractLut(loaded.image.view(), options);
    QStringList notes;
    for (const Diagnostic& d : result.diagnostics)
        notes << QString::fromStdString(d.str());
    startFrom(std::move(result.lut), tr("extracted from %1").arg(QFileInfo(path).fileName()));
    return notes;
}

void Document::editParam(AdjustParam id, double value) {
    const double before = param(id);
    if (before == value)
        return;
    m_undo->push(new SetAdjustmentCommand(this, id, before, value, m_gesture));
}

void Document::resetAdjustments() {
    if (m_adjustments.isNeutral())
        return;
    m_undo->push(new ResetAdjustmentsCommand(this, m_adjustments));
    ++m_gesture;
}

void Document::applyAdjustmentsState(const Adjustments& a) {
    if (a == m_adjustments)
        return;
    m_adjustments = a;
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

Diagnostics Document::exportLut(const QString& path, const QString& formatName,
                                const FormatOptions& options, bool smashCompensate) const {
    LutFile file;
    file.cube = smashCompensate ? smashGameLut(*m_effective) : *m_effective;
    return formats::writeLut(path.toStdString(), file, options, formatName.toStdString());
}

Diagnostics Document::saveAs(const QString& path) {
    Diagnostics d = exportLut(path);
    m_lutPath = path;
    m_origin = path;
    m_unsavedOrigin = false;
    m_undo->setClean();
    emit pathChanged();
    emitModifiedIfChanged();
    return d;
}

void Document::openImage(const QString& path) {
    formats::LoadedImage loaded = formats::readImage(path.toStdString());
    // A screenshot holds display-encoded values whatever its bit depth (as lutkit preview).
    const bool linear = loaded.info.isFloat && !m_fromScreenshot;
    auto scene =
        std::make_shared<const Image>(prepareScene(loaded.image, linear, m_fromScreenshot));
    m_image = std::make_shared<const Image>(std::move(loaded.image));
    m_scene = std::move(scene);
    m_imagePath = path;
    m_imageLinear = linear;
    m_imageInfo = loaded.info;
    emit imageChanged();
}

void Document::setFromScreenshot(bool on) {
    if (on == m_fromScreenshot)
        return;
    m_fromScreenshot = on;
    if (!m_image)
        return;
    m_imageLinear = m_imageInfo.isFloat && !on;
    m_scene = std::make_shared<const Image>(prepareScene(*m_image, m_imageLinear, on));
    emit imageChanged();
}

} // namespace lut::gui
