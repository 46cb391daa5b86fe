// SPDX-License-Identifier: Apache-2.0
// Issue 23 in the editor: Tools > Match to Reference… on the sample scene, the reference being
// the scene graded by a formula written here and shuffled. The preview takes the matched LUT
// while the sliders move (strength 0: the neutral LUT; 1: near the true grade), Cancel gives the
// document's LUT back, OK makes the match the document's LUT (exported like every other edit).
// Issue 42: the match fitted on a worker (progress, Cancel, the window repainting: the repaint
// probe), the sliders' values shown, Lightness and Colour share kept once moved, OK undoable;
// every slider move re-baked on a worker (latest wins, a cancelled bake never shown, OK waiting
// for the table of the values shown).
#include "GuiTestSupport.h"
#include "ProbeSupport.h"
#include "TestPaths.h"

#include "BackgroundTask.h"
#include "Document.h"
#include "MainWindow.h"
#include "MatchBaker.h"
#include "MatchDialog.h"
#include "MatchSession.h"
#include "PreviewController.h"
#include "WindowActions.h"

#include "lut/formats/ImageIO.h"
#include "lut/interp/Sampler.h"

#include <QAction>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::samplePath;
using namespace lut::gui::test;

namespace {

double q8(double v) {
    return std::round(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0;
}

glm::dvec3 grade(glm::dvec3 in) { // curves per channel, then saturation 1.2
    const glm::dvec3 c(0.03 + 0.94 * std::pow(in.x, 0.85),
                       0.5 + 0.5 * std::tanh(2.0 * (in.y - 0.5)) / std::tanh(1.0),
                       0.02 + 0.9 * in.z);
    const double luma = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    return glm::dvec3(luma) + 1.2 * (c - glm::dvec3(luma));
}

// Mean 8-bit steps between the table applied to the scene and the scene graded.
double stepsToGrade(const Lut3D& table, const Image& scene) {
    const auto s = makeSampler(table, Interpolation::Tetrahedral);
    double sum = 0.0;
    const int n = scene.width() * scene.height();
    for (int i = 0; i < n; ++i) {
        const float* p = scene.data() + 4 * i;
        const glm::vec3 got = s->sample(glm::vec3(p[0], p[1], p[2]));
        const glm::dvec3 want = grade(glm::dvec3(p[0], p[1], p[2]));
        for (int c = 0; c < 3; ++c)
            sum += std::fabs(q8(got[c]) - q8(want[c])) * 255.0;
    }
    return sum / (3.0 * n);
}

// The picture graded by grade() and its pixels shuffled: a reference with the look and no
// correspondence, written as an 8-bit PNG.
QString writeReference(const Image& scene, const char* name) {
    Image ref(scene.width(), scene.height(), 1.0f);
    std::vector<int> order(static_cast<std::size_t>(scene.width() * scene.height()));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    for (std::size_t i = 0; i < order.size(); ++i) {
        const float* p = scene.data() + 4 * order[i];
        const glm::dvec3 g = grade(glm::dvec3(p[0], p[1], p[2]));
        for (int c = 0; c < 3; ++c)
            ref.data()[4 * i + c] = static_cast<float>(q8(g[c]));
    }
    const QString path =
        QString::fromStdString(std::string(LUTKIT_BINARY_DIR) + "/test-tmp-" + name + ".png");
    formats::writeImage(path.toStdString(), ref, formats::ImageWriteOptions(8));
    return path;
}

int boxValue(const QDialog& dlg, const char* slider) {
    auto* box = dlg.findChild<QSpinBox*>(QString::fromLatin1(slider) + QStringLiteral(".value"));
    return box ? box->value() : -1;
}

} // namespace

class EditorMatchTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void matchShowsLiveAndKeepsOnOk() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        const Image scene = *w.document()->storedImage();
        // the reference: the scene graded and shuffled
        Image ref(scene.width(), scene.height(), 1.0f);
        std::vector<int> order(static_cast<std::size_t>(scene.width() * scene.height()));
        std::iota(order.begin(), order.end(), 0);
        std::shuffle(order.begin(), order.end(), std::mt19937(5));
        for (std::size_t i = 0; i < order.size(); ++i) {
            const float* p = scene.data() + 4 * order[i];
            const glm::dvec3 g = grade(glm::dvec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c)
                ref.data()[4 * i + c] = static_cast<float>(q8(g[c]));
        }
        const QString refPath =
            QString::fromStdString(std::string(LUTKIT_BINARY_DIR) + "/test-tmp-editor-match.png");
        formats::writeImage(refPath.toStdString(), ref, formats::ImageWriteOptions(8));
        QVERIFY(w.findChild<QAction*>("matchReference"));

