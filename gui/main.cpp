// SPDX-License-Identifier: Apache-2.0
// lutkit-editor: the Qt 6 LUT editor.
//   lutkit-editor [IMAGE [LUT]]
//   lutkit-editor --screenshot OUT.png [IMAGE [LUT]]   render the window offscreen, save, exit
//   lutkit-editor --save-preview OUT.png IMAGE [LUT]   write the preview image like lutkit preview
//   lutkit-editor --script FILE [IMAGE [LUT]]          drive the window (ScriptRunner.h), exit
#include "CpuState.h"
#include "Document.h"
#include "MainWindow.h"
#include "PreviewController.h"
#include "PreviewRenderer.h"
#include "PreviewView.h"
#include "ScriptRunner.h"

#include "lut/Error.h"
#include "lut/LutPurpose.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/Pipeline.h"

#include "lut/Version.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QPalette>
#include <QSaveFile>
#include <QStyleFactory>
#include <QTextStream>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

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

// Until the QApplication exists: the platform plugin's messages are held back, and its fatal
// one ("no Qt platform plugin could be initialized") becomes one line and exit code 1.
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

int main(int argc, char** argv) {
    // The command line is read before any QApplication exists: --help, --version and usage
    // errors need no display.
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    QCoreApplication::setOrganizationName(QStringLiteral("lutkit"));
    QCoreApplication::setApplicationName(QStringLiteral("lutkit-editor"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LUTKIT_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Preview a colour grading LUT on a screenshot as the game shows it, adjust it "
        "and export it."));
    // The options speak lutkit's vocabulary (-V/--version, -v/--verbose, --interp); any bad usage
    // exits 2, as lutkit does.
    const QCommandLineOption helpOpt = parser.addHelpOption();
    QCommandLineOption versionOpt({QStringLiteral("V"), QStringLiteral("version")},
                                  QStringLiteral("Print the version and exit."));
    parser.addPositionalArgument(QStringLiteral("image"),
                                 QStringLiteral("Screenshot or render to preview."),
                                 QStringLiteral("[IMAGE"));
    parser.addPositionalArgument(QStringLiteral("lut"),
                                 QStringLiteral("LUT file (any format lutkit reads)."),
                                 QStringLiteral("[LUT]]"));
    QCommandLineOption shotOpt(
        QStringLiteral("screenshot"),
        QStringLiteral(
            "Render the window offscreen once the preview is ready, save it to FILE and exit."),
        QStringLiteral("FILE"));
    QCommandLineOption saveOpt(
        QStringLiteral("save-preview"),
        QStringLiteral(
            "Write the full-resolution preview image to FILE (as lutkit preview does) and exit."),
        QStringLiteral("FILE"));
    QString presets, oldPresets;
    for (const lut::Preset p : lut::allPresets()) {
        presets += (presets.isEmpty() ? "" : ", ") + QString::fromLatin1(lut::toString(p));
        for (const auto& alias : lut::presetAliases(p))
            oldPresets += (oldPresets.isEmpty() ? "" : ", ") + QString::fromStdString(alias);
    }
    QCommandLineOption presetOpt(
        QStringLiteral("preset"),
        QStringLiteral("Preview preset: %1 (default smash; also %2). smash is the Smash target; "
                       "another preset is an engine's chain (target engine).")
            .arg(presets, oldPresets),
        QStringLiteral("NAME"), QStringLiteral("smash"));
    QString interps;
    for (const auto m : {lut::Interpolation::Nearest, lut::Interpolation::Trilinear,
                         lut::Interpolation::Tetrahedral})
        interps += (interps.isEmpty() ? "" : ", ") + QString::fromLatin1(lut::toString(m));
    QCommandLineOption interpOpt(
        {QStringLiteral("interp"), QStringLiteral("interpolation")},
        QStringLiteral("LUT interpolation: %1 (default trilinear).").arg(interps),
        QStringLiteral("NAME"), QStringLiteral("trilinear"));
    QCommandLineOption noBloomOpt(QStringLiteral("no-bloom"), QStringLiteral("Switch bloom off."));
    QCommandLineOption noLutOpt(QStringLiteral("no-lut"),
                                QStringLiteral("Preview with a neutral LUT."));
    QCommandLineOption noBrightenOpt(QStringLiteral("no-brighten"),
                                     QStringLiteral("Switch the Smash brighten pass off."));
    QCommandLineOption sizeOpt(QStringLiteral("window-size"),
                               QStringLiteral("Window size WxH (default 1480x920)."),
                               QStringLiteral("WxH"));
    QCommandLineOption fromShotOpt(
        QStringLiteral("from-screenshot"),
        QStringLiteral("IMAGE is an in-game screenshot: undo the game's grading first (as lutkit "
                       "preview --from-screenshot)."));
    QCommandLineOption adjustOpt(
        QStringLiteral("adjust"),
        QStringLiteral("Apply an adjustment after opening, e.g. exposure=0.5, gain.r=1.1 "
                       "(repeatable; one undo step each)."),
        QStringLiteral("KEY=VALUE"));
    QCommandLineOption viewOpt(QStringLiteral("view"),
                               QStringLiteral("Preview view: split (default), after or before."),
                               QStringLiteral("MODE"), QStringLiteral("split"));
    QCommandLineOption zoomOpt(QStringLiteral("zoom"),
                               QStringLiteral("fit (default) or a percentage such as 100."),
                               QStringLiteral("ZOOM"), QStringLiteral("fit"));
    QCommandLineOption verboseOpt({QStringLiteral("v"), QStringLiteral("verbose")},
                                  QStringLiteral("Log each preview update's time to stderr."));
    QCommandLineOption targetOpt(
        QStringLiteral("target"),
        QStringLiteral("What the LUT is for: smash (Smash Ultimate, color_grading_lut.nutexb; "
                       "default), engine (a 16^3 strip PNG) or cube (a grading app)."),
        QStringLiteral("TARGET"));
    QCommandLineOption lutTargetOpt(
        QStringLiteral("lut-target"),
        QStringLiteral("What LUT is for when the file does not say (as lutkit's --lut-target): "
                       "raw (an edit, the look itself) or smash (the game's LUT, already made for "
                       "Smash Ultimate). Default: ask once per file (taken as raw without a "
                       "window)."),
        QStringLiteral("NAME"));
    QCommandLineOption inputOpt(
        QStringLiteral("input"),
        QStringLiteral("What IMAGE holds: screenshot or scene (default: 8/16-bit files are "
                       "in-game screenshots, float files linear scenes)."),
        QStringLiteral("KIND"));
    QCommandLineOption scriptOpt(
        QStringLiteral("script"),
        QStringLiteral("Run the commands in FILE on the window (one per line; see the editor's "
                       "docs), print what they print, exit 0 when all worked."),
        QStringLiteral("FILE"));
    parser.addOptions({versionOpt, shotOpt, saveOpt, presetOpt, interpOpt, noBloomOpt, noLutOpt,
                       noBrightenOpt, sizeOpt, fromShotOpt, adjustOpt, viewOpt, zoomOpt, verboseOpt,
                       targetOpt, lutTargetOpt, inputOpt, scriptOpt});
    if (!parser.parse(arguments)) {
        std::fprintf(stderr, "lutkit-editor: %s\nRun 'lutkit-editor --help' for usage.\n",
                     qPrintable(parser.errorText()));
        return 2;
    }
    // --help-all is Qt's "help with Qt's own options"; the editor takes none (its command line is
    // read before Qt sees it), so it is --help.
    if (parser.isSet(helpOpt) || parser.isSet(QStringLiteral("help-all"))) {
        // Without an application object Qt cannot name the program.
        std::printf("%s", qPrintable(parser.helpText().replace(QStringLiteral("<executable_name>"),
                                                               QStringLiteral("lutkit-editor"))));
        return 0;
    }
    if (parser.isSet(versionOpt)) {
        std::printf("lutkit-editor %s\n", LUTKIT_VERSION);
        return 0;
    }

    // Every option value is checked here, before any window system is touched: a bad value is
    // bad usage (exit 2 with one line), with or without a display.
    const auto usage = [](const QString& message) {
        std::fprintf(stderr, "lutkit-editor: %s\nRun 'lutkit-editor --help' for usage.\n",
                     qPrintable(message));
        return 2;
    };
    lut::gui::PreviewOptions options;
    lut::gui::ExportTarget target = lut::gui::ExportTarget::Smash; // the document's
    std::optional<lut::SceneKind> input;
    std::optional<lut::LutPurpose> lutAnswer; // --lut-target
    // The value of `option` through `parse`; a refusal names the option.
    const auto value = [&parser](const QCommandLineOption& option, auto parse) {
        try {
            return parse(parser.value(option).toStdString());
        } catch (const std::exception& e) {
            throw lut::Error("--" + option.names().first().toStdString() + ": " + e.what());
        }
    };
    try {
        // --preset smash is the Smash target; another preset is an engine's chain.
        const lut::Preset preset = value(presetOpt, lut::parsePreset);
        target = parser.isSet(targetOpt)        ? value(targetOpt, lut::gui::parseExportTarget)
                 : preset == lut::Preset::Smash ? lut::gui::ExportTarget::Smash
                                                : lut::gui::ExportTarget::Engine;
        if (preset != lut::Preset::Smash)
            options.preset = preset;
        options.interpolation = value(interpOpt, lut::parseInterpolation);
        if (parser.isSet(lutTargetOpt))
            lutAnswer = value(lutTargetOpt, lut::parseLutPurpose);
        if (parser.isSet(inputOpt))
            input = value(inputOpt, lut::parseSceneKind);
        else if (parser.isSet(fromShotOpt))
            input = lut::SceneKind::Screenshot;
    } catch (const std::exception& e) {
        return usage(QString::fromUtf8(e.what()));
    }
    options.bloom = !parser.isSet(noBloomOpt);
    options.lutEnabled = !parser.isSet(noLutOpt);
    options.brighten = !parser.isSet(noBrightenOpt);
    QSize windowSize;
    if (parser.isSet(sizeOpt)) {
        const QStringList wh = parser.value(sizeOpt).split('x');
        bool okW = false, okH = false;
        if (wh.size() == 2)
            windowSize = QSize(wh[0].toInt(&okW), wh[1].toInt(&okH));
        if (!okW || !okH || windowSize.width() < 100 || windowSize.height() < 100 ||
            windowSize.width() > 16384 || windowSize.height() > 16384)
            return usage(QStringLiteral("--window-size %1: expected WxH, e.g. 1480x920 (100 to "
                                        "16384 each)")
                             .arg(parser.value(sizeOpt)));
    }
    const QString view = parser.value(viewOpt);
    if (view != QLatin1String("split") && view != QLatin1String("after") &&
        view != QLatin1String("before"))
        return usage(QStringLiteral("--view %1: expected split, after or before").arg(view));
    double zoomPercent = 0; // 0 = fit
    if (parser.value(zoomOpt) != QLatin1String("fit")) {
        bool isNumber = false;
        zoomPercent = parser.value(zoomOpt).toDouble(&isNumber);
        if (!isNumber || !(zoomPercent > 0) || zoomPercent > 6400)
            return usage(QStringLiteral("--zoom %1: expected fit or a percentage from 1 to 6400")
                             .arg(parser.value(zoomOpt)));
    }
    struct Adjust {
        const lut::gui::AdjustParamInfo* info;
        double value;
    };
    std::vector<Adjust> adjusts;
    for (const QString& a : parser.values(adjustOpt)) {
        const QString key = a.section('=', 0, 0).trimmed();
        bool isNumber = false;
        const double value = a.section('=', 1).toDouble(&isNumber);
        const lut::gui::AdjustParamInfo* info = nullptr;
        for (const auto& p : lut::gui::adjustParams())
            if (QString::fromStdString(p.key) == key)
                info = &p;
        if (!info || !isNumber || !a.contains('=')) {
            QString keys;
            for (const auto& p : lut::gui::adjustParams())
                keys += ' ' + QString::fromStdString(p.key);
            return usage(
                QStringLiteral("--adjust %1: expected KEY=NUMBER with KEY one of%2").arg(a, keys));
        }
        adjusts.push_back({info, std::clamp(value, info->min, info->max)});
    }
    // Positionals: IMAGE [LUT]. A file manager's "Open with" passes a single .cube or .nutexb,
    // which must open as the LUT, and a LUT file named first is still taken as the LUT.
    const QStringList args = parser.positionalArguments();
    if (args.size() > 2)
        return usage(
            QStringLiteral("expected at most IMAGE and LUT, got %1 files").arg(args.size()));

    // Headless modes need a platform before QApplication exists.
    const bool headless = parser.isSet(shotOpt) || parser.isSet(saveOpt);
    if (headless && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // No display to open (no DISPLAY or WAYLAND_DISPLAY, or a server that does not answer): Qt
    // reports it as a fatal message and aborts (exit 134, a paragraph about reinstalling). One
    // line instead, saying how to run the editor, and exit 1.
    installNoDisplayHandler();
    QApplication app(argc, argv);
    qInstallMessageHandler(g_previousHandler);
    lut::gui::clearUpperVectorState(); // threads started from here inherit it (CpuState.h)
    // The desktop entry and icon installed from gui/desktop (window grouping, taskbar icon).
    QGuiApplication::setDesktopFileName(QStringLiteral("lutkit-editor"));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("lutkit-editor")));
    applyDarkTheme(app);
    lut::formats::registerBuiltinFormats();

    const bool scripted = parser.isSet(scriptOpt);
    lut::gui::MainWindow window;
    window.setVerbose(parser.isSet(verboseOpt));
    window.setInteractiveErrors(!headless && !scripted);
    if (!headless && !scripted)
        window.restoreWindowState();
    if (lutAnswer)
        window.setLutPurposeAnswer(*lutAnswer);
    window.document()->setTarget(target);
    window.setPreviewOptions(options);
    if (windowSize.isValid())
        window.resize(windowSize);

    QString imagePath = args.value(0), lutPath = args.value(1);
    const auto lutOnly = [](const QString& p) { // a LUT extension that is not a picture's
        return lut::gui::looksLikeLutFile(p) && !lut::formats::isImageExtension(p.toStdString());
    };
    if (args.size() == 1 && lut::gui::looksLikeLutFile(args[0]))
        std::swap(imagePath, lutPath);
    else if (args.size() == 2 && lutOnly(args[0]) && !lutOnly(args[1]))
        std::swap(imagePath, lutPath);
    bool ok = true;
    if (!imagePath.isEmpty())
        ok = window.openImageFile(imagePath) && ok;
    if (input) { // the picture's kind as the user said, not as detected
        lut::gui::PreviewOptions o = window.previewOptions();
        o.input = *input;
        window.setPreviewOptions(o);
    }
    if (!lutPath.isEmpty())
        ok = window.openLutFile(lutPath) && ok;
    for (const Adjust& a : adjusts) {
        window.document()->editParam(a.info->id, a.value);
        window.document()->endGesture();
    }
    if ((headless || scripted) && !ok)
        return 1;

    if (view == QLatin1String("after"))
        window.previewView()->setMode(lut::gui::PreviewView::Mode::After);
    else if (view == QLatin1String("before"))
        window.previewView()->setMode(lut::gui::PreviewView::Mode::Before);
    window.show();
    QApplication::processEvents(); // lay the window out before zooming about the view centre
    if (zoomPercent > 0)
        window.previewView()->zoomTo(zoomPercent / 100.0);
    if (scripted) {
        QTextStream out(stdout);
        window.waitForPreview();
        const int rc = lut::gui::runScript(window, parser.value(scriptOpt), out);
        window.close();
        return rc;
    }
    if (!headless)
        return app.exec();

    if (parser.isSet(saveOpt) && !window.savePreviewImage(parser.value(saveOpt)))
        return 1;
    if (parser.isSet(shotOpt)) {
        window.waitForPreview();
        QApplication::processEvents();
        const QImage shot = window.grab().toImage();
        QSaveFile out(parser.value(shotOpt)); // atomic: temporary file renamed on commit
        if (!out.open(QIODevice::WriteOnly) || !shot.save(&out, "PNG") || !out.commit()) {
            std::fprintf(stderr, "lutkit-editor: cannot write %s\n",
                         qPrintable(parser.value(shotOpt)));
            return 1;
        }
        if (parser.isSet(verboseOpt))
            std::fprintf(stderr, "screenshot %dx%d written to %s\n", shot.width(), shot.height(),
                         qPrintable(parser.value(shotOpt)));
    }
    return 0;
}
