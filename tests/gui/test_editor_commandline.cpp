// SPDX-License-Identifier: Apache-2.0
// lutkit-editor's command line (gui/app/EditorOptions.h), run as a program: --save-preview and
// --screenshot without a display (the preview equal to the pipeline's through the one 8-bit
// conversion), a LUT named first or alone, lutkit's vocabulary (-V, -v, --interp), bad usage.
#include "EditorTestSupport.h"
#include "GuiTestSupport.h"
#include "TestPaths.h"

#include "Document.h"
#include "PreviewController.h"
#include "PreviewRenderer.h"

#include "lut/Quantize.h"
#include "lut/Version.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/pipeline/Pipeline.h"

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::samplePath;

namespace {

// lutkit-editor run to its end with `args`: exit 0, else false with its stderr in *err.
bool runsOk(const QStringList& args, QString* err = nullptr) {
    const lut::gui::test::Run r = lut::gui::test::run(QString::fromUtf8(LUTKIT_EDITOR), args);
    if (err)
        *err = r.err;
    return r.code == 0;
}

} // namespace

class EditorCommandLineTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { formats::registerBuiltinFormats(); }

    void savePreviewAndScreenshotFromTheCommandLine() {
        QTemporaryDir dir;
        const QString preview = dir.filePath("preview.png");
        const QString shot = dir.filePath("shot.png");
        QString err;
        QVERIFY2(runsOk({QStringLiteral("--save-preview"), preview, samplePath("sample_scene.png"),
                         samplePath("sample_grade.cube")},
                        &err),
                 qPrintable(err));
        QVERIFY2(runsOk({QStringLiteral("--screenshot"), shot, QStringLiteral("--window-size"),
                         QStringLiteral("1200x800"), samplePath("sample_scene.png"),
                         samplePath("sample_grade.cube")},
                        &err),
                 qPrintable(err));
        const QImage s(shot);
        QCOMPARE(s.size(), QSize(1200, 800));

        // The saved preview is the pipeline output through the one 8-bit conversion.
        Document doc;
        doc.openImage(samplePath("sample_scene.png"));
        doc.openLut(samplePath("sample_grade.cube"));
        const PreviewOptions o;
        const ExportTarget t = doc.target(); // Smash, as the window's
        const Image want = renderPreview(prepareScene(*doc.storedImage(), false, o, t), o, t,
                                         makeTargetLut(doc.lutSource(), t).shown)
                               .image;
        const formats::LoadedImage got = formats::readImage(preview.toStdString());
        QCOMPARE(got.image.width(), want.width());
        QCOMPARE(got.image.height(), want.height());
        int mismatches = 0;
        for (int y = 0; y < want.height(); ++y)
            for (int x = 0; x < want.width(); ++x)
                for (int c = 0; c < 3; ++c)
                    mismatches +=
                        toUnorm8(got.image.pixel(x, y)[c]) != toUnorm8(want.pixel(x, y)[c]);
        QCOMPARE(mismatches, 0);

        // A LUT named first (or alone, as a file manager's "Open with" passes it) is still the
        // LUT: the same preview bytes as IMAGE LUT (it used to be opened as a picture and fail).
        const QString swapped = dir.filePath("swapped.png");
        QVERIFY2(runsOk({QStringLiteral("--save-preview"), swapped, samplePath("sample_grade.cube"),
                         samplePath("sample_scene.png")},
                        &err),
                 qPrintable(err));
        QFile a(preview), b(swapped);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());
        QVERIFY2(runsOk({QStringLiteral("--screenshot"), dir.filePath("lut-only.png"),
                         samplePath("sample_grade.cube")},
                        &err),
                 qPrintable(err));
    }

    // lutkit-editor's command line speaks lutkit's vocabulary (issue 18): -V is the version, -v
    // verbose, --interp the interpolation (--interpolation still works), any bad usage exits 2.
    void commandLineSpeaksLutkitsVocabulary() {
        QString out, err;
        auto run = [&out, &err](const QStringList& args) {
            QProcess p;
            p.start(QString::fromUtf8(LUTKIT_EDITOR), args);
            if (!p.waitForFinished(120000))
                return -1;
            out = QString::fromLocal8Bit(p.readAllStandardOutput());
            err = QString::fromLocal8Bit(p.readAllStandardError());
            return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        };
        QCOMPARE(run({QStringLiteral("-V")}), 0);
        QCOMPARE(out, QStringLiteral("lutkit-editor " LUTKIT_VERSION "\n"));
        QCOMPARE(run({QStringLiteral("--no-such-option")}), 2);
        QVERIFY2(err.contains(QLatin1String("no-such-option")), qPrintable(err));
        QCOMPARE(run({QStringLiteral("--preset"), QStringLiteral("bogus")}), 2);
        QCOMPARE(run({QStringLiteral("--interp"), QStringLiteral("cubic")}), 2);
        const QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("p.png"));
        for (const QString& interp :
             {QStringLiteral("--interp"), QStringLiteral("--interpolation")})
            QCOMPARE(run({QStringLiteral("-v"), QStringLiteral("--save-preview"), png, interp,
                          QStringLiteral("tetrahedral"), QStringLiteral("--preset"),
                          QStringLiteral("filmic"), samplePath("sample_scene.png")}),
                     0);
    }
};

QTEST_MAIN(EditorCommandLineTest)
#include "test_editor_commandline.moc"
