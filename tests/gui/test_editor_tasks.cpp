// SPDX-License-Identifier: Apache-2.0
// Issue 28, the editor's second pass: nothing freezes, nothing ambiguous. Each problem of the
// issue driven through the window, offscreen, as a user meets it:
//   - Tools > Compare with LUT File, File > Save Preview Image and opening a file run on workers
//     with progress and Cancel in the status bar; a repaint probe (RepaintProbe.h) in the window
//     repaints all along while they run (its longest gaps logged, measured by
//     bench/editor_probe.sh: no time is asserted here); a cancelled
//     compare opens no report, a cancelled save leaves the old file, a cancelled or superseded open
//     stops decoding (a 200 KB PNG of 8192x8192 pixels, made here with zlib);
//   - the export suggests beside the opened LUT (the documented edited/ folder for a stage's
//     color_grading_lut.nutexb), the replace question names the full path, and "Keep the file"
//     returns to the export dialog;
//   - Ctrl+= zooms in; a dropped 256x16 strip is asked its layout as Open LUT asks;
//   - the first graded frame of a 4K picture: logged (speed is measured, never asserted).
#include "EditorTestSupport.h"
#include "GuiTestSupport.h"
#include "ProbeSupport.h"

#include "BackgroundTask.h"
#include "CompareDialog.h"
#include "Document.h"
#include "ExportDialog.h"
#include "ExportNaming.h"
#include "FileActions.h"
#include "FileLoader.h"
#include "MainWindow.h"
#include "PreviewController.h"
#include "PreviewView.h"
#include "RepaintProbe.h"
#include "TaskStatus.h"
#include "WindowActions.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <QAbstractButton>
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QtTest>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::samplePath;
using namespace lut::gui::test;

namespace {

// CPU time of the process (every thread), to tell work from waiting on a busy machine.
double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

} // namespace

class EditorTasksTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        formats::registerBuiltinFormats();
    }

    void compareRunsOnAWorkerWithProgressAndCancel() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.document()->adoptImage(noisyPicture(1920, 1080), QStringLiteral("shot.png"));
        w.waitForPreview();
        RepaintProbe* probe = probeIn(w);
        BackgroundTask* task = w.windowActions()->compareTask();
        TaskStatus* status = statusOf(w, "task.compare");
        QVERIFY(status);

        // Started, the call returns at once; the status bar shows it with its progress.
        probe->start();
        QElapsedTimer call;
        call.start();
        w.windowActions()->startCompare(samplePath("sample_grade.cube"));
        const double callMs = call.nsecsElapsed() / 1e6;
        QVERIFY(task->isBusy());
        QVERIFY(status->isVisible());
        QVERIFY(status->text().contains(QStringLiteral("sample_grade.cube")));
        QVERIFY(waitFor([&] { return task->fraction() > 0.02; }, 60000));
        // Cancel: the window is free at once, no report opens, nothing is delivered later.
        status->cancelButton()->click();
        QVERIFY(!task->isBusy());
        QVERIFY(!status->isVisible());
        QCOMPARE(task->lastOutcome(), BackgroundTask::Outcome::Cancelled);
        QVERIFY(waitFor([&] { return task->threadsRunning() == 0; }, 30000)); // it stopped
        QTest::qWait(100);
        probe->stop();
        QVERIFY(!w.windowActions()->compareDialog());
        QVERIFY(!w.windowActions()->lastComparison());
        qInfo("compare started in %.1f ms; %s", callMs, qPrintable(stallText(*probe)));
        QVERIFY2(repaintedThroughout(*probe), qPrintable(stallText(*probe)));

        // To the end on a smaller picture: the report opens beside the window, not modal.
        w.document()->adoptImage(noisyPicture(320, 180), QStringLiteral("small.png"));
        w.waitForPreview();
        probe->start();
        w.windowActions()->startCompare(samplePath("sample_grade.cube"));
        task->waitForIdle();
        probe->stop();
        QCOMPARE(task->lastOutcome(), BackgroundTask::Outcome::Done);
        QVERIFY(w.windowActions()->compareDialog());
        QVERIFY(w.windowActions()->compareDialog()->isVisible());
        QVERIFY(!w.windowActions()->compareDialog()->isModal());
        const auto* report = w.windowActions()->compareDialog()->findChild<QPlainTextEdit*>(
            QStringLiteral("compareReport"));
        QVERIFY(report && report->toPlainText().contains(QStringLiteral("small.png")));
        QVERIFY2(repaintedThroughout(*probe, 2), qPrintable(stallText(*probe)));
        w.windowActions()->compareDialog()->close();
    }

    void savePreviewImageRunsOnAWorkerAndACancelKeepsTheOldFile() {
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.document()->adoptImage(noisyPicture(3840, 2160), QStringLiteral("shot4k.png"));
        w.waitForPreview();
        RepaintProbe* probe = probeIn(w);
        BackgroundTask* task = w.fileActions()->saveTask();
        const QString path = dir.filePath("preview.png");
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly) && old.write("the old file") > 0);
        old.close();

        // Cancelled once it has written part of the picture: the old file is as it was.
        probe->start();
        QVERIFY(w.fileActions()->startSavePreview(path));
        QVERIFY(task->isBusy());
        QVERIFY(statusOf(w, "task.savePreview")->isVisible());
        QVERIFY(waitFor([&] { return task->fraction() > 0.05 || !task->isBusy(); }, 60000));
        QVERIFY2(task->isBusy(), "the save ended before it could be cancelled");
        statusOf(w, "task.savePreview")->cancelButton()->click();
        QCOMPARE(task->lastOutcome(), BackgroundTask::Outcome::Cancelled);
        // Its thread stops at the next chunk of rows and removes its temporary file.
        QVERIFY(waitFor([&] { return task->threadsRunning() == 0; }, 30000));
        QFile kept(path);
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("the old file"));
        kept.close();
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList{"preview.png"});

        // To the end: the file is the full-resolution preview, and the window never stalled.
        QVERIFY(w.fileActions()->startSavePreview(path));
        task->waitForIdle();
        probe->stop();
        QCOMPARE(task->lastOutcome(), BackgroundTask::Outcome::Done);
        const formats::LoadedImage saved = formats::readImage(path.toStdString());
        QCOMPARE(saved.image.width(), 3840);
        const Image want = w.preview()->renderFullResolution();
        std::size_t differ = 0;
        for (std::size_t i = 0; i < want.pixels().size(); i += 4)
            for (int c = 0; c < 3; ++c)
                differ +=
                    saved.image.pixels()[i + c] !=
                    float(std::lround(std::clamp(double(want.pixels()[i + c]), 0.0, 1.0) * 255.0)) /
                        255.0f;
        QCOMPARE(differ, std::size_t(0));
        qInfo("save preview 4K: %s", qPrintable(stallText(*probe)));
        QVERIFY2(repaintedThroughout(*probe), qPrintable(stallText(*probe)));
    }

    void openingAHugePictureIsCancellableAndASecondOpenStopsIt() {
        QTemporaryDir dir;
        const QString huge = dir.filePath("huge.png");
        QVERIFY(lut::gui::test::writeBlackPng(huge, 8192, 8192));
        QVERIFY2(QFileInfo(huge).size() < 400 * 1024,
                 qPrintable(QString::number(QFileInfo(huge).size())));
        const QString small = dir.filePath("small.png");
        formats::writeImage(small.toStdString(), noisyPicture(64, 48).image,
                            formats::ImageWriteOptions(8, false, false));

        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        FileLoader* loader = w.fileActions()->loader();
        QList<QPair<QString, double>> stopped;
        connect(loader, &FileLoader::readStopped, this, [&](const QString& p, double f) {
            stopped.append({p, f});
        });
        RepaintProbe* probe = probeIn(w);
        probe->start();

        // Cancel: the status bar's button, while the picture decodes.
        QVERIFY(w.fileActions()->startOpenImage(huge));
        TaskStatus* loading = statusOf(w, "loading");
        QVERIFY(loading->isVisible());
        QVERIFY(loading->text().contains(QStringLiteral("huge.png")));
        QVERIFY(waitFor([&] { return loader->fraction() > 0.0 || !loader->isBusy(); }, 60000));
        QVERIFY2(loader->isBusy(), "the picture was read before it could be cancelled");
        loading->cancelButton()->click();
        QVERIFY(!loader->isBusy());
        QVERIFY(!loading->isVisible());
        QVERIFY(waitFor([&] { return loader->threadsRunning() == 0; }, 10000));
        QVERIFY(waitFor([&] { return !stopped.isEmpty(); }, 2000));
        QCOMPARE(stopped.last().first, huge);
        QVERIFY2(stopped.last().second < 0.9, qPrintable(QString::number(stopped.last().second)));
        QVERIFY(!w.document()->hasImage());

        // Superseded: another picture opened meanwhile stops the first one's decoding.
        stopped.clear();
        QVERIFY(w.fileActions()->startOpenImage(huge));
        QVERIFY(waitFor([&] { return loader->fraction() > 0.0 || !loader->isBusy(); }, 60000));
        QVERIFY(w.openImageFile(small));
        QVERIFY(waitFor([&] { return loader->threadsRunning() == 0; }, 10000));
        QVERIFY(waitFor([&] { return !stopped.isEmpty(); }, 2000));
        QCOMPARE(stopped.last().first, huge);
        QVERIFY2(stopped.last().second < 0.9, qPrintable(QString::number(stopped.last().second)));
        QCOMPARE(w.document()->imagePath(), small);
        w.waitForPreview();
        probe->stop();
        qInfo("huge picture open, cancel, supersede: %s", qPrintable(stallText(*probe)));
        QVERIFY2(repaintedThroughout(*probe), qPrintable(stallText(*probe)));
    }

    void theExportSuggestsBesideTheOpenedStageLut() {
        // A mod's stage folder and a screenshot folder elsewhere (the case).
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("mod/stage/battlefield/normal/lut"));
        QVERIFY(QDir(dir.path()).mkpath("shots"));
        const QString stage = dir.filePath("mod/stage/battlefield/normal/lut");
        ExportNameInput in;
        in.lutPath = stage + "/color_grading_lut.nutexb";
        in.imagePath = dir.filePath("shots/battlefield.png");
        in.format = QStringLiteral("nutexb");
        in.extension = QStringLiteral(".nutexb");
        QCOMPARE(suggestedExportPath(in), stage + "/edited/color_grading_lut.nutexb");
        // Another LUT of that stage: beside it, not in the screenshots' folder.
        in.lutPath = stage + "/look.cube";
        QCOMPARE(suggestedExportPath(in), stage + "/color_grading_lut.nutexb");
        // No LUT opened (a neutral start): beside the picture.
        in.lutPath.clear();
        QCOMPARE(suggestedExportPath(in), dir.filePath("shots/color_grading_lut.nutexb"));
    }

    void keepInTheReplaceQuestionReturnsToTheExportDialog() {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("stage/edited"));
        const QString lut = dir.filePath("stage/color_grading_lut.nutexb");
        LutFile neutral;
        neutral.cube = Lut3D::identity(16);
        formats::writeLut(lut.toStdString(), neutral);
        const QString target = dir.filePath("stage/edited/color_grading_lut.nutexb");
        QFile previous(target);
        QVERIFY(previous.open(QIODevice::WriteOnly) && previous.write("previous export") > 0);
        previous.close();

        MainWindow w;
        w.setInteractiveErrors(true); // the questions are asked
        w.show();
        QVERIFY(w.openLutFile(lut));
        QStringList seen;
        int exportDialogs = 0;
        // First the export dialog: Export (its default file, the edited/ one). Then the question:
        // it names the full path; Keep. Then the export dialog again, same file: Cancel.
        std::function<void()> answerExport;
        answerExport = [&] {
            onNextDialog<ExportDialog>([&](ExportDialog* d) {
                ++exportDialogs;
                seen << QStringLiteral("export:") + d->path();
                if (exportDialogs == 1) {
                    onNextDialog<QMessageBox>([&](QMessageBox* box) {
                        seen << QStringLiteral("question:") + box->text();
                        answerExport();
                        box->reject(); // Escape: "Keep the file"
                    });
                    d->accept();
                } else {
                    d->reject();
                }
            });
        };
        answerExport();
        w.fileActions()->exportDialog();
        QCOMPARE(exportDialogs, 2);
        QCOMPARE(seen.size(), 3);
        QCOMPARE(seen[0], QStringLiteral("export:") + target);
        QVERIFY2(seen[1].contains(QDir::toNativeSeparators(target)), qPrintable(seen[1]));
        QCOMPARE(seen[2], QStringLiteral("export:") + target);
        QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError())); // no error box on Keep
        QFile kept(target);
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("previous export"));
    }

    void ctrlEqualsZoomsIn() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        activate(w);
        const double before = w.previewView()->zoom();
        QTest::keyClick(&w, Qt::Key_Equal, Qt::ControlModifier);
        QVERIFY2(std::abs(w.previewView()->zoom() - before * 1.25) < 1e-9,
                 qPrintable(QString::number(w.previewView()->zoom() / before)));
        QTest::keyClick(&w, Qt::Key_Minus, Qt::ControlModifier);
        QVERIFY(std::abs(w.previewView()->zoom() - before) < 1e-9);
    }

    void aDroppedStripIsAskedItsLayout() {
        QTemporaryDir dir;
        const QString strip = dir.filePath("graded.png");
        LutFile f;
        f.cube = Lut3D::identity(16);
        FormatOptions o;
        o.layout = LutLayout::Pilot;
        formats::writeLut(strip.toStdString(), f, o, "strip");
        QVERIFY(stripLayoutIsAmbiguous(strip));

        MainWindow w;
        w.setInteractiveErrors(true);
        w.show();
        // One dialog asks the layout and, since the strip does not say, what it is for.
        QString asked;
        bool purposeAsked = false;
        onNextDialog<QDialog>([&](QDialog* d) {
            if (d->objectName() != QStringLiteral("openLut"))
                return;
            asked = d->findChild<QLabel*>(QStringLiteral("openLut.question"))->text();
            d->findChild<QComboBox*>(QStringLiteral("openLut.layout"))
                ->setCurrentText(QStringLiteral("unity"));
            if (auto* game = d->findChild<QAbstractButton*>(QStringLiteral("purpose.smash"))) {
                purposeAsked = true;
                game->click();
            }
            d->accept();
        });
        bool askedTwice = false;
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(strip)});
        QDragEnterEvent enter(QPoint(200, 200), Qt::CopyAction, &mime, Qt::LeftButton,
                              Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        QDropEvent drop(QPointF(200, 200), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QVERIFY(drop.isAccepted());
        QVERIFY(waitFor([&] { return !asked.isEmpty(); }, 8000));
        QTimer secondQuestion; // lives as long as this test: no second question while it loads
        connect(&secondQuestion, &QTimer::timeout, this, [&] {
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* box = qobject_cast<QMessageBox*>(top); box && box->isVisible()) {
                    askedTwice = true;
                    box->reject();
                }
        });
        secondQuestion.start(20);
        w.waitForLoads();
        secondQuestion.stop();
        QVERIFY2(asked.contains(QStringLiteral("graded.png")), qPrintable(asked));
        QVERIFY(purposeAsked);
        QCOMPARE(w.document()->lutPath(), strip);
        QCOMPARE(w.document()->lutPurpose(), LutPurpose::Smash); // the answer given
        QVERIFY(!askedTwice);
        // Read as the unity layout it was told (a neutral unreal strip read as unity is not
        // neutral: the layouts order the slices differently).
        const Lut3D asUnity = [&] {
            FormatOptions u;
            u.layout = LutLayout::Unity;
            return formats::readLut(strip.toStdString(), u).toLut3D();
        }();
        QCOMPARE(w.document()->baseLut().entries(), asUnity.entries());
    }

    void firstGradedFrameOfA4kPictureIsLogged() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1480, 920);
        w.show();
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        QElapsedTimer clock;
        double firstGraded = -1, firstFull = -1, before = -1, cpuGraded = -1, cpuFull = -1;
        double cpu0 = 0;
        QString frames;
        connect(w.preview(), &PreviewController::beforeReady, this, [&] {
            if (before < 0)
                before = clock.nsecsElapsed() / 1e6;
        });
        connect(w.preview(), &PreviewController::frameReady, this,
                [&](std::shared_ptr<const PreviewFrame> f) {
                    const double now = clock.nsecsElapsed() / 1e6;
                    if (!f->error.isEmpty())
                        return;
                    frames += QStringLiteral(" [1/%1 at %2 ms: LUT %3, scopes %4, total %5]")
                                  .arg(f->proxyFactor)
                                  .arg(now, 0, 'f', 0)
                                  .arg(f->milliseconds, 0, 'f', 0)
                                  .arg(f->scopesMilliseconds, 0, 'f', 0)
                                  .arg(f->totalMilliseconds, 0, 'f', 0);
                    if (firstGraded < 0) {
                        firstGraded = now;
                        cpuGraded = cpuSeconds() - cpu0;
                    }
                    if (f->proxyFactor == 1 && firstFull < 0) {
                        firstFull = now;
                        cpuFull = cpuSeconds() - cpu0;
                    }
                });
        RepaintProbe* probe = probeIn(w);
        formats::LoadedImage picture = noisyPicture(3840, 2160);
        probe->start();
        cpu0 = cpuSeconds();
        clock.start();
        w.document()->adoptImage(std::move(picture), QStringLiteral("shot4k.png"));
        w.waitForPreview();
        const double cpu = cpuSeconds() - cpu0;
        probe->stop();
        qInfo("4K picture: before picture after %.0f ms, first graded frame after %.0f ms (CPU of "
              "all threads until then %.0f ms), full-resolution frame after %.0f ms (CPU %.0f "
              "ms; target: first graded frame within 300 ms); CPU %.2f s; %s; frames:%s",
              before, firstGraded, cpuGraded * 1000, firstFull, cpuFull * 1000, cpu,
              qPrintable(stallText(*probe)), qPrintable(frames));
        QVERIFY(firstGraded >= 0 && firstFull >= firstGraded);
    }
};

QTEST_MAIN(EditorTasksTest)
#include "test_editor_tasks.moc"
