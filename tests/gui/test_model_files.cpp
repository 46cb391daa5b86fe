// SPDX-License-Identifier: Apache-2.0
// The editor's document model without widgets, its files and names: recent files, what a dropped
// file is, the export's suggested names, error texts, a strip's notes and layout, built-in LUTs.
#include "GuiTestSupport.h"

#include "Document.h"
#include "ErrorText.h"
#include "ExportNaming.h"
#include "RecentFiles.h"

#include "lut/LutPurpose.h"
#include "lut/formats/Registry.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::maxDiff;
using lut::gui::test::samplePath;

class ModelFilesTest : public QObject {
    Q_OBJECT
private slots:
    void recentFilesAreUniqueAndBounded() {
        QStringList l;
        for (int i = 0; i < 15; ++i)
            l = addRecentFile(l, QStringLiteral("/tmp/f%1.cube").arg(i), 10);
        QCOMPARE(l.size(), 10);
        QCOMPARE(l.first(), QStringLiteral("/tmp/f14.cube"));
        l = addRecentFile(l, QStringLiteral("/tmp/f10.cube"), 10);
        QCOMPARE(l.first(), QStringLiteral("/tmp/f10.cube"));
        QCOMPARE(l.count(QStringLiteral("/tmp/f10.cube")), 1);
    }

    void classifiesDroppedFiles() {
        QVERIFY(looksLikeLutFile(samplePath("sample_grade.cube")));
        QVERIFY(!looksLikeLutFile(samplePath("sample_scene.png")));
        QVERIFY(!looksLikeLutFile(samplePath("sample_scene.exr")));
    }

    void exportNamesAreNewAndOnePerFormat() {
        // Issue 15, problem 1: the export's suggested file is never the opened LUT, the game's
        // is color_grading_lut.nutexb, and two formats never share a name.
        QTemporaryDir dir;
        const QString grade = dir.filePath("my_grade.cube");
        QFile::copy(samplePath("sample_grade.cube"), grade);
        ExportNameInput in;
        in.lutPath = grade;
        in.imagePath = samplePath("sample_scene.png");
        in.format = QStringLiteral("nutexb");
        in.extension = QStringLiteral(".nutexb");
        QCOMPARE(suggestedExportPath(in), dir.filePath("color_grading_lut.nutexb"));
        in.format = QStringLiteral("cube");
        in.extension = QStringLiteral(".cube");
        const QString cube = suggestedExportPath(in);
        QVERIFY2(cube != grade, qPrintable(cube));
        QCOMPARE(QFileInfo(cube).absolutePath(), QFileInfo(grade).absolutePath());
        in.format = QStringLiteral("flame");
        in.extension = QStringLiteral(".3dl");
        const QString flame = suggestedExportPath(in);
        in.format = QStringLiteral("lustre");
        const QString lustre = suggestedExportPath(in);
        QVERIFY2(flame != lustre, qPrintable(flame));
        in.format = QStringLiteral("strip");
        in.extension = QStringLiteral(".png");
        in.layout = QStringLiteral("pilot");
        const QString pilot = suggestedExportPath(in);
        in.layout = QStringLiteral("unity");
        QVERIFY(pilot != suggestedExportPath(in));
        // The opened LUT is the game's file: the suggestion keeps the name in another folder.
        in.lutPath = dir.filePath("color_grading_lut.nutexb");
        in.imagePath.clear();
        in.format = QStringLiteral("nutexb");
        in.extension = QStringLiteral(".nutexb");
        in.layout.clear();
        const QString edited = suggestedExportPath(in);
        QVERIFY2(edited != in.lutPath && edited.endsWith("/color_grading_lut.nutexb"),
                 qPrintable(edited));
        // Untitled: beside the picture.
        in.lutPath.clear();
        in.imagePath = dir.filePath("shot.png");
        QCOMPARE(suggestedExportPath(in), dir.filePath("color_grading_lut.nutexb"));
    }

