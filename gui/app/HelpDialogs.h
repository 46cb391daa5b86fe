// SPDX-License-Identifier: Apache-2.0
#pragma once
// Help > Quick Start and Help > Keyboard Shortcuts: two small windows beside the editor (not
// modal). The shortcuts are read from the window's own actions when the list opens, so the list
// is what the keys do, never a copy that drifts; the few keys that are no menu action (the
// slider's, the preview's) are added by hand.
class QMainWindow;
class QWidget;

namespace lut::gui {

// Object name "help.quickStart"; its text browser "help.quickStart.text".
QWidget* showQuickStart(QMainWindow* window);
// Object name "help.shortcuts"; its text browser "help.shortcuts.text".
QWidget* showShortcuts(QMainWindow* window);

} // namespace lut::gui
