// SPDX-License-Identifier: Apache-2.0
// The editor from the outside, as its users and the CLI see it:
//   - issue 15, problem 2 and "one truth": for every target the window's preview (saved with the
//     scripted mode) equals the CLI's rendering of the file the default export wrote, bit for
//     bit, on the sample scene (screenshot PNG and linear EXR);
//   - --help and --version work without a display;
//   - under a real X server (xvfb-run, when installed) the scripted window takes typed values and
//     shortcuts, a slider drag is one undo step, dropped files open, the default export and a
//     screenshot are written.
#include "EditorTestSupport.h"
#include "GuiTestSupport.h"
#include "TestPaths.h"

#include "lut/Image.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextStream>
#include <QtTest>

using namespace lut;
using lut::gui::test::Run;
using lut::gui::test::run;
using lut::gui::test::samplePath;
using lut::gui::test::writeScript;

namespace {

// The paints of each "probe longest-gap G ms own O ms over P paints" line a script printed.
QList<int> probePaints(const QString& out) {
    QList<int> paints;
    auto it = QRegularExpression(QStringLiteral("probe longest-gap [0-9.]+ ms own [0-9.]+ ms over "
                                                "([0-9]+) paints"))
                  .globalMatch(out);
    while (it.hasNext())
        paints << it.next().captured(1).toInt();
    return paints;
}

QString exportedPath(const QString& out) {
    const auto m =
        QRegularExpression(QStringLiteral("^exported (.*)$"), QRegularExpression::MultilineOption)
            .match(out);
    return m.hasMatch() ? m.captured(1).trimmed() : QString();
}

} // namespace

class EditorCliTest : public QObject {
    Q_OBJECT
private slots:
    void previewIsTheCliRenderingOfTheExportedFileForEveryTarget_data() {
        QTest::addColumn<QString>("image");
        QTest::addColumn<QStringList>("setup");   // script lines choosing target and chain
        QTest::addColumn<QString>("extension");   // of the default export
        QTest::addColumn<QStringList>("cli");     // how the CLI renders it (--lut LUT IN -o OUT)
        QTest::addColumn<bool>("viaDisplayOnly"); // the scene is first display-encoded (2 steps)
        // One recipe (lut/pipeline/PreviewPlan.h): lutkit preview with the preset the target
        // means renders every case, screenshots and scenes alike, in one command.
        const QStringList preview = {QStringLiteral("preview"), QStringLiteral("-q")};
        const QStringList none = preview + QStringList{"--preset", "none"};
        const QStringList apply = {QStringLiteral("apply"), QStringLiteral("-q"),
                                   QStringLiteral("--interp"), QStringLiteral("trilinear")};
        QTest::newRow("smash, in-game screenshot")
            << "sample_scene.png" << QStringList{"target smash"} << ".nutexb" << preview << false;
        QTest::newRow("smash, in-game screenshot, said")
            << "sample_scene.png" << QStringList{"target smash"} << ".nutexb"
            << preview + QStringList{"--from-screenshot", "--no-bloom"} << false;
        QTest::newRow("engine strip, screenshot")
            << "sample_scene.png" << QStringList{"target engine"} << ".png" << none << false;
        QTest::newRow("engine strip, screenshot, apply")
            << "sample_scene.png" << QStringList{"target engine"} << ".png" << apply << false;
        QTest::newRow("grading cube, screenshot")
            << "sample_scene.png" << QStringList{"target cube"} << ".cube" << none << false;
        QTest::newRow("smash, 16-bit screenshot")
            << "scene16.png" << QStringList{"target smash"} << ".nutexb" << preview << false;
        QTest::newRow("engine strip, 16-bit screenshot")
            << "scene16.png" << QStringList{"target engine"} << ".png" << none << false;
        QTest::newRow("smash, linear scene")
            << "sample_scene.exr" << QStringList{"target smash"} << ".nutexb" << preview << false;
        QTest::newRow("smash, linear scene, no bloom")
            << "sample_scene.exr" << QStringList{"target smash", "bloom off"} << ".nutexb"
            << preview + QStringList{"--no-bloom"} << false;
        QTest::newRow("engine strip, scene, filmic chain")
            << "sample_scene.exr" << QStringList{"target engine", "chain filmic"} << ".png"
            << preview + QStringList{"--preset", "pilot"} << false;
        QTest::newRow("grading cube, scene, cinematic chain")
            << "sample_scene.exr" << QStringList{"target cube", "chain cinematic"} << ".cube"
            << preview + QStringList{"--preset", "lecture"} << false;
        QTest::newRow("grading cube, scene, display only")
            << "sample_scene.exr" << QStringList{"target cube", "chain none"} << ".cube" << none
            << false;
        QTest::newRow("grading cube, scene, display only, two steps")
            << "sample_scene.exr" << QStringList{"target cube", "chain none"} << ".cube" << apply
            << true;
    }