    void errorTextsNameTheLimitNotTheConstant() {
        QTemporaryDir dir;
        QFile f(dir.filePath("huge.cube"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("LUT_3D_SIZE 300\n0 0 0\n");
        f.close();
        Document doc;
        QString message;
        try {
            doc.openLut(f.fileName());
        } catch (const std::exception& e) {
            message = QString::fromStdString(humanErrorText(e));
        }
        QVERIFY2(message.contains(QStringLiteral("256 points per axis")), qPrintable(message));
        QVERIFY2(!message.contains(QStringLiteral("lut::")) && !message.contains("kMax"),
                 qPrintable(message));
        // The rest of the message is the library's, word for word: only the limit's name changed.
        QCOMPARE(message, f.fileName() + QStringLiteral(":1:13: LUT_3D_SIZE 300 is over the limit "
                                                        "of 256 (the largest 3D LUT lutkit reads "
                                                        "has 256 points per axis) (found '300')"));
    }

    void errorTextsAreToldByTypeNotByText() {
        // An error that merely mentions a limit's name (a file called so, a quoted line) is
        // shown as it is; the limit's words come from the error's type and limit alone.
        const Error plain("kMax3DSize.cube: lut::limits::kMax1DSize is not a LUT");
        QCOMPARE(humanErrorText(plain), std::string(plain.what()));
        const LineLimitError line("x.cube", 2, 65537, LimitId::MaxTextLineBytes,
                                  "line is longer than the limit of 65536 bytes (", ")", "abc");
        QCOMPARE(std::string(line.what()),
                 std::string("x.cube:2:65537: line is longer than the limit of 65536 bytes "
                             "(lut::limits::kMaxTextLineBytes) (found 'abc')"));
        QCOMPARE(humanErrorText(line),
                 std::string("x.cube:2:65537: line is longer than the limit of 65536 bytes (the "
                             "longest line lutkit reads is 65,536 bytes) (found 'abc')"));
        const FileLimitError file(LimitId::MaxLutFileBytes, "big.cube: file is 9 bytes (", ")");
        QCOMPARE(std::string(file.what()),
                 std::string("big.cube: file is 9 bytes (lut::limits::kMaxLutFileBytes)"));
        QCOMPARE(humanErrorText(file),
                 std::string("big.cube: file is 9 bytes (the largest LUT file lutkit reads is "
                             "2,048 MB)"));
    }

    void stripNotesAreKeptAndTheLayoutCanBeChosen() {
        // A 256x16 strip fits three layouts: a Unity strip is detected as such and the reader
        // says so (a note that changes what the user gets); the note reaches the document, and
        // the user's choice of layout reads the picture that way.
        QTemporaryDir dir;
        Lut3D warm = Lut3D::identity(16);
        for (std::size_t i = 0; i < warm.entryCount(); ++i)
            warm.entries()[i].x = std::min(1.0f, warm.entries()[i].x * 1.1f);
        const QString path = dir.filePath("strip.png");
        LutFile f;
        f.cube = warm;
        FormatOptions unity;
        unity.layout = LutLayout::Unity;
        formats::writeLut(path.toStdString(), f, unity);
        Document doc;
        const QStringList notes = doc.openLut(path);
        QVERIFY2(notes.join(' ').contains(QStringLiteral("layout detected")),
                 qPrintable(notes.join(' ')));
        QCOMPARE(doc.lutNotes(), notes);
        QVERIFY(stripLayoutIsAmbiguous(path));
        QVERIFY(maxDiff(doc.baseLut(), warm) < 0.5 / 255 + 1e-6); // detected right: 8-bit only
        FormatOptions pilot;
        pilot.layout = LutLayout::Pilot;
        doc.openLut(path, pilot);
        const Lut3D want = formats::readLut(path.toStdString(), pilot).toLut3D();
        QCOMPARE(maxDiff(doc.baseLut(), want), 0.0);
        QVERIFY(maxDiff(doc.baseLut(), warm) > 0.1); // read the other way: another LUT
    }

    void builtInLutsOpenUntitled() {
        // builtin:smash-default is the game's default stage LUT: a game LUT, and no file, so the
        // document stays untitled (Save asks where; nothing is written to "builtin:...").
        Document doc;
        doc.openLut(QStringLiteral("builtin:smash-default"));
        QVERIFY(doc.lutPath().isEmpty());
        QCOMPARE(doc.lutOrigin(), QStringLiteral("Smash Ultimate's default stage LUT")); // issue 43
        QCOMPARE(doc.lutPurpose(), LutPurpose::Smash);
        QCOMPARE(doc.baseLut().size(), 16);
        QCOMPARE(doc.baseLut().at(7, 0, 15), glm::vec3(121.0f, 0.0f, 255.0f) / 255.0f);
        QVERIFY(!doc.isModified());
        doc.openLut(QStringLiteral("builtin:neutral"));
        QCOMPARE(doc.lutPurpose(), LutPurpose::Raw);
        QVERIFY(doc.baseLut().isIdentity(0.0f));
        QVERIFY(looksLikeLutFile(QStringLiteral("builtin:smash-default")));
    }
};

QTEST_GUILESS_MAIN(ModelFilesTest)
#include "test_model_files.moc"
