// SPDX-License-Identifier: Apache-2.0
#include "BuiltinNames.h"

#include "lut/io/BuiltinLut.h"

#include <QCoreApplication>

namespace lut::gui {

QString builtinLutTitle(const QString& nameOrPath) {
    const QString prefix = QString::fromLatin1(kBuiltinLutPrefix.data(),
                                               static_cast<qsizetype>(kBuiltinLutPrefix.size()));
    const QString name = nameOrPath.startsWith(prefix) ? nameOrPath.mid(prefix.size()) : nameOrPath;
    if (name == QLatin1String("neutral"))
        return QCoreApplication::translate("lut::gui", "Neutral (no change, 16³)");
    if (name == QLatin1String("smash-default"))
        return QCoreApplication::translate("lut::gui", "Smash Ultimate's default stage LUT");
    return nameOrPath;
}

} // namespace lut::gui
