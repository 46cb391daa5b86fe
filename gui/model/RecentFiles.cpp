// SPDX-License-Identifier: Apache-2.0
#include "RecentFiles.h"

#include <QFileInfo>

namespace lut::gui {

QStringList addRecentFile(QStringList list, const QString& path, int maxEntries) {
    const QString canonical = QFileInfo(path).absoluteFilePath();
    list.removeAll(canonical);
    list.prepend(canonical);
    while (list.size() > maxEntries)
        list.removeLast();
    return list;
}

} // namespace lut::gui
