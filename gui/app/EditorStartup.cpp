// SPDX-License-Identifier: Apache-2.0
#include "EditorStartup.h"

#include "CpuState.h"

#include "lut/formats/Registry.h"

#include <QApplication>
#include <QIcon>
#include <QPalette>
#include <QStyleFactory>

#include <cstdio>
#include <cstdlib>

namespace lut::gui {

namespace {

void applyDarkTheme(QApplication& app) {
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QPalette p;
    const QColor window(0x35, 0x36, 0x3a), base(0x25, 0x26, 0x29), text(0xe6, 0xe6, 0xe6);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, window);
    p.setColor(QPalette::ToolTipBase, base);
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, window);
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, Qt::red);
    p.setColor(QPalette::Highlight, QColor(0x3d, 0x8e, 0xe6));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::PlaceholderText, QColor(0x8a, 0x8a, 0x8a));
    p.setColor(QPalette::Disabled, QPalette::Text, QColor(0x80, 0x80, 0x80));
    p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(0x80, 0x80, 0x80));
    p.setColor(QPalette::Disabled, QPalette::WindowText, QColor(0x80, 0x80, 0x80));
    app.setPalette(p);
}

QtMessageHandler g_previousHandler = nullptr;

void installNoDisplayHandler() {
    g_previousHandler = qInstallMessageHandler([](QtMsgType type, const QMessageLogContext& context,
                                                  const QString& message) {
        const bool platform =
            QByteArray(context.category ? context.category : "").startsWith("qt.qpa") ||
            message.contains(QStringLiteral("platform plugin"));
        if (type == QtFatalMsg && platform) {
            const QByteArray display = qgetenv("DISPLAY"), wayland = qgetenv("WAYLAND_DISPLAY");
            const QByteArray where =
                display.isEmpty() && wayland.isEmpty()
                    ? QByteArray("no display found (neither DISPLAY nor WAYLAND_DISPLAY is set)")
                    : "cannot open the display " +
                          (display.isEmpty() ? "WAYLAND_DISPLAY=" + wayland : "DISPLAY=" + display);
            std::fprintf(stderr,
                         "lutkit-editor: error: %s: run it in a desktop session, or with "
                         "QT_QPA_PLATFORM=offscreen for scripts (--save and --screenshot "
                         "need no display)\n",
                         where.constData());
            std::fflush(stderr);
            std::_Exit(1);
        }
        if (platform && type != QtFatalMsg)
            return; // said above if it comes to the fatal one
        if (g_previousHandler)
            g_previousHandler(type, context, message);
        else
            std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
    });
}

} // namespace

void holdPlatformMessages() {
    installNoDisplayHandler();
}

void releasePlatformMessages() {
    qInstallMessageHandler(g_previousHandler);
}

void startEditorApplication(QApplication& app) {
    clearUpperVectorState(); // threads started from here inherit it (CpuState.h)
    // The desktop entry and icon installed from gui/desktop (window grouping, taskbar icon).
    QGuiApplication::setDesktopFileName(QStringLiteral("lutkit-editor"));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("lutkit-editor")));
    applyDarkTheme(app);
    formats::registerBuiltinFormats();
}

} // namespace lut::gui
