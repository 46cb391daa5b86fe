// SPDX-License-Identifier: Apache-2.0
#pragma once
// Recent-file list logic (most recent first, no duplicates, bounded), kept apart from QSettings
// so it is testable.
#include <QStringList>

namespace lut::gui {

QStringList addRecentFile(QStringList list, const QString& path, int maxEntries = 10);

} // namespace lut::gui
