// SPDX-License-Identifier: Apache-2.0
#include "ExportNaming.h"

#include <QDir>
#include <QFileInfo>

namespace lut::gui {

namespace {

bool sameFile(const QString& a, const QString& b) {
    if (a.isEmpty() || b.isEmpty())
        return false;
    const QFileInfo fa(a), fb(b);
    const QString ca = fa.canonicalFilePath(), cb = fb.canonicalFilePath();
    if (!ca.isEmpty() && !cb.isEmpty())
        return ca == cb; // symlinks and ./.. resolved
    return QDir::cleanPath(fa.absoluteFilePath()) == QDir::cleanPath(fb.absoluteFilePath());
}

} // namespace

QString suggestedExportPath(const ExportNameInput& in) {
    QStringList folders;
    if (!in.lutPath.isEmpty())
        folders << QFileInfo(in.lutPath).absolutePath();
    if (!in.imagePath.isEmpty())
        folders << QFileInfo(in.imagePath).absolutePath();
    folders << (in.fallbackFolder.isEmpty() ? QDir::currentPath() : in.fallbackFolder);
    auto isOpened = [&](const QString& path) {
        return sameFile(path, in.lutPath) || sameFile(path, in.imagePath);
    };

    if (in.format == QLatin1String("nutexb")) {
        // Every stage's LUT has this one name, so the folder is what matters: beside the opened
        // LUT (its stage), never in the screenshot's folder while a LUT is open; when that file is
        // the opened LUT, the documented "edited" folder beside it. A file there already (an
        // earlier export) is replaced only after the question that names its full path.
        const QString name = QStringLiteral("color_grading_lut") + in.extension;
        const QString beside = QDir(folders.front()).filePath(name);
        if (!isOpened(beside))
            return beside;
        return QDir(folders.front()).filePath(QStringLiteral("edited/") + name);
    }
    QString base = !in.lutPath.isEmpty()     ? QFileInfo(in.lutPath).completeBaseName()
                   : !in.imagePath.isEmpty() ? QFileInfo(in.imagePath).completeBaseName()
                                             : QStringLiteral("grade");
    QString key = in.gameLut ? QStringLiteral("game_") + in.format : in.format;
    if (!in.layout.isEmpty())
        key += QLatin1Char('_') + in.layout;
    QString path = QDir(folders.front()).filePath(base + QLatin1Char('_') + key + in.extension);
    // <name>_<format> can only be an opened file if that file was named so: add a suffix then.
    for (int i = 2; isOpened(path); ++i)
        path = QDir(folders.front())
                   .filePath(base + QLatin1Char('_') + key + QStringLiteral("_%1").arg(i) +
                             in.extension);
    return path;
}

} // namespace lut::gui
