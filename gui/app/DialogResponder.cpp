// SPDX-License-Identifier: Apache-2.0
#include "DialogResponder.h"

#include <QApplication>
#include <QDialog>
#include <QKeyEvent>
#include <QMessageBox>
#include <QPointer>

namespace lut::gui {

DialogResponder::DialogResponder(QObject* parent) : QObject(parent) {
    m_timer.setInterval(25);
    connect(&m_timer, &QTimer::timeout, this, &DialogResponder::poll);
    m_timer.start();
}

void DialogResponder::poll() {
    if (hold)
        return;
    QWidget* modal = QApplication::activeModalWidget();
    if (!modal)
        for (QWidget* top : QApplication::topLevelWidgets())
            if (auto* d = qobject_cast<QDialog*>(top); d && d->isVisible() && d->isModal())
                modal = d;
    // Guarded: the key may close the dialog, and a dialog that deletes itself on close is gone
    // after processEvents (the match dialog's OK crashed the scripted editor).
    QPointer<QDialog> dialog = qobject_cast<QDialog*>(modal);
    if (!dialog || !dialog->isVisible())
        return;
    QString text = dialog->windowTitle();
    if (auto* box = qobject_cast<QMessageBox*>(dialog))
        text += QStringLiteral(": ") + box->text();
    seen << text;
    QKeyEvent key(QEvent::KeyPress, accept ? Qt::Key_Return : Qt::Key_Escape, Qt::NoModifier);
    QApplication::sendEvent(dialog->focusWidget() ? dialog->focusWidget() : dialog, &key);
    QApplication::processEvents();
    if (dialog && dialog->isVisible()) // the key did not close it (a button without focus policy)
        accept ? dialog->accept() : dialog->reject();
}

} // namespace lut::gui
