// SPDX-License-Identifier: Apache-2.0
#include "ScriptInput.h"

#include "MainWindow.h"
#include "ScriptContext.h"

#include <QApplication>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QMimeData>
#include <QMouseEvent>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QThread>
#include <QUrl>

#include <algorithm>

namespace lut::gui {

void sendKeys(const QKeySequence& seq) {
    for (int i = 0; i < seq.count(); ++i) {
        const QKeyCombination k = seq[i];
        QWidget* target = QApplication::focusWidget();
        need(target != nullptr, QStringLiteral("no widget has the keyboard focus"));
        QString text;
        if (!(k.keyboardModifiers() & (Qt::ControlModifier | Qt::AltModifier)) &&
            k.key() < 0x01000000)
            text = QKeySequence(k.key()).toString().toLower();
        QKeyEvent press(QEvent::KeyPress, k.key(), k.keyboardModifiers(), text);
        QApplication::sendEvent(target, &press);
        QKeyEvent release(QEvent::KeyRelease, k.key(), k.keyboardModifiers(), text);
        if (QWidget* now = QApplication::focusWidget())
            QApplication::sendEvent(now, &release);
        QApplication::processEvents();
    }
}

void dragSlider(QSlider* s, int position, int ms) {
    QStyleOptionSlider opt;
    opt.initFrom(s);
    opt.orientation = s->orientation();
    opt.minimum = s->minimum();
    opt.maximum = s->maximum();
    opt.sliderPosition = s->value();
    opt.sliderValue = s->value();
    const QRect handle =
        s->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, s);
    const int span = s->width() - handle.width();
    const auto xOf = [&](int v) {
        return QStyle::sliderPositionFromValue(s->minimum(), s->maximum(), v, span) +
               handle.width() / 2;
    };
    QPointF at(xOf(s->value()), s->height() / 2.0);
    auto send = [&](QEvent::Type type, QPointF p, Qt::MouseButtons buttons) {
        QMouseEvent e(type, p, s->mapToGlobal(p), Qt::LeftButton, buttons, Qt::NoModifier);
        QApplication::sendEvent(s, &e);
        QApplication::processEvents();
    };
    send(QEvent::MouseButtonPress, at, Qt::LeftButton);
    const double target = xOf(position);
    // over `ms`: a move every 16 ms (a mouse's rate), the window's events run between them
    const int moves = ms > 0 ? std::max(1, ms / 16) : 5;
    QElapsedTimer clock;
    clock.start();
    for (int i = 1; i <= moves; ++i) {
        send(QEvent::MouseMove, QPointF(at.x() + (target - at.x()) * i / moves, at.y()),
             Qt::LeftButton);
        while (ms > 0 && clock.elapsed() < static_cast<qint64>(ms) * i / moves) {
            QApplication::processEvents(QEventLoop::AllEvents, 5);
            QThread::msleep(1);
        }
    }
    send(QEvent::MouseButtonRelease, QPointF(target, at.y()), Qt::NoButton);
}

bool dropFiles(MainWindow& w, const QStringList& files) {
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString& a : files)
        urls << QUrl::fromLocalFile(QFileInfo(a).absoluteFilePath());
    mime.setUrls(urls);
    const QPoint at = w.rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&w, &enter);
    need(enter.isAccepted(), QStringLiteral("the window refused the drag"));
    QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&w, &drop);
    QApplication::processEvents(); // a LUT opens once the drop has returned
    w.waitForLoads();
    return drop.isAccepted();
}

} // namespace lut::gui
