// SPDX-License-Identifier: Apache-2.0
#pragma once
// The scripted mode's (ScriptRunner.h) answer to the modal dialogs a command opens (an export
// dialog, a question, the match's amounts), as the user would with Return (accept: the default
// button) or Escape (reject); it remembers what they said, so a script never waits for a person.
// Held (`dialogs hold`), it leaves them open for the script's own commands (match-drag).
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace lut::gui {

class DialogResponder : public QObject {
public:
    explicit DialogResponder(QObject* parent);
    bool accept = false;
    bool hold = false; // leaves them open (a script that works the dialog itself)
    QStringList seen;

private:
    void poll();
    QTimer m_timer;
};

} // namespace lut::gui
