// SPDX-License-Identifier: Apache-2.0
#include "ShortcutGuard.h"

#include <QAction>
#include <QKeyEvent>
#include <QWidget>

namespace lut::gui {

ShortcutGuard::ShortcutGuard(QWidget* window) : QObject(window), m_window(window) {}

bool ShortcutGuard::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride)
        return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || (widget != m_window && !m_window->isAncestorOf(widget)))
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (!(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier)))
        return false;
    const QKeySequence pressed(key->keyCombination());
    for (const QAction* a : m_window->findChildren<QAction*>()) {
        if (!a->isEnabled())
            continue;
        for (const QKeySequence& s : a->shortcuts())
            if (s.matches(pressed) == QKeySequence::ExactMatch) {
                event->ignore(); // not overridden: the shortcut map triggers the action
                return true;
            }
    }
    return false;
}

} // namespace lut::gui
