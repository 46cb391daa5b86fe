// SPDX-License-Identifier: Apache-2.0
// lutkit-editor: the Qt 6 LUT editor. Its command line: gui/app/EditorOptions.h.
//   lutkit-editor [IMAGE [LUT]]
//   lutkit-editor --screenshot OUT.png [IMAGE [LUT]]   render the window offscreen, save, exit
//   lutkit-editor --save-preview OUT.png IMAGE [LUT]   write the preview image like lutkit preview
//   lutkit-editor --script FILE [IMAGE [LUT]]          drive the window (ScriptRunner.h), exit
#include "Document.h"
#include "EditorOptions.h"
#include "EditorStartup.h"
#include "MainWindow.h"
#include "PreviewView.h"
#include "ScriptRunner.h"

#include "lut/Version.h"

#include <QApplication>
#include <QSaveFile>
#include <QTextStream>

#include <cstdio>

namespace {

using lut::gui::EditorOptions;
using lut::gui::MainWindow;

// The window as the options say, its files opened and adjusted; false when a file failed.
bool setUpWindow(MainWindow& window, const EditorOptions& o) {
    const bool user = !o.headless() && !o.scripted();
    window.setVerbose(o.verbose);
    window.setInteractiveErrors(user);
    if (user)
        window.restoreWindowState();
    if (o.lutAnswer)
        window.setLutPurposeAnswer(*o.lutAnswer);
    window.document()->setTarget(o.target);
    window.setPreviewOptions(o.preview);
    if (o.windowSize.isValid())
        window.resize(o.windowSize);
    bool ok = true;
    if (!o.imagePath.isEmpty())
        ok = window.openImageFile(o.imagePath) && ok;
    if (o.input) { // the picture's kind as the user said, not as detected
        lut::gui::PreviewOptions p = window.previewOptions();
        p.input = *o.input;
        window.setPreviewOptions(p);
    }
    if (!o.lutPath.isEmpty())
        ok = window.openLutFile(o.lutPath) && ok;
    for (const EditorOptions::Adjust& a : o.adjusts) {
        window.document()->editParam(a.info->id, a.value);
        window.document()->endGesture();
    }
    return ok;
}

void showWindow(MainWindow& window, const EditorOptions& o) {
    using Mode = lut::gui::PreviewView::Mode;
    if (o.view == QLatin1String("after"))
        window.previewView()->setMode(Mode::After);
    else if (o.view == QLatin1String("before"))
        window.previewView()->setMode(Mode::Before);
    window.show();
    QApplication::processEvents(); // lay the window out before zooming about the view centre
    if (o.zoomPercent > 0)
        window.previewView()->zoomTo(o.zoomPercent / 100.0);
}

int runScripted(MainWindow& window, const QString& script) {
    QTextStream out(stdout);
    window.waitForPreview();
    const int rc = lut::gui::runScript(window, script, out);
    window.close();
    return rc;
}

// --save-preview, then --screenshot.
int runHeadless(MainWindow& window, const EditorOptions& o) {
    if (o.savePreviewPath && !window.savePreviewImage(*o.savePreviewPath))
        return 1;
    if (!o.screenshotPath)
        return 0;
    window.waitForPreview();
    QApplication::processEvents();
    const QImage shot = window.grab().toImage();
    QSaveFile out(*o.screenshotPath); // atomic: temporary file renamed on commit
    if (!out.open(QIODevice::WriteOnly) || !shot.save(&out, "PNG") || !out.commit()) {
        std::fprintf(stderr, "lutkit-editor: cannot write %s\n", qPrintable(*o.screenshotPath));
        return 1;
    }
    if (o.verbose)
        std::fprintf(stderr, "screenshot %dx%d written to %s\n", shot.width(), shot.height(),
                     qPrintable(*o.screenshotPath));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    // The command line is read before any QApplication exists: --help, --version and usage
    // errors need no display.
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    QCoreApplication::setOrganizationName(QStringLiteral("lutkit"));
    QCoreApplication::setApplicationName(QStringLiteral("lutkit-editor"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LUTKIT_VERSION));
    const auto read = lut::gui::readEditorOptions(arguments);
    if (const int* exitCode = std::get_if<int>(&read))
        return *exitCode;
    const EditorOptions& o = std::get<EditorOptions>(read);

    // Headless modes need a platform before QApplication exists.
    if (o.headless() && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    lut::gui::holdPlatformMessages(); // no display: one line and exit 1 (EditorStartup.h)
    QApplication app(argc, argv);
    lut::gui::releasePlatformMessages();
    lut::gui::startEditorApplication(app);

    MainWindow window;
    if (!setUpWindow(window, o) && (o.headless() || o.scripted()))
        return 1;
    showWindow(window, o);
    if (o.scripted())
        return runScripted(window, *o.scriptPath);
    if (!o.headless())
        return app.exec();
    return runHeadless(window, o);
}