        const Lut3D before = w.document()->baseLut();
        auto session = std::make_unique<MatchSession>(w.document()->storedImage(), false, refPath);
        MatchDialog dlg(&w, EditorContext{w.document(), w.preview(), &w}, std::move(session));
        dlg.show();
        dlg.waitForBake(); // the table is baked on a worker
        auto* report = dlg.findChild<QPlainTextEdit*>("matchReport");
        QVERIFY(report && report->toPlainText().contains("before"));
        auto* strength = dlg.findChild<QSlider*>("matchStrength");
        QVERIFY(strength);

        // full strength: the preview's LUT lands near the true grade
        std::shared_ptr<const Lut3D> shown = w.preview()->source().effective;
        QVERIFY(shown);
        const double full = stepsToGrade(*shown, scene);
        QVERIFY2(full < 1.5, qPrintable(QString::number(full)));
        // strength 0: the neutral LUT
        strength->setValue(0);
        dlg.waitForBake();
        shown = w.preview()->source().effective;
        QVERIFY(shown->maxDeviationFromIdentity() < 1e-5f);
        // Cancel: the document's LUT again, untouched
        dlg.reject();
        QCOMPARE(w.preview()->source(), w.document()->lutSource());
        QVERIFY(w.document()->baseLut().entries() == before.entries());