    void previewIsTheCliRenderingOfTheExportedFileForEveryTarget() {
        QFETCH(QString, image);
        QFETCH(QStringList, setup);
        QFETCH(QString, extension);
        QFETCH(QStringList, cli);
        QFETCH(bool, viaDisplayOnly);
        // Copies, so the default export lands beside them (never in the source tree).
        QTemporaryDir dir;
        const QString in = dir.filePath(image);
        const QString grade = dir.filePath("sample_grade.cube");
        if (image == "scene16.png") { // a 16-bit screenshot: values no 8-bit file holds
            formats::LoadedImage shot =
                formats::readImage(samplePath("sample_scene.png").toStdString());
            for (int y = 0; y < shot.image.height(); ++y)
                for (int x = 0; x < shot.image.width(); ++x)
                    for (int c = 0; c < 3; ++c) {
                        float& v = shot.image.pixel(x, y)[c];
                        v = std::min(1.0f, v * 0.97f + 0.03f * float(x) / shot.image.width());
                    }
            formats::ImageWriteOptions o;
            o.bitDepth = 16;
            o.alpha = false;
            formats::writeImage(in.toStdString(), shot.image, o);
        } else {
            QVERIFY(QFile::copy(samplePath(qPrintable(image)), in));
        }
        QVERIFY(QFile::copy(samplePath("sample_grade.cube"), grade));
        const QString ext =
            image.endsWith(".exr") ? QStringLiteral(".exr") : QStringLiteral(".png");
        // (the sample grade says nothing about its purpose: the editor, told, takes it as an
        // edit, as the CLI does)
        const QString mine = dir.filePath("editor" + ext);
        const QString theirs = dir.filePath("cli" + ext);
        const QString script =
            writeScript(dir, "s.txt",
                        QStringList{"set saturation 1.3", "set exposure 0.2"} + setup +
                            QStringList{"wait", "export", "save-preview " + mine});
        const Run e = run(QString::fromUtf8(LUTKIT_EDITOR), {"--script", script, in, grade});
        QVERIFY2(e.code == 0, qPrintable(e.out + e.err));
        const QString exported = exportedPath(e.out);
        QVERIFY2(exported.endsWith(extension), qPrintable(e.out));
        QCOMPARE(QFileInfo(exported).absolutePath(), QFileInfo(grade).absolutePath());
        if (extension == ".nutexb")
            QCOMPARE(QFileInfo(exported).fileName(), QStringLiteral("color_grading_lut.nutexb"));

        QString cliIn = in;
        if (viaDisplayOnly) { // the display-encoded scene, as a float file
            cliIn = dir.filePath("display.exr");
            const Run d =
                run(QString::fromUtf8(LUTKIT_CLI),
                    {"preview", "-q", "--preset", "none", "--bit-depth", "32", in, "-o", cliIn});
            QVERIFY2(d.code == 0, qPrintable(d.err));
        }
        const Run c = run(QString::fromUtf8(LUTKIT_CLI),
                          cli + QStringList{"--lut", exported, cliIn, "-o", theirs});
        QVERIFY2(c.code == 0, qPrintable(c.err));
        const formats::LoadedImage a = formats::readImage(mine.toStdString());
        const formats::LoadedImage b = formats::readImage(theirs.toStdString());
        QCOMPARE(a.image.width(), b.image.width());
        QCOMPARE(a.image.height(), b.image.height());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < a.image.pixels().size(); ++i)
            differ += i % 4 != 3 && a.image.pixels()[i] != b.image.pixels()[i];
        QCOMPARE(differ, std::size_t(0));
    }

    void theEditorsGameExportIsWhatConvertWrites_data() {
        QTest::addColumn<QString>("lut");
        QTest::newRow("sample grade") << "sample";
        QTest::newRow("values above white, white darkened") << "above";
    }

    // Issue 26: `convert x.cube y.nutexb` and the editor's default export of x.cube are the same
    // bytes: one conversion (lut::convertPurpose) with one rule above white, passed by both.
    void theEditorsGameExportIsWhatConvertWrites() {
        QFETCH(QString, lut);
        QTemporaryDir dir;
        const QString cube = dir.filePath("x.cube");
        if (lut == "sample") {
            QVERIFY(QFile::copy(samplePath("sample_grade.cube"), cube));
        } else {
            // An edit whose outputs leave [0,1] (up to 1.35) and that darkens white to 0.85:
            // where the rule above white decides the entries.
            Lut3D e(9);
            for (int b = 0; b < 9; ++b)
                for (int g = 0; g < 9; ++g)
                    for (int r = 0; r < 9; ++r) {
                        const glm::vec3 in(r / 8.0f, g / 8.0f, b / 8.0f);
                        e.at(r, g, b) = glm::vec3(1.35f * in.x, 0.85f * in.y + 0.02f,
                                                  0.6f * in.z + 0.5f * in.x * in.x);
                    }
            LutFile f;
            f.cube = e;
            formats::writeLut(cube.toStdString(), f);
        }
        const QString script = writeScript(dir, "s.txt", {"target smash", "wait", "export"});
        const Run e = run(QString::fromUtf8(LUTKIT_EDITOR), {"--script", script, cube});
        QVERIFY2(e.code == 0, qPrintable(e.out + e.err));
        const QString exported = exportedPath(e.out);
        QVERIFY2(exported.endsWith(".nutexb"), qPrintable(e.out));
        const QString converted = dir.filePath("convert.nutexb");
        const Run c = run(QString::fromUtf8(LUTKIT_CLI), {"convert", "-q", cube, converted});
        QVERIFY2(c.code == 0, qPrintable(c.err));
        QFile a(exported), b(converted);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QByteArray ab = a.readAll(), bb = b.readAll();
        QVERIFY(!ab.isEmpty());
        QVERIFY2(ab == bb, "the editor's .nutexb differs from lutkit convert's");
        if (lut == "above") { // the case the rule decides: the entries near white differ
            const Lut3D game = formats::readLut(converted.toStdString()).toLut3D();
            // red keeps white (1.35 x clipped): the neutral stage's own entry, the rule above white
            QVERIFY(game.at(15, 15, 15).x > 0.99f);
            // green darkens white to 0.87: the brightest input shows 0.87, as the edited
            // screenshot does (not continued above it: issue 40)
            QVERIFY(game.at(15, 15, 15).y < 0.7f);
        }
    }

    void helpAndVersionNeedNoDisplay() {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        const Run help = run(QString::fromUtf8(LUTKIT_EDITOR), {"--help"}, env);
        QCOMPARE(help.code, 0);
        QVERIFY2(help.out.contains(QStringLiteral("Usage: lutkit-editor")), qPrintable(help.out));
        QVERIFY(help.out.contains(QStringLiteral("--target")));
        const Run version = run(QString::fromUtf8(LUTKIT_EDITOR), {"--version"}, env);
        QCOMPARE(version.code, 0);
        QVERIFY2(version.out.startsWith(QStringLiteral("lutkit-editor ")), qPrintable(version.out));
        const Run bad = run(QString::fromUtf8(LUTKIT_EDITOR), {"--no-such-option"}, env);
        QCOMPARE(bad.code, 2);
    }

    void withoutADisplayOneLineAndExitOne() {
        // Issue 43: started without a display it aborted (exit 134) with Qt's paragraph about
        // reinstalling. Now one line saying so and how to run it, exit 1: with no display named,
        // and with one named that does not answer.
        for (const QString& display : {QString(), QStringLiteral(":987")}) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove(QStringLiteral("DISPLAY"));
            env.remove(QStringLiteral("WAYLAND_DISPLAY"));
            env.remove(QStringLiteral("QT_QPA_PLATFORM"));
            if (!display.isEmpty())
                env.insert(QStringLiteral("DISPLAY"), display);
            const Run r =
                run(QString::fromUtf8(LUTKIT_EDITOR), {samplePath("sample_scene.png")}, env);
            QCOMPARE(r.code, 1);
            const QStringList lines = r.err.trimmed().split('\n');
            QVERIFY2(lines.size() == 1, qPrintable(r.err));
            QVERIFY2(lines[0].startsWith(QStringLiteral("lutkit-editor: error: ")),
                     qPrintable(r.err));
            QVERIFY2(r.err.contains(display.isEmpty() ? QStringLiteral("no display found")
                                                      : QStringLiteral("DISPLAY=:987")),
                     qPrintable(r.err));
            QVERIFY2(r.err.contains(QStringLiteral("QT_QPA_PLATFORM=offscreen")),
                     qPrintable(r.err));
        }
    }

    void helpAllAndBadOptionValuesExitTwoWithoutADisplay() {
        // Issue 28: --help-all and a bad option value aborted (exit 134) looking for a display.
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        const Run all = run(QString::fromUtf8(LUTKIT_EDITOR), {"--help-all"}, env);
        QCOMPARE(all.code, 0);
        QVERIFY2(all.out.contains(QStringLiteral("Usage: lutkit-editor")), qPrintable(all.err));
        const QList<QStringList> bad = {
            {"--preset", "sepia"},    {"--target", "xbox"},      {"--interp", "cubic"},
            {"--input", "photo"},     {"--view", "sideways"},    {"--zoom", "big"},
            {"--zoom", "-5"},         {"--window-size", "huge"}, {"--window-size", "0x0"},
            {"--adjust", "exposure"}, {"--adjust", "warmth=1"},  {"a.png", "b.cube", "c.png"}};
        for (const QStringList& args : bad) {
            const Run r = run(QString::fromUtf8(LUTKIT_EDITOR), args, env);
            QVERIFY2(r.code == 2, qPrintable(args.join(' ') + ": exit " + QString::number(r.code) +
                                             " " + r.err));
            // One line saying what is wrong, naming the value, then where to look.
            const QStringList lines = r.err.trimmed().split('\n');
            QCOMPARE(lines.size(), 2);
            QVERIFY2(lines[0].startsWith(QStringLiteral("lutkit-editor: ")) &&
                         lines[0].contains(args.size() == 3 ? QStringLiteral("3 files")
                                                            : args.last().section('=', 0, 0)),
                     qPrintable(lines[0]));
            QCOMPARE(lines[1], QStringLiteral("Run 'lutkit-editor --help' for usage."));
        }
    }

    void theSecondPassInARealWindowUnderXvfb() {
        // Issue 28 under a real X server, scripted: the long tasks run with progress and Cancel
        // while a repaint probe in the window repaints all along, a huge picture's decoding is
        // cancelled, the hue ranges and Ctrl+= work.
        const QString xvfb = QStandardPaths::findExecutable(QStringLiteral("xvfb-run"));
        if (xvfb.isEmpty())
            QSKIP("xvfb-run is not installed");
        QTemporaryDir dir;
        const QString grade = dir.filePath("grade.cube");
        QVERIFY(QFile::copy(samplePath("sample_grade.cube"), grade));
        const QString shot = dir.filePath("shot.png");
        {
            Image img(1920, 1080);
            for (int y = 0; y < 1080; ++y)
                for (int x = 0; x < 1920; ++x) {
                    float* p = img.pixel(x, y);
                    p[0] = float((x * 255) / 1919) / 255.0f;
                    p[1] = float((y * 255) / 1079) / 255.0f;
                    p[2] = float(((x ^ y) * 7) & 255) / 255.0f;
                    p[3] = 1.0f;
                }
            formats::writeImage(shot.toStdString(), img,
                                formats::ImageWriteOptions(8, false, false));
        }
        const QString huge = dir.filePath("huge.png");
        QVERIFY(lut::gui::test::writeBlackPng(huge, 8192, 8192));
        const QString preview = dir.filePath("preview.png");
        const QString script =
            writeScript(dir, "pass2.txt",
                        {"open-image " + shot, "open-lut " + grade, "wait",
                         // Tools > Compare: on a worker, the window painting all along.
                         "probe on", "start-compare " + grade, "print task:compare",
                         "wait-task compare", "probe off", "print task:compare",
                         // File > Save Preview Image: the same.
                         "probe on", "start-save-preview " + preview, "wait-task save-preview",
                         "probe off", "print task:save-preview",
                         // A 200 KB file holding 8192x8192 pixels: decoding, then cancelled.
                         "probe on", "start-open-image " + huge, "sleep 150", "print task:load",
                         "cancel load", "print task:load", "sleep 100", "probe off", "print title",
                         // Hue vs Sat, the yellows down: one point and its range.
                         "hue-range hue.sat yellows -0.5", "print curve:hue.sat",
                         // Ctrl+= zooms in.
                         "focus curveEditor", "print zoom", "key ctrl+=", "print zoom"});
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
        const Run r = run(xvfb,
                          {"-a", "-s", "-screen 0 1600x1000x24", QString::fromUtf8(LUTKIT_EDITOR),
                           "--script", script},
                          env);
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        qInfo("%s", qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("task:compare busy")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("task:compare idle done")));
        QVERIFY(r.out.contains(QStringLiteral("task:save-preview idle done")));
        QVERIFY(QFileInfo::exists(preview));
        QVERIFY2(r.out.contains(QStringLiteral("task:load busy")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("task:load idle")));
        QVERIFY2(r.out.contains(QStringLiteral("title grade.cube[*] — shot.png")),
                 qPrintable(r.out));
        // Every probe watched its task: the window repainted along it (the gaps are logged above;
        // bench/editor_probe.sh measures them alone on the machine: no time is asserted here).
        QCOMPARE(probePaints(r.out).size(), 3);
        for (const int paints : probePaints(r.out))
            QVERIFY2(paints >= 2, qPrintable(r.out));
        // Yellows down, with neutral anchors at red and green.
        QVERIFY2(r.out.contains(QStringLiteral("curve:hue.sat 0,0 60,-0.5 120,0")),
                 qPrintable(r.out));
        const auto zooms =
            QRegularExpression(QStringLiteral("zoom ([0-9.]+) %")).globalMatch(r.out);
        QList<double> z;
        for (auto it = zooms; it.hasNext();)
            z << it.next().captured(1).toDouble();
        QCOMPARE(z.size(), 2);
        QVERIFY2(std::abs(z[1] / z[0] - 1.25) < 0.01, qPrintable(r.out));
    }

    void theMatchInARealWindowUnderXvfb() {
        // Issue 42 under a real X server, scripted: Tools > Match to Reference on a 1080p
        // screenshot fits on a worker while the repaint probe sees the window repaint, a Cancel
        // stops it, and OK is one undo step.
        const QString xvfb = QStandardPaths::findExecutable(QStringLiteral("xvfb-run"));
        if (xvfb.isEmpty())
            QSKIP("xvfb-run is not installed");
        QTemporaryDir dir;
        const QString shot = dir.filePath("shot.png");
        const QString ref = dir.filePath("look.png");
        {
            Image img(1920, 1080), look(1920, 1080);
            for (int y = 0; y < 1080; ++y)
                for (int x = 0; x < 1920; ++x) {
                    float* p = img.pixel(x, y);
                    p[0] = float((x * 255) / 1919) / 255.0f;
                    p[1] = float((y * 255) / 1079) / 255.0f;
                    p[2] = float(((x ^ y) * 7) & 255) / 255.0f;
                    p[3] = 1.0f;
                    // the look: warmer and darker, its pixels in another order
                    float* q = look.pixel(1919 - x, (y * 7) % 1080);
                    q[0] = std::min(1.0f, 0.1f + 0.9f * p[0]);
                    q[1] = 0.85f * p[1];
                    q[2] = 0.7f * p[2];
                    q[3] = 1.0f;
                }
            formats::writeImage(shot.toStdString(), img,
                                formats::ImageWriteOptions(8, false, false));
            formats::writeImage(ref.toStdString(), look,
                                formats::ImageWriteOptions(8, false, false));
        }
        const QString script = writeScript(
            dir, "match.txt",
            {"open-image " + shot, "wait", "print undo-count",
             // started, then cancelled: nothing changes
             "probe on", "start-match " + ref, "sleep 300", "print task:match", "cancel match",
             "print task:match", "sleep 100", "probe off", "print undo-count",
             // to the end, the dialog answered with OK
             "dialogs accept", "probe on", "start-match " + ref, "wait-task match", "sleep 300",
             "probe off", "print task:match", "print dialogs", "print undo-count", "print title"});
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
        const Run r = run(xvfb,
                          {"-a", "-s", "-screen 0 1600x1000x24", QString::fromUtf8(LUTKIT_EDITOR),
                           "--script", script},
                          env);
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        qInfo("%s", qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("task:match busy")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("task:match idle cancelled")));
        QVERIFY(r.out.contains(QStringLiteral("task:match idle done")));
        QVERIFY2(r.out.contains(QStringLiteral("Match to Reference")), qPrintable(r.out));
        // No step after the cancel, one after OK (undoable: index 1).
        const auto undo = QRegularExpression(QStringLiteral("undo-count ([0-9]+) index ([0-9]+)"))
                              .globalMatch(r.out);
        QStringList counts;
        for (auto it = undo; it.hasNext();)
            counts << it.next().captured(0);
        QCOMPARE(counts, QStringList({"undo-count 0 index 0", "undo-count 0 index 0",
                                      "undo-count 1 index 1"}));
        QVERIFY2(r.out.contains(QStringLiteral("title Untitled[*] — shot.png")), qPrintable(r.out));
        // Both probes watched their task: the window repainted along it (the gaps are logged above;
        // bench/editor_probe.sh measures them alone on the machine: no time is asserted here).
        QCOMPARE(probePaints(r.out).size(), 2);
        for (const int paints : probePaints(r.out))
            QVERIFY2(paints >= 2, qPrintable(r.out));
    }

    void aRealWindowUnderXvfb() {
        const QString xvfb = QStandardPaths::findExecutable(QStringLiteral("xvfb-run"));
        if (xvfb.isEmpty())
            QSKIP("xvfb-run is not installed");
        QTemporaryDir dir;
        const QString grade = dir.filePath("grade.cube");
        QVERIFY(QFile::copy(samplePath("sample_grade.cube"), grade));
        const QString shot = dir.filePath("window.png");
        const QString script = writeScript(
            dir, "x.txt",
            {"drop " + samplePath("sample_scene.png") + " " + grade, "print title", "print input",
             // Type a value, press Enter, then the shortcuts from the spin box.
             "focus spin.exposure", "key ctrl+a", "type 0.75", "key Return", "print param:exposure",
             "key ctrl+z", "print param:exposure", "key ctrl+y", "print param:exposure",
             "key ctrl+shift+z",
             // A slider dragged with the mouse: one undo step.
             "drag saturation 1.4", "print undo-count",
             // Ctrl+E opens the export dialog; Return takes its default (the game's file).
             "dialogs accept", "key ctrl+e", "print dialogs", "wait", "screenshot " + shot,
             "print clip"});
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
        const Run r = run(xvfb,
                          {"-a", "-s", "-screen 0 1600x1000x24", QString::fromUtf8(LUTKIT_EDITOR),
                           "--script", script},
                          env);
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("title grade.cube[*] — sample_scene.png")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("input screenshot")));
        QVERIFY(r.out.contains(QStringLiteral("param:exposure 0.75\nparam:exposure 0\n"
                                              "param:exposure 0.75\n")));
        QVERIFY2(r.out.contains(QStringLiteral("undo-count 2 index 2")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("dialogs Export LUT")), qPrintable(r.out));
        QVERIFY(QFileInfo::exists(dir.filePath("color_grading_lut.nutexb")));
        QVERIFY(r.out.contains(QStringLiteral("clip LUT entries outside 0..1:")));
        const QImage s(shot);
        QCOMPARE(s.size(), QSize(1480, 920));
    }
};

QTEST_GUILESS_MAIN(EditorCliTest)
#include "test_editor_cli.moc"
