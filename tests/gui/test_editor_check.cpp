// SPDX-License-Identifier: Apache-2.0
// Issue 24 in the editor: the Check panel lists lutkit check's findings for the LUT the export
// writes, kept current; clicking a finding highlights its colours on the picture, and the
// highlighted pixels are exactly those the defect's formula (written here) says it touches; an
// export warns about a failing check. A game LUT is judged by what the game shows with it.
#include "GuiTestSupport.h"

#include "CheckModel.h"
#include "CheckPanel.h"
#include "Document.h"
#include "MainWindow.h"
#include "PreviewController.h"
#include "PreviewView.h"

#include "lut/formats/ImageIO.h"

#include <QListWidget>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace lut;
using namespace lut::gui;

namespace {

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// Red folds back near the red axis: R = r - 0.25 (1 - g)(1 - b) smoothstep(0.45, 0.65, r).
double foldRed(double r, double g, double b) {
    return r - 0.25 * (1 - g) * (1 - b) * smoothstep(0.45, 0.65, r);
}
// Whether output red falls as input red rises at this colour (the formula's derivative sign,
// by a central difference).
bool folds(double r, double g, double b) {
    return foldRed(r + 1e-4, g, b) < foldRed(r - 1e-4, g, b);
}

QString writeFoldCube(const QTemporaryDir& dir) {
    const QString path = dir.filePath("fold.cube");
    std::ofstream o(path.toStdString());
    o.precision(9);
    constexpr int n = 33;
    o << "LUT_3D_SIZE " << n << "\n";
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                o << foldRed(r / 32.0, g / 32.0, b / 32.0) << " " << g / 32.0 << " " << b / 32.0
                  << "\n";
    return path;
}

// A 64x32 screenshot: the left half a dark red the fold touches, the right half a grey.
const glm::vec3 kRed(0.55f, 0.04f, 0.03f), kGrey(0.5f, 0.5f, 0.5f);
QString writeShot(const QTemporaryDir& dir) {
    Image shot(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            const glm::vec3 c = x < 32 ? kRed : kGrey;
            float* p = shot.pixel(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = 1.0f;
        }
    formats::ImageWriteOptions w;
    w.alpha = false;
    w.bitDepth = 16; // the colours as written, within 1/65535
    const QString path = dir.filePath("shot.png");
    formats::writeImage(path.toStdString(), shot, w);
    return path;
}

void settle(MainWindow& w) {
    w.waitForLoads();
    w.waitForPreview();
    w.checkPanel()->model()->waitForIdle();
    QApplication::processEvents();
}

} // namespace

class EditorCheckTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void findingsListedAndHighlightedOnThePicture() {
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        w.document()->setTarget(ExportTarget::Grading); // the export is the LUT itself
        QVERIFY(w.openImageFile(writeShot(dir)));
        QVERIFY(w.openLutFile(writeFoldCube(dir)));
        settle(w);
        CheckPanel* panel = w.checkPanel();
        const auto report = panel->model()->report();
        QVERIFY(report);
        QVERIFY2(panel->verdictText().startsWith(QStringLiteral("FAIL")),
                 qPrintable(panel->verdictText()));
        QVERIFY(panel->verdictText().contains(QStringLiteral("monotonicity")));
        QListWidget* list = panel->findingsList();
        QCOMPARE(list->count(), static_cast<int>(report->findings.size()));
        QVERIFY(list->item(0)->text().contains(QStringLiteral("fold-over")));

