// SPDX-License-Identifier: Apache-2.0
#include "EditorOptions.h"

#include "Document.h"

#include "lut/Error.h"
#include "lut/Version.h"
#include "lut/formats/ImageFiles.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/Pipeline.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <algorithm>
#include <cstdio>

namespace lut::gui {

namespace {

// Bad usage: the message, said as one line and exit 2.
struct Usage {
    QString message;
};

using Option = QCommandLineOption;
QString S(const char* text) {
    return QString::fromUtf8(text);
}

QString presetHelp() {
    QString presets, oldPresets;
    for (const Preset p : allPresets()) {
        presets += (presets.isEmpty() ? "" : ", ") + QString::fromLatin1(toString(p));
        for (const auto& alias : presetAliases(p))
            oldPresets += (oldPresets.isEmpty() ? "" : ", ") + QString::fromStdString(alias);
    }
    return QStringLiteral("Preview preset: %1 (default smash; also %2). smash is the Smash target; "
                          "another preset is an engine's chain (target engine).")
        .arg(presets, oldPresets);
}

QString interpHelp() {
    QString interps;
    for (const auto m :
         {Interpolation::Nearest, Interpolation::Trilinear, Interpolation::Tetrahedral})
        interps += (interps.isEmpty() ? "" : ", ") + QString::fromLatin1(toString(m));
    return QStringLiteral("LUT interpolation: %1 (default trilinear).").arg(interps);
}

// The options, in --help's order (after -h and -V).
struct Options {
    Option version{{S("V"), S("version")}, S("Print the version and exit.")};
    Option shot{S("screenshot"),
                S("Render the window offscreen once the preview is ready, save it to FILE and "
                  "exit."),
                S("FILE")};
    Option save{S("save-preview"),
                S("Write the full-resolution preview image to FILE (as lutkit preview does) and "
                  "exit."),
                S("FILE")};
    Option preset{S("preset"), presetHelp(), S("NAME"), S("smash")};
    Option interp{{S("interp"), S("interpolation")}, interpHelp(), S("NAME"), S("trilinear")};
    Option noBloom{S("no-bloom"), S("Switch bloom off.")};
    Option noLut{S("no-lut"), S("Preview with a neutral LUT.")};
    Option noBrighten{S("no-brighten"), S("Switch the Smash brighten pass off.")};
    Option size{S("window-size"), S("Window size WxH (default 1480x920)."), S("WxH")};
    Option fromShot{S("from-screenshot"),
                    S("IMAGE is an in-game screenshot: undo the game's grading first (as lutkit "
                      "preview --from-screenshot).")};
    Option adjust{S("adjust"),
                  S("Apply an adjustment after opening, e.g. exposure=0.5, gain.r=1.1 "
                    "(repeatable; one undo step each)."),
                  S("KEY=VALUE")};
    Option view{S("view"), S("Preview view: split (default), after or before."), S("MODE"),
                S("split")};
    Option zoom{S("zoom"), S("fit (default) or a percentage such as 100."), S("ZOOM"), S("fit")};
    Option verbose{{S("v"), S("verbose")}, S("Log each preview update's time to stderr.")};
    Option target{S("target"),
                  S("What the LUT is for: smash (Smash Ultimate, color_grading_lut.nutexb; "
                    "default), engine (a 16^3 strip PNG) or cube (a grading app)."),
                  S("TARGET")};
    Option lutTarget{S("lut-target"),
                     S("What LUT is for when the file does not say (as lutkit's --lut-target): "
                       "raw (an edit, the look itself) or smash (the game's LUT, already made for "
                       "Smash Ultimate). Default: ask once per file (taken as raw without a "
                       "window)."),
                     S("NAME")};
    Option input{S("input"),
                 S("What IMAGE holds: screenshot or scene (default: 8/16-bit files are in-game "
                   "screenshots, float files linear scenes)."),
                 S("KIND")};
    Option script{S("script"),
                  S("Run the commands in FILE on the window (one per line; see the editor's "
                    "docs), print what they print, exit 0 when all worked."),
                  S("FILE")};

