// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit-editor's start (gui/main.cpp): the application's look and state, and what Qt says when
// there is no display to open.
class QApplication;

namespace lut::gui {

// Until the QApplication exists: the platform plugin's messages are held back, and its fatal one
// ("no Qt platform plugin could be initialized": no DISPLAY or WAYLAND_DISPLAY, or a server that
// does not answer; Qt would abort with exit 134 and a paragraph about reinstalling) becomes one
// line saying how to run the editor, and exit 1.
void holdPlatformMessages();
// Once the QApplication exists: Qt's messages as before holdPlatformMessages().
void releasePlatformMessages();
// The vector unit's state for the threads started from here (CpuState.h), the desktop entry and
// icon installed from gui/desktop, the dark Fusion theme, lutkit's formats registered.
void startEditorApplication(QApplication& app);

} // namespace lut::gui