        // Clicking the first finding highlights the colours it concerns: the formula folds at
        // the red, not at the grey, and the overlay marks exactly the red half.
        QVERIFY(folds(kRed.r, kRed.g, kRed.b));
        QVERIFY(!folds(kGrey.r, kGrey.g, kGrey.b));
        list->scrollToItem(list->item(0));
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                          list->visualItemRect(list->item(0)).center());
        settle(w);
        const QImage& overlay = w.previewView()->highlight();
        QCOMPARE(overlay.size(), QSize(64, 32));
        for (int y = 0; y < 32; y += 5)
            for (int x = 0; x < 64; x += 3)
                QCOMPARE(qAlpha(overlay.pixel(x, y)) > 0, x < 32);
        QCOMPARE(panel->model()->highlightedPixels(), 32 * 32);
        // A second click takes it away.
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                          list->visualItemRect(list->item(0)).center());
        settle(w);
        QVERIFY(w.previewView()->highlight().isNull());

        // Exporting that LUT warns about the failing check (the notes bar).
        QVERIFY(w.exportLut(dir.filePath("out.cube"), QStringLiteral("cube"), {},
                            ExportTarget::Grading));
        QVERIFY2(w.notesText().contains(QStringLiteral("Check: monotonicity fails: fold-over")),
                 qPrintable(w.notesText()));
    }

    void keptCurrentAndGameLutsJudgedByTheLookTheyGive() {
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(writeShot(dir)));
        // The neutral document, Smash target: the compensated game LUT, judged by what the game
        // shows, passes (its own table fails: compressed under 0.73 and clipped there).
        settle(w);
        QCOMPARE(w.document()->target(), ExportTarget::Smash);
        auto report = w.checkPanel()->model()->report();
        QVERIFY(report);
        QVERIFY2(report->status() == CheckStatus::Pass, qPrintable(w.checkPanel()->verdictText()));
        QVERIFY(report->description.find("the game shows") != std::string::npos);
        QCOMPARE(w.checkPanel()->findingsList()->count(), 0);
        // A new LUT: the panel follows.
        QVERIFY(w.openLutFile(writeFoldCube(dir)));
        settle(w);
        report = w.checkPanel()->model()->report();
        QVERIFY(report && report->status() == CheckStatus::Fail);
        QVERIFY(w.checkPanel()->verdictText().contains(QStringLiteral("monotonicity")));
    }

    void aDragIsCheckedOnceItSettlesAndAnExportWarnsAboutItsOwnLut() {
        // A slider drag hands the model a new LUT every frame: checking each one took both cores
        // from the preview (found by hand, 2026-11-29: 105-135 ms of CPU per 1080p drag frame
        // instead of ~30). Ten LUTs in a row are checked once, the last, after they settle.
        CheckModel model;
        int reports = 0;
        connect(&model, &CheckModel::reportChanged, [&] { ++reports; });
        std::shared_ptr<const Lut3D> last;
        for (int i = 0; i < 10; ++i) {
            Lut3D lut = Lut3D::identity(17);
            for (int b = 0; b < 17; ++b)
                for (int g = 0; g < 17; ++g)
                    for (int r = 0; r < 17; ++r)
                        lut.at(r, g, b) *= 1.0f - 0.02f * static_cast<float>(i);
            last = std::make_shared<const Lut3D>(std::move(lut));
            model.setLut(last, false);
            QCoreApplication::processEvents();
        }
        QVERIFY(model.isBusy()); // settling
        QTRY_VERIFY_WITH_TIMEOUT(!model.isBusy(), 20000);
        QCOMPARE(reports, 1);
        QVERIFY(model.report());
        QCOMPARE(model.failingChecks().size(), 0); // a darker neutral: nothing fails
        // The fold of findingsListedAndHighlightedOnThePicture set, and the export's warnings
        // asked at once, before any check of it ran: they are the fold's, not the last report's.
        Lut3D fold = Lut3D::identity(17);
        for (int b = 0; b < 17; ++b)
            for (int g = 0; g < 17; ++g)
                for (int r = 0; r < 17; ++r)
                    fold.at(r, g, b).r = static_cast<float>(foldRed(r / 16.0, g / 16.0, b / 16.0));
        model.setLut(std::make_shared<const Lut3D>(std::move(fold)), false);
        const QStringList warnings = model.failingChecks();
        QVERIFY2(!warnings.isEmpty() && warnings.join(' ').contains(QStringLiteral("monotonicity")),
                 qPrintable(warnings.join('\n')));
        QTRY_VERIFY_WITH_TIMEOUT(!model.isBusy(), 20000);
        QCOMPARE(model.failingChecks(), warnings); // nothing older replaced it
    }
};

QTEST_MAIN(EditorCheckTest)
#include "test_editor_check.moc"