        // OK keeps it
        MatchDialog again(
            &w, EditorContext{w.document(), w.preview(), &w},
            std::make_unique<MatchSession>(w.document()->storedImage(), false, refPath));
        again.show();
        again.waitForBake();
        auto* buttons = again.findChild<QDialogButtonBox*>();
        QVERIFY(buttons);
        QVERIFY(!w.windowActions()->undoAction()->isEnabled()); // nothing to undo yet
        buttons->button(QDialogButtonBox::Ok)->click();
        QVERIFY(stepsToGrade(w.document()->baseLut(), scene) < 1.5);
        QVERIFY(w.document()->lutOrigin().contains("matched to"));
        QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
        // ... as one undo step: Undo gives back the LUT that was there, Redo the match.
        QVERIFY(w.windowActions()->undoAction()->isEnabled());
        QVERIFY(w.document()->isModified());
        const Lut3D matched = w.document()->baseLut();
        w.windowActions()->undoAction()->trigger();
        QVERIFY(w.document()->baseLut().entries() == before.entries());
        QVERIFY(!w.document()->lutOrigin().contains("matched to"));
        QVERIFY(!w.document()->isModified());
        QCOMPARE(w.preview()->source(), w.document()->lutSource());
        w.windowActions()->redoAction()->trigger();
        QVERIFY(w.document()->baseLut().entries() == matched.entries());
        QVERIFY(w.document()->isModified());
    }

    void slidersShowTheirValuesAndStayIndependent() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        const QString refPath = writeReference(*w.document()->storedImage(), "editor-match-sl");
        MatchDialog dlg(
            &w, EditorContext{w.document(), w.preview(), &w},
            std::make_unique<MatchSession>(w.document()->storedImage(), false, refPath));
        dlg.show();
        auto* strength = dlg.findChild<QSlider*>("matchStrength");
        auto* luma = dlg.findChild<QSlider*>("matchLuma");
        auto* chroma = dlg.findChild<QSlider*>("matchChroma");
        QVERIFY(strength && luma && chroma);
        // Every slider shows its value.
        QCOMPARE(boxValue(dlg, "matchStrength"), 100);
        QCOMPARE(boxValue(dlg, "matchLuma"), 100);
        QCOMPARE(boxValue(dlg, "matchChroma"), 100);
        // Untouched, the shares follow Strength (unset: lutkit match's rule).
        strength->setValue(80);
        QCOMPARE(boxValue(dlg, "matchStrength"), 80);
        QCOMPARE(luma->value(), 80);
        QCOMPARE(boxValue(dlg, "matchLuma"), 80);
        QVERIFY(!dlg.session().options().lumaStrength);
        QCOMPARE(dlg.session().options().strength, 0.8);
        // Lightness moved on its own keeps its value when Strength moves; Colour still follows.
        luma->setValue(30);
        QCOMPARE(boxValue(dlg, "matchLuma"), 30);
        strength->setValue(150);
        QCOMPARE(luma->value(), 30);
        QCOMPARE(boxValue(dlg, "matchLuma"), 30);
        QCOMPARE(chroma->value(), 150);
        QCOMPARE(dlg.session().options().lumaStrength.value_or(-1), 0.3);
        QVERIFY(!dlg.session().options().chromaStrength);
        QCOMPARE(dlg.session().options().strength, 1.5);
        // A value typed in the number box moves its slider, and that share is kept too.
        auto* chromaBox = dlg.findChild<QSpinBox*>("matchChroma.value");
        chromaBox->setValue(60);
        QCOMPARE(chroma->value(), 60);
        strength->setValue(10);
        QCOMPARE(chroma->value(), 60);
        QCOMPARE(luma->value(), 30);
        QCOMPARE(dlg.session().options().chromaStrength.value_or(-1), 0.6);
        // The preview shows those amounts: lightness 0 and colour 0 is the neutral LUT.
        luma->setValue(0);
        chroma->setValue(0);
        strength->setValue(200);
        QCOMPARE(luma->value(), 0);
        dlg.waitForBake();
        QVERIFY(w.preview()->source().effective->maxDeviationFromIdentity() < 1e-5f);
        dlg.reject();
    }

    void matchRunsOnAWorkerWithProgressAndCancel() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1200, 800);
        w.show();
        formats::LoadedImage shot = noisyPicture(1920, 1080);
        const QString refPath = writeReference(shot.image, "editor-match-1080");
        w.document()->adoptImage(std::move(shot), QStringLiteral("shot.png"));
        w.waitForPreview();
        RepaintProbe* probe = probeIn(w);
        BackgroundTask* task = w.windowActions()->matchTask();
        TaskStatus* status = statusOf(w, "task.match");
        QVERIFY(task && status);

        // Started, the call returns at once; the status bar shows it; Cancel stops it.
        probe->start();
        w.windowActions()->startMatch(refPath);
        QVERIFY(task->isBusy());
        QVERIFY(status->isVisible());
        QVERIFY(status->text().contains(QStringLiteral("editor-match-1080")));
        QVERIFY(waitFor([&] { return task->fraction() > 0.05; }, 60000));
        status->cancelButton()->click();
        QVERIFY(!task->isBusy());
        QCOMPARE(task->lastOutcome(), BackgroundTask::Outcome::Cancelled);
        QVERIFY(waitFor([&] { return task->threadsRunning() == 0; }, 30000)); // it stopped
        QTest::qWait(100);
        probe->stop();
        QVERIFY(!w.windowActions()->matchDialog());
        QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
        qInfo("match cancelled: %s", qPrintable(stallText(*probe)));
        QVERIFY2(repaintedThroughout(*probe), qPrintable(stallText(*probe)));

        // To the end: the window repaints throughout, the progress rises, the dialog opens.
        double lastFraction = 0.0;
        int rises = 0;
        connect(task, &BackgroundTask::progressChanged, this, [&](double f) {
            if (f > lastFraction + 1e-9)
                ++rises;
            lastFraction = std::max(lastFraction, f);
        });
        probe->start();
        w.windowActions()->startMatch(refPath);
        task->waitForIdle();
        probe->stop();
        QCOMPARE(task->lastOutcome(), BackgroundTask::Outcome::Done);
        qInfo("match to the end: %s, progress rose %d times", qPrintable(stallText(*probe)), rises);
        QVERIFY2(repaintedThroughout(*probe), qPrintable(stallText(*probe)));
        QVERIFY(rises >= 2);
        MatchDialog* dlg = w.windowActions()->matchDialog();
        QVERIFY(dlg && dlg->isVisible());
        auto* buttons = dlg->findChild<QDialogButtonBox*>();
        buttons->button(QDialogButtonBox::Ok)->click(); // waits for the bake if one runs
        QVERIFY(waitFor([&] { return w.document()->lutOrigin().contains("editor-match-1080"); },
                        30000));
        QVERIFY(w.document()->baseLut().maxDeviationFromIdentity() > 0.02f);
        QVERIFY(w.windowActions()->undoAction()->isEnabled());
        QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
    }
    // A slider's move re-bakes on a worker, never on the window's thread: the move returns with
    // the preview as it was (the table arrives through the window's events). Latest wins: the
    // values a drag passes while a bake runs are never baked; what the preview keeps is the table
    // of the values the sliders rest on (strength 0: the neutral LUT; 1: near the true grade).
    void slidersRebakeOnAWorkerLatestWins() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        const Image scene = *w.document()->storedImage();
        const QString refPath = writeReference(scene, "editor-match-bake");
        MatchDialog dlg(
            &w, EditorContext{w.document(), w.preview(), &w},
            std::make_unique<MatchSession>(w.document()->storedImage(), false, refPath));
        dlg.show();
        dlg.waitForBake();
        auto* strength = dlg.findChild<QSlider*>("matchStrength");
        QVERIFY(strength);
        const std::shared_ptr<const Lut3D> full = w.preview()->source().effective;
        QVERIFY(full && full->maxDeviationFromIdentity() > 0.02f);

        int proxies = 0, exacts = 0;
        std::shared_ptr<const Lut3D> lastExact;
        connect(dlg.baker(), &MatchBaker::baked, &dlg,
                [&](std::shared_ptr<const Lut3D> t, bool exact) {
                    exact ? ++exacts : ++proxies;
                    if (exact)
                        lastExact = t;
                });
        const int bakes = dlg.baker()->bakes(), skipped = dlg.baker()->skipped();
        // 100 moves with no event run between them (the window's thread busy with the drag)
        for (int v = 99; v >= 0; --v) {
            strength->setValue(v);
            QVERIFY(w.preview()->source().effective == full); // not baked here
        }
        QVERIFY(dlg.isBaking());
        dlg.waitForBake();
        // the first move's bake ran; 98 waited and were replaced; the last one was baked
        QCOMPARE(dlg.baker()->bakes() - bakes, 2);
        QCOMPARE(dlg.baker()->skipped() - skipped, 98);
        QCOMPARE(proxies, 1); // strength 0.99's table, overtaken: shown while on its way
        QCOMPARE(exacts, 1);
        QVERIFY(w.preview()->source().effective == lastExact);
        QVERIFY(lastExact->maxDeviationFromIdentity() < 1e-5f);
        // and back to full strength: near the true grade (the formula above)
        strength->setValue(100);
        QVERIFY(w.preview()->source().effective == lastExact);
        dlg.waitForBake();
        QVERIFY(stepsToGrade(*w.preview()->source().effective, scene) < 1.5);
        dlg.reject();
    }

    // Cancel while a table bakes: the document as it was (its LUT, no undo step), and the table
    // baking never reaches the preview. OK while a table bakes: the dialog waits for it, and the
    // document takes the table of the values the sliders show (not the one the preview showed
    // when OK was pressed), in one undo step that gives back the exact LUT that was there.
    void cancelAndOkWhileBaking() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.waitForPreview();
        const Lut3D before = w.document()->baseLut();
        QVERIFY(before.maxDeviationFromIdentity() > 0.02f); // a real grade, not the neutral LUT
        const QString origin = w.document()->lutOrigin();
        const int steps = w.document()->undoStack()->count();
        const QString refPath = writeReference(*w.document()->storedImage(), "editor-match-ok");
        auto open = [&] {
            auto d = std::make_unique<MatchDialog>(
                &w, EditorContext{w.document(), w.preview(), &w},
                std::make_unique<MatchSession>(w.document()->storedImage(), false, refPath));
            d->show();
            d->waitForBake();
            return d;
        };
        {
            auto dlg = open();
            dlg->findChild<QSlider*>("matchStrength")->setValue(50);
            QVERIFY(dlg->isBaking());
            dlg->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Cancel)->click();
            QVERIFY(!dlg->isVisible());
            dlg->waitForBake(); // the dropped bake ends and delivers nothing
            QCOMPARE(w.preview()->source(), w.document()->lutSource());
            QVERIFY(w.document()->baseLut().entries() == before.entries());
            QCOMPARE(w.document()->lutOrigin(), origin);
            QCOMPARE(w.document()->undoStack()->count(), steps);
            QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
        }
        {
            auto dlg = open();
            const std::shared_ptr<const Lut3D> shown = w.preview()->source().effective;
            QVERIFY(shown->maxDeviationFromIdentity() > 0.02f); // full strength shown
            dlg->findChild<QSlider*>("matchStrength")->setValue(0);
            QVERIFY(dlg->isBaking());
            QPushButton* ok = dlg->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
            ok->click();
            QVERIFY(dlg->isVisible()); // waiting for the bake, the window live
            QVERIFY(!ok->isEnabled());
            QVERIFY(w.document()->baseLut().entries() == before.entries());
            QVERIFY(waitFor([&] { return !dlg->isVisible(); }, 30000));
            QVERIFY(w.document()->baseLut().maxDeviationFromIdentity() < 1e-5f); // strength 0
            QVERIFY(w.document()->lutOrigin().contains("matched to"));
            QCOMPARE(w.document()->undoStack()->count(), steps + 1);
            QVERIFY(w.windowActions()->undoAction()->isEnabled());
            w.windowActions()->undoAction()->trigger();
            QVERIFY(w.document()->baseLut().entries() == before.entries());
            QCOMPARE(w.document()->lutOrigin(), origin);
            QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
        }
    }
};

QTEST_MAIN(EditorMatchTest)
#include "test_editor_match.moc"
