// SPDX-License-Identifier: Apache-2.0
#pragma once
// Keeps the window's shortcuts working from every widget: a spin box (its line edit) claims
// Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y and even Ctrl+E (end of line) for itself, so after typing a value
// and pressing Enter, undo and export did nothing until the user clicked elsewhere. Installed on
// the application, it refuses those claims (the ShortcutOverride event) for any key sequence
// that is a shortcut of one of the window's actions and has a Ctrl or Alt modifier; plain keys
// (digits, letters) stay with the widget being typed in.
#include <QObject>

class QWidget;

namespace lut::gui {

class ShortcutGuard : public QObject {
    Q_OBJECT
public:
    // Guards the shortcuts of `window`'s actions for widgets inside `window`.
    explicit ShortcutGuard(QWidget* window);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* m_window;
};

} // namespace lut::gui