    void addTo(QCommandLineParser& parser) const {
        parser.addOptions({version, shot, save, preset, interp, noBloom, noLut, noBrighten, size,
                           fromShot, adjust, view, zoom, verbose, target, lutTarget, input,
                           script});
    }
};

// The value of `option` through `parse`; a refusal names the option.
template <class Parse>
auto valueOf(const QCommandLineParser& parser, const Option& option, Parse parse) {
    try {
        return parse(parser.value(option).toStdString());
    } catch (const std::exception& e) {
        throw Usage{QString::fromUtf8(
            ("--" + option.names().first().toStdString() + ": " + e.what()).c_str())};
    }
}

// --preset, --target, --interp, --lut-target, --input, the switches.
void readPreview(const QCommandLineParser& parser, const Options& o, EditorOptions& e) {
    // --preset smash is the Smash target; another preset is an engine's chain.
    const Preset preset = valueOf(parser, o.preset, parsePreset);
    e.target = parser.isSet(o.target)    ? valueOf(parser, o.target, parseExportTarget)
               : preset == Preset::Smash ? ExportTarget::Smash
                                         : ExportTarget::Engine;
    if (preset != Preset::Smash)
        e.preview.preset = preset;
    e.preview.interpolation = valueOf(parser, o.interp, parseInterpolation);
    if (parser.isSet(o.lutTarget))
        e.lutAnswer = valueOf(parser, o.lutTarget, parseLutPurpose);
    if (parser.isSet(o.input))
        e.input = valueOf(parser, o.input, parseSceneKind);
    else if (parser.isSet(o.fromShot))
        e.input = SceneKind::Screenshot;
    e.preview.bloom = !parser.isSet(o.noBloom);
    e.preview.lutEnabled = !parser.isSet(o.noLut);
    e.preview.brighten = !parser.isSet(o.noBrighten);
}

// --window-size, --view, --zoom.
void readWindow(const QCommandLineParser& parser, const Options& o, EditorOptions& e) {
    if (parser.isSet(o.size)) {
        const QStringList wh = parser.value(o.size).split('x');
        bool okW = false, okH = false;
        if (wh.size() == 2)
            e.windowSize = QSize(wh[0].toInt(&okW), wh[1].toInt(&okH));
        const QSize s = e.windowSize;
        if (!okW || !okH || s.width() < 100 || s.height() < 100 || s.width() > 16384 ||
            s.height() > 16384)
            throw Usage{QStringLiteral("--window-size %1: expected WxH, e.g. 1480x920 (100 to "
                                       "16384 each)")
                            .arg(parser.value(o.size))};
    }
    e.view = parser.value(o.view);
    if (e.view != QLatin1String("split") && e.view != QLatin1String("after") &&
        e.view != QLatin1String("before"))
        throw Usage{QStringLiteral("--view %1: expected split, after or before").arg(e.view)};
    if (parser.value(o.zoom) != QLatin1String("fit")) {
        bool isNumber = false;
        e.zoomPercent = parser.value(o.zoom).toDouble(&isNumber);
        if (!isNumber || !(e.zoomPercent > 0) || e.zoomPercent > 6400)
            throw Usage{QStringLiteral("--zoom %1: expected fit or a percentage from 1 to 6400")
                            .arg(parser.value(o.zoom))};
    }
}

// --adjust KEY=VALUE, repeated.
void readAdjusts(const QCommandLineParser& parser, const Options& o, EditorOptions& e) {
    for (const QString& a : parser.values(o.adjust)) {
        const QString key = a.section('=', 0, 0).trimmed();
        bool isNumber = false;
        const double value = a.section('=', 1).toDouble(&isNumber);
        const AdjustParamInfo* info = nullptr;
        for (const auto& p : adjustParams())
            if (QString::fromStdString(p.key) == key)
                info = &p;
        if (!info || !isNumber || !a.contains('=')) {
            QString keys;
            for (const auto& p : adjustParams())
                keys += ' ' + QString::fromStdString(p.key);
            throw Usage{
                QStringLiteral("--adjust %1: expected KEY=NUMBER with KEY one of%2").arg(a, keys)};
        }
        e.adjusts.push_back({info, std::clamp(value, info->min, info->max)});
    }
}

// Positionals: IMAGE [LUT]. A file manager's "Open with" passes a single .cube or .nutexb, which
// must open as the LUT, and a LUT file named first is still taken as the LUT.
void readFiles(const QCommandLineParser& parser, EditorOptions& e) {
    const QStringList args = parser.positionalArguments();
    if (args.size() > 2)
        throw Usage{
            QStringLiteral("expected at most IMAGE and LUT, got %1 files").arg(args.size())};
    e.imagePath = args.value(0);
    e.lutPath = args.value(1);
    const auto lutOnly = [](const QString& p) { // a LUT extension that is not a picture's
        return looksLikeLutFile(p) && !formats::isImageExtension(p.toStdString());
    };
    if (args.size() == 1 && looksLikeLutFile(args[0]))
        std::swap(e.imagePath, e.lutPath);
    else if (args.size() == 2 && lutOnly(args[0]) && !lutOnly(args[1]))
        std::swap(e.imagePath, e.lutPath);
}

int usage(const QString& message) {
    std::fprintf(stderr, "lutkit-editor: %s\nRun 'lutkit-editor --help' for usage.\n",
                 qPrintable(message));
    return 2;
}

} // namespace

std::variant<EditorOptions, int> readEditorOptions(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        S("Preview a colour grading LUT on a screenshot as the game shows it, adjust it and "
          "export it."));
    const QCommandLineOption helpOpt = parser.addHelpOption();
    const Options o;
    parser.addPositionalArgument(S("image"), S("Screenshot or render to preview."), S("[IMAGE"));
    parser.addPositionalArgument(S("lut"), S("LUT file (any format lutkit reads)."), S("[LUT]]"));
    o.addTo(parser);
    if (!parser.parse(arguments))
        return usage(parser.errorText());
    // --help-all is Qt's "help with Qt's own options"; the editor takes none (its command line is
    // read before Qt sees it), so it is --help.
    if (parser.isSet(helpOpt) || parser.isSet(S("help-all"))) {
        // Without an application object Qt cannot name the program.
        std::printf("%s", qPrintable(parser.helpText().replace(S("<executable_name>"),
                                                               S("lutkit-editor"))));
        return 0;
    }
    if (parser.isSet(o.version)) {
        std::printf("lutkit-editor %s\n", LUTKIT_VERSION);
        return 0;
    }
    // Every option value is checked here, before any window system is touched.
    EditorOptions e;
    try {
        readPreview(parser, o, e);
        readWindow(parser, o, e);
        readAdjusts(parser, o, e);
        readFiles(parser, e);
    } catch (const Usage& u) {
        return usage(u.message);
    }
    e.verbose = parser.isSet(o.verbose);
    const auto mode = [&parser](const Option& option) {
        return parser.isSet(option) ? std::optional<QString>(parser.value(option)) : std::nullopt;
    };
    e.screenshotPath = mode(o.shot);
    e.savePreviewPath = mode(o.save);
    e.scriptPath = mode(o.script);
    return e;
}

} // namespace lut::gui
