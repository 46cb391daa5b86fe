// SPDX-License-Identifier: Apache-2.0
// Issue 16, "usable in the editor": the editor's Tools (Plot LUT, Compare with LUT File) give what
// the CLI gives, run through the scripted mode:
//   - plot-save of the sample grade equals `lutkit plot` of the file the default export wrote,
//     pixel for pixel (grading cube, and Smash's compensated game LUT);
//   - compare of the sample grade with itself reports ΔE 0; with a neutral LUT the same max
//     ΔE2000 as `lutkit diff --json`.
#include "EditorTestSupport.h"
#include "GuiTestSupport.h"
#include "TestPaths.h"

#include "lut/formats/ImageIO.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace lut;
using lut::gui::test::Run;
using lut::gui::test::run;
using lut::gui::test::runEditorScript;
using lut::gui::test::samplePath;

namespace {

QString readText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// The number on the report's "max-delta-e2000 N" line (NaN when missing).
double reportedMax(const QString& report) {
    const auto m = QRegularExpression(QStringLiteral("^max-delta-e2000 (\\S+)$"),
                                      QRegularExpression::MultilineOption)
                       .match(report);
    bool ok = false;
    const double v = m.hasMatch() ? m.captured(1).toDouble(&ok) : 0.0;
    return ok ? v : std::nan("");
}

// Two pictures of the same size, every sample equal.
bool samePixels(const QString& pathA, const QString& pathB) {
    const formats::LoadedImage a = formats::readImage(pathA.toStdString());
    const formats::LoadedImage b = formats::readImage(pathB.toStdString());
    if (a.image.width() != b.image.width() || a.image.height() != b.image.height() ||
        a.image.width() < 100) {
        qWarning("sizes %dx%d and %dx%d", a.image.width(), a.image.height(), b.image.width(),
                 b.image.height());
        return false;
    }
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.image.pixels().size(); ++i)
        differ += a.image.pixels()[i] != b.image.pixels()[i];
    if (differ)
        qWarning("%zu samples differ", differ);
    return differ == 0;
}

} // namespace

class EditorMathsTest : public QObject {
    Q_OBJECT
private slots:
    void plotIsTheCliPlotOfTheExportedFile_data() {
        QTest::addColumn<QString>("target");
        QTest::addColumn<QString>("extension");
        QTest::newRow("grading cube") << "cube"
                                      << ".cube";
        QTest::newRow("smash") << "smash"
                               << ".nutexb";
    }

    void plotIsTheCliPlotOfTheExportedFile() {
        QFETCH(QString, target);
        QFETCH(QString, extension);
        QTemporaryDir dir;
        const QString grade = dir.filePath("sample_grade.cube");
        QVERIFY(QFile::copy(samplePath("sample_grade.cube"), grade));
        const QString exported = dir.filePath("exported" + extension);
        const QString mine = dir.filePath("editor_plot.png");
        const QString theirs = dir.filePath("cli_plot.png");
        const Run e = runEditorScript(
            dir, {"target " + target, "wait", "export " + exported, "plot-save " + mine}, {grade});
        QVERIFY2(e.code == 0, qPrintable(e.out + e.err));
        QVERIFY(QFileInfo::exists(exported));
        const Run c = run(QString::fromUtf8(LUTKIT_CLI), {"plot", "-q", exported, theirs});
        QVERIFY2(c.code == 0, qPrintable(c.out + c.err));
        QVERIFY(samePixels(mine, theirs));
        if (target == "cube") { // the cube export holds the table exactly: the source plots alike
            const QString source = dir.filePath("cli_source_plot.png");
            const Run s = run(QString::fromUtf8(LUTKIT_CLI), {"plot", "-q", grade, source});
            QVERIFY2(s.code == 0, qPrintable(s.err));
            QVERIFY(samePixels(mine, source));
        }

        // An existing file is not replaced without being told (headless: refused).
        const Run again = runEditorScript(dir, {"target " + target, "plot-save " + mine}, {grade});
        QVERIFY2(again.code != 0, qPrintable(again.out));
    }

    void compareReportsTheCliMaxDeltaE() {
        QTemporaryDir dir;
        const QString grade = dir.filePath("sample_grade.cube");
        QVERIFY(QFile::copy(samplePath("sample_grade.cube"), grade));
        const QString neutral = dir.filePath("neutral.cube");
        const Run n = run(QString::fromUtf8(LUTKIT_CLI), {"neutral", "-q", neutral});
        QVERIFY2(n.code == 0, qPrintable(n.out + n.err));
        const QString self = dir.filePath("self.txt");
        const QString other = dir.filePath("neutral.txt");
        const Run e = runEditorScript(
            dir,
            {"target cube", "compare " + grade + " " + self, "compare " + neutral + " " + other},
            {grade});
        QVERIFY2(e.code == 0, qPrintable(e.out + e.err));

        const QString selfText = readText(self);
        QVERIFY2(selfText.contains("identical: ΔE2000 0"), qPrintable(selfText));
        QCOMPARE(reportedMax(selfText), 0.0);

        const QString text = readText(other);
        QVERIFY2(text.contains("ΔE2000   max"), qPrintable(text));
        QVERIFY2(text.contains("8-bit    max   R"), qPrintable(text));
        QVERIFY2(text.contains("worst    input"), qPrintable(text));
        QVERIFY2(text.contains("where    (largest mean ΔE first)"), qPrintable(text));
        const double mine = reportedMax(text);
        QVERIFY2(mine > 0.1, qPrintable(text));

        const Run d = run(QString::fromUtf8(LUTKIT_CLI), {"diff", "--json", grade, neutral});
        QVERIFY2(d.code == 0, qPrintable(d.err));
        const QJsonDocument json = QJsonDocument::fromJson(d.out.toUtf8());
        QVERIFY2(json.isObject(), qPrintable(d.out));
        const double theirs = json.object()["delta_e2000"].toObject()["max"].toDouble();
        QCOMPARE(mine, theirs);
    }
};

QTEST_GUILESS_MAIN(EditorMathsTest)
#include "test_editor_maths.moc"
