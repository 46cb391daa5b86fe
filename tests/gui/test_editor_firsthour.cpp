// SPDX-License-Identifier: Apache-2.0
// Issue 43's editor items, what a person meets in the first hour: the game's .cube and the edit's
// under distinct names; an untagged game strip asked its purpose with the game's LUT pre-selected
// and why, read in its own layout (the LUT dock shows smush); atlases in the export list; built-in
// LUTs by names a person reads; the After side never the ungraded picture; Help's quick start and
// shortcuts; History rows with their values. Also the export dialog's Strength written.
#include "EditorTestSupport.h"
#include "GuiTestSupport.h"
#include "TestPaths.h"

#include "Document.h"
#include "ExportDialog.h"
#include "FileActions.h"
#include "LutView.h"
#include "MainWindow.h"
#include "PreviewView.h"
#include "WindowActions.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::onNextDialog;
using lut::gui::test::samplePath;

namespace {

double srgbEnc(double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}
double srgbDec(double x) {
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}

// Smush-LUT's game LUT (16^3, 8-bit) for a warm edit, in the smush layout (x = r + 16 g, y = b:
// docs/specs/strip-layouts.md), as its tool writes it: for each lattice input s the game showed
// srgb(min(1, (1.3703 s)^2.2)); the entry makes it show the edit of that (Smush-LUT's formula,
// tests/lutlib/test_game_lut_evidence.cpp), with no tag saying what it is for.
void writeSmushGameStrip(const QString& path) {
    Image img(256, 16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const double s[3] = {r / 15.0, g / 15.0, b / 15.0};
                const double gain[3] = {0.95, 0.9, 0.8}, lift[3] = {0.0, 0.0, 0.05};
                float* p = img.pixel(r + 16 * g, b);
                for (int c = 0; c < 3; ++c) {
                    const double shown = srgbEnc(std::min(1.0, std::pow(1.3703 * s[c], 2.2)));
                    const double w = std::clamp(gain[c] * shown + lift[c], 0.0, 1.0);
                    const double l =
                        (std::pow(srgbDec(w), 1 / 2.2) / 1.3703 - s[c]) / 0.99961 + s[c];
                    p[c] = static_cast<float>(std::round(std::clamp(l, 0.0, 1.0) * 255.0) / 255.0);
                }
                p[3] = 1.0f;
            }
    formats::writeImage(path.toStdString(), img, formats::ImageWriteOptions(8, false, false));
}

QString exportPathFor(ExportTarget target, const QString& format, const ExportNameInput& naming) {
    ExportDialog dlg(target, naming);
    if (!dlg.selectChoice(format))
        return {};
    return dlg.path();
}

} // namespace

class EditorFirstHourTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        formats::registerBuiltinFormats();
    }

    void theGamesCubeAndTheEditsHaveDistinctNames() {
        QTemporaryDir dir;
        ExportNameInput naming;
        naming.lutPath = dir.filePath("look.cube");
        naming.imagePath = dir.filePath("shot.png");
        // The Smash target's .cube (the game's LUT) and the Grading target's (the edit).
        const QString game = exportPathFor(ExportTarget::Smash, "cube", naming);
        const QString edit = exportPathFor(ExportTarget::Grading, "cube", naming);
        QVERIFY(!game.isEmpty() && !edit.isEmpty());
        QVERIFY2(game != edit, qPrintable(game));
        QCOMPARE(QFileInfo(game).fileName(), QStringLiteral("look_game_cube.cube"));
        QCOMPARE(QFileInfo(edit).fileName(), QStringLiteral("look_cube.cube"));
        // Every other format too: the game's and the edit's never share a name.
        for (const QString f : {"flame", "resolve_cube", "spi3d"}) {
            const QString g = exportPathFor(ExportTarget::Smash, f, naming);
            QVERIFY2(g.isEmpty() || g != exportPathFor(ExportTarget::Grading, f, naming),
                     qPrintable(g));
        }
    }

    void anUntaggedGameStripIsAskedWithTheGameSelectedAndShownInItsLayout() {
        QTemporaryDir dir;
        const QString strip = dir.filePath("smush_out.png");
        writeSmushGameStrip(strip);
        MainWindow w;
        w.setInteractiveErrors(true);
        w.show();
        bool asked = false, gameSelected = false, editSelected = true;
        QString why;
        onNextDialog<QDialog>([&](QDialog* d) {
            if (d->objectName() != QStringLiteral("openLut"))
                return;
            asked = true;
            auto* game = d->findChild<QAbstractButton*>(QStringLiteral("purpose.smash"));
            auto* edit = d->findChild<QAbstractButton*>(QStringLiteral("purpose.raw"));
            gameSelected = game && game->isChecked();
            editSelected = edit && edit->isChecked();
            for (QLabel* l : d->findChildren<QLabel*>())
                why += l->text() + QLatin1Char('\n');
            d->accept(); // the pre-selected answers
        });
        QVERIFY(w.fileActions()->openLutAsking(strip));
        w.waitForLoads();
        QVERIFY(asked);
        QVERIFY(gameSelected);
        QVERIFY(!editSelected);
        QVERIFY2(why.contains(QStringLiteral("content says it is the game's LUT")) &&
                     why.contains(QStringLiteral("186")),
                 qPrintable(why));
        QCOMPARE(w.document()->lutPurpose(), LutPurpose::Smash);
        // Read, and shown in the LUT dock, in its own layout (not "unreal").
        QCOMPARE(w.document()->lutLayout().value_or(LutLayout::Hald), LutLayout::Smush);
        QCOMPARE(w.lutView()->layout(), LutLayout::Smush);
        // Opened again the way every strip is detected: still shown as smush.
        w.setInteractiveErrors(false);
        w.document()->newNeutral(33);
        QVERIFY(w.openLutFile(strip));
        QCOMPARE(w.lutView()->layout(), LutLayout::Smush);
    }

    void atlasesAreInTheExportListAndGrowByARow() {
        bool listed = false;
        for (const ExportChoice& c : exportChoices())
            listed = listed || (c.format == QStringLiteral("atlas") && c.layout == "reshade");
        QVERIFY(listed);

        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.document()->setTarget(ExportTarget::Grading);
        const QString atlas = dir.filePath("looks.png");
        FormatOptions o;
        o.layout = LutLayout::Reshade;
        QVERIFY(w.fileActions()->exportLut(atlas, "atlas", o, ExportTarget::Grading, false));
        QImage first(atlas);
        QCOMPARE(first.size(), QSize(1024, 64)); // the neutral row and the LUT
        first = first.convertToFormat(QImage::Format_RGB888);
        // Row 0 is the neutral LUT, by the reshade placement: x = r + 32 b, y = g.
        int worst = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 1024; ++x) {
                const QColor c = first.pixelColor(x, y);
                const int want[3] = {int(std::lround(255.0 * (x % 32) / 31.0)),
                                     int(std::lround(255.0 * y / 31.0)),
                                     int(std::lround(255.0 * (x / 32) / 31.0))};
                worst = std::max({worst, std::abs(c.red() - want[0]), std::abs(c.green() - want[1]),
                                  std::abs(c.blue() - want[2])});
            }
        QCOMPARE(worst, 0);
        // Row 1: what lutkit atlas build makes of the Grading export, byte for byte.
        const QString cube = dir.filePath("edit.cube");
        QVERIFY(w.fileActions()->exportLut(cube, "cube", {}, ExportTarget::Grading, false));
        const QString ref = dir.filePath("ref.png");
        QProcess cli;
        cli.start(QString::fromUtf8(LUTKIT_CLI),
                  {"atlas", "build", cube, "-o", ref, "--neutral-first", "-q"});
        QVERIFY(cli.waitForFinished(60000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QCOMPARE(first, QImage(ref).convertToFormat(QImage::Format_RGB888));

        // Exported again into that atlas: its rows are kept and the LUT is added below them.
        w.document()->editParam(AdjustParam::Exposure, 0.5);
        QVERIFY(w.fileActions()->exportLut(atlas, "atlas", o, ExportTarget::Grading, false));
        const QImage second = QImage(atlas).convertToFormat(QImage::Format_RGB888);
        QCOMPARE(second.size(), QSize(1024, 96));
        QCOMPARE(second.copy(0, 0, 1024, 64), first);
        QVERIFY(second.copy(0, 64, 1024, 32) != first.copy(0, 32, 1024, 32));
        // The same LUT again is refused, naming the row, and the file stays as it was.
        QVERIFY(!w.fileActions()->exportLut(atlas, "atlas", o, ExportTarget::Grading, false));
        QVERIFY2(w.lastError().contains(QStringLiteral("row 2")) &&
                     w.lastError().contains(QStringLiteral("the export")) &&
                     !w.lastError().contains(QStringLiteral("row3.cube")),
                 qPrintable(w.lastError()));
        QCOMPARE(QImage(atlas).convertToFormat(QImage::Format_RGB888), second);
        // A picture that is no atlas is never replaced.
        const QString photo = dir.filePath("photo.png");
        QImage(300, 200, QImage::Format_RGB888).save(photo);
        const QByteArray before = [&] {
            QFile f(photo);
            f.open(QIODevice::ReadOnly);
            return f.readAll();
        }();
        QVERIFY(!w.fileActions()->exportLut(photo, "atlas", o, ExportTarget::Grading, false));
        QFile f(photo);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), before);
    }

    void builtInLutsHaveNamesAPersonReads() {
        MainWindow w;
        w.setInteractiveErrors(false);
        auto* smash = w.findChild<QAction*>(QStringLiteral("open.builtin:smash-default"));
        auto* neutral = w.findChild<QAction*>(QStringLiteral("open.builtin:neutral"));
        QVERIFY(smash && neutral);
        QCOMPARE(smash->text(), QStringLiteral("Smash Ultimate's default stage LUT"));
        QVERIFY(!neutral->text().contains(QStringLiteral("builtin")));
        smash->trigger();
        w.waitForLoads();
        QVERIFY2(w.windowTitle().startsWith(QStringLiteral("Smash Ultimate's default stage LUT")),
                 qPrintable(w.windowTitle()));
        QVERIFY(!w.windowTitle().contains(QStringLiteral("builtin:")));
        QCOMPARE(w.document()->lutOrigin(), QStringLiteral("Smash Ultimate's default stage LUT"));
        w.document()->openLut(QStringLiteral("builtin:neutral"));
        QCOMPARE(w.document()->displayName(), QStringLiteral("Neutral (no change, 16³)"));
    }

    void theAfterSideNeverShowsTheUngradedPicture() {
        PreviewView v;
        v.resize(400, 200);
        v.show();
        v.setImageSize(QSize(200, 100));
        QImage before(200, 100, QImage::Format_RGB32);
        before.fill(QColor(255, 0, 0));
        v.setBefore(before); // the picture just opened; its graded frame not there yet
        for (PreviewView::Mode m : {PreviewView::Mode::After, PreviewView::Mode::Split}) {
            v.setMode(m);
            const QImage shot = v.grab().toImage();
            const QColor right = shot.pixelColor(shot.width() * 3 / 4, shot.height() / 2);
            QVERIFY2(right != QColor(255, 0, 0), qPrintable(right.name()));
        }
        QImage after(200, 100, QImage::Format_RGB32);
        after.fill(QColor(0, 0, 255));
        v.setAfter(after);
        const QImage shot = v.grab().toImage();
        QCOMPARE(shot.pixelColor(shot.width() * 3 / 4, shot.height() / 2), QColor(0, 0, 255));
        QCOMPARE(shot.pixelColor(shot.width() / 4, shot.height() / 2), QColor(255, 0, 0));
    }

    void helpHasTheQuickStartAndEveryShortcut() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        auto* quick = w.findChild<QAction*>(QStringLiteral("help.quickStartAction"));
        auto* keys = w.findChild<QAction*>(QStringLiteral("help.shortcutsAction"));
        QVERIFY(quick && keys);
        quick->trigger();
        auto* qs = w.findChild<QTextBrowser*>(QStringLiteral("help.quickStart.text"));
        QVERIFY(qs && qs->isVisible());
        const QString guide = qs->toPlainText();
        for (const char* step : {"Open Image", "Target", "Export LUT", "color_grading_lut.nutexb"})
            QVERIFY2(guide.contains(QString::fromLatin1(step)), step);
        keys->trigger();
        auto* list = w.findChild<QTextBrowser*>(QStringLiteral("help.shortcuts.text"));
        QVERIFY(list && list->isVisible());
        const QString text = list->toPlainText();
        // Every key of every action of the window is listed.
        int listed = 0;
        for (QAction* a : w.findChildren<QAction*>())
            for (const QKeySequence& k : a->shortcuts()) {
                QVERIFY2(text.contains(k.toString(QKeySequence::NativeText)),
                         qPrintable(k.toString() + " " + a->text()));
                ++listed;
            }
        QVERIFY(listed >= 15);
        QVERIFY(text.contains(QStringLiteral("Ctrl+E")) && text.contains(QStringLiteral("Undo")));
    }

    void historyRowsShowTheirValues() {
        MainWindow w;
        w.setInteractiveErrors(false);
        Document* doc = w.document();
        doc->editParam(AdjustParam::Exposure, 0.25);
        doc->editParam(AdjustParam::Exposure, 0.5); // the same drag: one step, where it ended
        doc->endGesture();
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->undoStack()->text(0), QStringLiteral("Set Exposure (stops): 0.000 → 0.500"));
        doc->editParam(AdjustParam::Saturation, 1.2);
        doc->endGesture();
        QCOMPARE(doc->undoStack()->text(1), QStringLiteral("Set Saturation: 1.000 → 1.200"));
        doc->resetAdjustments();
        QVERIFY2(doc->undoStack()->text(2).contains(QStringLiteral("Exposure (stops) 0.500 → "
                                                                   "0.000")),
                 qPrintable(doc->undoStack()->text(2)));
        doc->editCurve(CurveId::Master,
                       Curve(CurveKind::Tone, {{0.0, 0.0}, {0.5, 0.62}, {1.0, 1.0}}));
        QVERIFY2(doc->undoStack()->text(3).contains(QStringLiteral("3 points")) &&
                     doc->undoStack()->text(3).contains(QStringLiteral("(0.50, 0.62)")),
                 qPrintable(doc->undoStack()->text(3)));
    }

    void theExportDialogsStrengthIsWritten() {
        // File > Export LUT with Strength 0: the file is the neutral LUT (the dialog's amounts
        // were dropped: the export ran without them).
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.document()->setTarget(ExportTarget::Grading);
        w.setInteractiveErrors(true);
        const QString out = dir.filePath("half.cube");
        onNextDialog<ExportDialog>([&](ExportDialog* d) {
            d->findChild<QLineEdit*>(QStringLiteral("path"))->setText(out);
            d->findChild<QDoubleSpinBox*>(QStringLiteral("strength"))->setValue(0.0);
            d->accept();
        });
        w.fileActions()->exportDialog();
        const LutFile written = formats::readLut(out.toStdString());
        QVERIFY(written.cube);
        QVERIFY2(written.cube->maxDeviationFromIdentity() < 1e-5f,
                 qPrintable(QString::number(written.cube->maxDeviationFromIdentity())));
    }
};

QTEST_MAIN(EditorFirstHourTest)
#include "test_editor_firsthour.moc"
