// SPDX-License-Identifier: Apache-2.0
// The editor driven like a user, offscreen: open files, drag a slider, undo, export, compare the
// exported LUT with a float64 expectation, and check the preview pixels against the pipeline and
// (when it exists) `lutkit preview`.
#include "GuiTestSupport.h"
#include "TestPaths.h"

#include "AdjustmentsPanel.h"
#include "Document.h"
#include "ExportDialog.h"
#include "MainWindow.h"
#include "PreviewController.h"
#include "PreviewRenderer.h"
#include "PreviewView.h"
#include "WindowActions.h"

#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/smash/SmashCompensation.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QWheelEvent>
#include <QtTest>

#include <ctime>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::exposureRef;
using lut::gui::test::samplePath;

namespace {

// Drags a slider from where it is to `position` in a few steps, like a mouse would.
void dragSlider(QSlider* s, int position) {
    s->setSliderDown(true);
    const int start = s->value();
    for (int i = 1; i <= 4; ++i)
        s->setValue(start + (position - start) * i / 4);
    s->setSliderDown(false);
}

// CPU seconds this process used (all threads): with a loaded machine the wall time says little,
// CPU time / cores is what the update costs on an idle one.
double processCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

} // namespace

class EditorTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void openFilesAndPreviewEqualsPipeline() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        QVERIFY(w.windowTitle().contains(QStringLiteral("sample_grade.cube")));
        QVERIFY(w.windowTitle().contains(QStringLiteral("sample_scene.png")));
        QVERIFY(!w.isWindowModified());
        w.waitForPreview();
        auto frame = w.currentFrame();
        QVERIFY(frame);
        QCOMPARE(frame->proxyFactor, 1);
        const PreviewOptions o = w.previewOptions();
        const ExportTarget t = w.document()->target();
        const Image want = renderPreview(prepareScene(*w.document()->storedImage(), false, o, t), o,
                                         t, makeTargetLut(w.document()->lutSource(), t).shown)
                               .image;
        QVERIFY(frame->image.pixels() == want.pixels());
        // The displayed 8-bit image is the same pixels through toUnorm8.
        QCOMPARE(qRed(frame->display.pixel(10, 20)), int(toUnorm8(want.pixel(10, 20)[0])));
    }

    void wheelMovesOnlyTheFocusedControl() {
        // Issue 43: the wheel over the Adjustments dock moved every slider passing under the
        // pointer (40 notches: Lift G -0.17, dozens of undo steps). Unfocused, a slider and its
        // number box ignore the wheel; focused (a click or Tab), they take it.
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        auto* slider = w.findChild<QSlider*>(QStringLiteral("slider.exposure"));
        auto* spin = w.findChild<QDoubleSpinBox*>(QStringLiteral("spin.exposure"));
        QVERIFY(slider && spin);
        const auto wheel = [](QWidget* target) {
            const QPointF at(target->width() / 2.0, target->height() / 2.0);
            QWheelEvent e(at, target->mapToGlobal(at), QPoint(), QPoint(0, 120 * 4), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(target, &e);
        };
        w.setFocus();
        const int before = slider->value();
        const double spinBefore = spin->value();
        const int undo = w.document()->undoStack()->count();
        wheel(slider);
        wheel(spin);
        QCOMPARE(slider->value(), before);
        QCOMPARE(spin->value(), spinBefore);
        QCOMPARE(w.document()->undoStack()->count(), undo);
        QCOMPARE(slider->focusPolicy(), Qt::StrongFocus);
        slider->setFocus();
        if (slider->hasFocus()) { // a platform that gives focus (offscreen does)
            wheel(slider);
            QVERIFY(slider->value() != before);
        }
    }

    void dropOpensImageAndLut() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(samplePath("sample_grade.cube")),
                      QUrl::fromLocalFile(samplePath("sample_scene.exr"))});
        // As a drag manager does: enter (the window accepts files), then drop.
        QDragEnterEvent enter(QPoint(200, 200), Qt::CopyAction, &mime, Qt::LeftButton,
                              Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(200, 200), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QVERIFY2(drop.isAccepted(), qPrintable(w.lastError()));
        // The files are read on the worker: the drop returned before they arrived.
        QVERIFY(w.isLoading());
        w.waitForLoads();
        QCOMPARE(w.document()->lutPath(), samplePath("sample_grade.cube"));
        QCOMPARE(w.document()->imagePath(), samplePath("sample_scene.exr"));
        QCOMPARE(w.previewOptions().input, SceneKind::Scene); // EXR: linear scene values
        QCOMPARE(w.document()->effectiveLut().size(), 33);
    }

    void brightenToggleShowsWhatThePreviewDoes() {
        // Checked = the picture has the game's brighten step: the Smash target has one, which
        // can be switched off for inspection (nearest interpolation included); the window then
        // says the picture is not the export. Other targets have none.
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        QAction* brighten = w.windowActions()->brightenAction();
        QComboBox* target = w.windowActions()->targetBox();
        QComboBox* interp = w.windowActions()->interpolationBox();
        QVERIFY(brighten->isEnabled() && brighten->isChecked());
        auto* state = w.findChild<QLabel*>(QStringLiteral("exportState"));
        QVERIFY(state->text().startsWith(QStringLiteral("Shows the")));

        // As a user picks "nearest" in the toolbar and switches brighten off.
        interp->setFocus();
        while (interp->currentData().toInt() != int(Interpolation::Nearest))
            QTest::keyClick(interp, Qt::Key_Down);
        QCOMPARE(w.previewOptions().interpolation, Interpolation::Nearest);
        QVERIFY(brighten->isEnabled());
        brighten->trigger();
        QVERIFY(!brighten->isChecked());
        QVERIFY(!w.previewOptions().brighten);
        QVERIFY2(state->text().startsWith(QStringLiteral("Inspection view")),
                 qPrintable(state->text()));
        w.waitForPreview();
        const TargetLut exported = makeTargetLut(w.document()->lutSource(), ExportTarget::Smash);
        PipelineSettings s;
        s.interpolation = Interpolation::Nearest;
        s.bloom = false;
        s.lut = std::make_shared<const Lut3D>(smashWithoutBrighten(*exported.shown));
        Image scene = *w.document()->storedImage();
        preparePreviewFrame(planPreview(PreviewRequest{}), scene.view(), nullptr);
        QVERIFY(w.currentFrame()->image.pixels() == Pipeline(s).run(scene).pixels());

        // The cube target has no brighten step: disabled and unchecked, whatever the choice was.
        target->setFocus();
        while (target->currentData().toInt() != int(ExportTarget::Grading))
            QTest::keyClick(target, Qt::Key_Down);
        QCOMPARE(w.document()->target(), ExportTarget::Grading);
        QVERIFY(!brighten->isEnabled());
        QVERIFY(!brighten->isChecked());
        // Back to Smash: the choice (off) is kept.
        while (target->currentData().toInt() != int(ExportTarget::Smash))
            QTest::keyClick(target, Qt::Key_Up);
        QVERIFY(brighten->isEnabled());
        QVERIFY(!brighten->isChecked());
        // Options set from outside (the command line) show in the widgets.
        PreviewOptions o = w.previewOptions();
        o.brighten = true;
        o.input = SceneKind::Scene;
        o.bloom = false;
        w.setPreviewOptions(o);
        QVERIFY(brighten->isChecked());
        QVERIFY(w.windowActions()->bloomAction()->isEnabled());
        QVERIFY(!w.windowActions()->bloomAction()->isChecked());
        QCOMPARE(w.windowActions()->inputBox()->currentData().toInt(), int(SceneKind::Scene));
    }

    void exportDialogOffersEveryLayout() {
        ExportNameInput naming;
        naming.lutPath = QStringLiteral("/tmp/grade.cube");
        ExportDialog dlg(ExportTarget::Grading, naming);
        auto* format = dlg.findChild<QComboBox*>(QStringLiteral("format"));
        auto* path = dlg.findChild<QLineEdit*>(QStringLiteral("path"));
        auto* size = dlg.findChild<QSpinBox*>(QStringLiteral("size"));
        QVERIFY(format && path && size);
        // The target's own file first: a .cube as edited, exactly what the preview shows.
        QCOMPARE(dlg.choice().format, QStringLiteral("cube"));
        QVERIFY(dlg.matchesPreview());
        QStringList layouts, paths;
        for (int i = 0; i < format->count(); ++i) {
            format->setCurrentIndex(i);
            const ExportChoice c = dlg.choice();
            QVERIFY(path->text().endsWith(c.extension));
            QVERIFY(path->text() != naming.lutPath);
            QVERIFY2(!paths.contains(path->text()), qPrintable(path->text()));
            paths << path->text();
            if (!c.layout.isEmpty()) {
                layouts << c.layout;
                // strips at their natural size, 16^3 = 256x16; the 1024x32 names at 32^3 only
                const bool named = c.layout == "reshade" || c.layout == "unity-32";
                QCOMPARE(size->value(), named ? 32 : 16);
                QCOMPARE(size->isEnabled(), !named);
            }
            const auto layout = dlg.options().layout;
            QCOMPARE(layout ? QString::fromLatin1(toString(*layout)) : QString(), c.layout);
        }
        for (const char* l : {"unreal", "unity", "smush", "reshade", "unity-32"})
            QVERIFY2(layouts.contains(QLatin1String(l)), l);
        // For Smash the dialog starts on the game's file.
        ExportDialog smash(ExportTarget::Smash, naming);
        QCOMPARE(smash.choice().format, QStringLiteral("nutexb"));
        QCOMPARE(smash.path(), QStringLiteral("/tmp/color_grading_lut.nutexb"));
        QVERIFY(smash.matchesPreview());
        QVERIFY(smash.selectChoice(QStringLiteral("cube")));
        QVERIFY(!smash.matchesPreview());
    }

    void pixelReadoutShowsInputAndOutput() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.waitForPreview();
        PreviewView* v = w.previewView();
        v->zoomTo(1.0, QPointF(0, 0)); // image pixel (x, y) at widget (x, y) + offset
        const QSize img(320, 180);
        const QPoint origin(int(std::round((v->width() - img.width()) / 2.0)),
                            int(std::round((v->height() - img.height()) / 2.0)));
        QTest::mouseMove(v, origin + QPoint(100, 50));
        auto* label = w.findChild<QLabel*>(QStringLiteral("pixelReadout"));
        QVERIFY(label);
        const QString text = label->text();
        QVERIFY2(text.contains(QStringLiteral("x 100  y 50")), qPrintable(text));
        const float* in = w.document()->storedImage()->pixel(100, 50);
        const float* out = w.currentFrame()->image.pixel(100, 50);
        QVERIFY2(text.contains(QString::number(double(in[0]), 'f', 4)), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("out ") + QString::number(double(out[0]), 'f', 4)),
                 qPrintable(text));
    }

    void screenshotAt100PercentHoldsThePreviewPixels() {
        // What --screenshot grabs: at 100 % in "after" mode each preview pixel is one screen
        // pixel, so the grab contains the preview exactly.
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1000, 700);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.waitForPreview();
        PreviewView* v = w.previewView();
        v->setMode(PreviewView::Mode::After);
        v->zoomTo(1.0);
        const QImage grab = w.grab().toImage().convertToFormat(QImage::Format_RGBX8888);
        const QImage& want = w.currentFrame()->display;
        const QPoint origin =
            v->mapTo(&w, QPoint(int(std::round((v->width() - want.width()) / 2.0)),
                                int(std::round((v->height() - want.height()) / 2.0))));
        int mismatches = 0;
        for (int y = 0; y < want.height(); ++y)
            for (int x = 0; x < want.width(); ++x)
                mismatches +=
                    (grab.pixel(origin + QPoint(x, y)) & 0xffffff) != (want.pixel(x, y) & 0xffffff);
        QCOMPARE(mismatches, 0);
    }

    void badFilesKeepTheDocument() {
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.document()->editParam(AdjustParam::Saturation, 0.5);
        const QString title = w.windowTitle();
        const auto lutBefore = w.document()->effectiveLutShared();
        const QString missing = dir.filePath("nope.cube");
        QVERIFY(!w.openLutFile(missing));
        QVERIFY(w.lastError().contains(QStringLiteral("nope.cube")));
        QVERIFY(!w.openImageFile(dir.filePath("nope.png")));
        QCOMPARE(w.windowTitle(), title);
        QCOMPARE(w.document()->effectiveLutShared(), lutBefore);
        QCOMPARE(w.document()->param(AdjustParam::Saturation), 0.5);
        QVERIFY(w.isWindowModified());
        QCOMPARE(w.document()->imagePath(), samplePath("sample_scene.png"));
    }

    void sliderUndoAndExportMatchFloat64() {
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.waitForPreview();
        const auto before = w.currentFrame();

        QSlider* slider = w.adjustmentsPanel()->slider(AdjustParam::Exposure);
        const AdjustParamInfo& info = adjustParamInfo(AdjustParam::Exposure);
        const int target = paramToSlider(info, 1.25, AdjustmentsPanel::kSteps);
        dragSlider(slider, target);
        const double stops = sliderToParam(info, target, AdjustmentsPanel::kSteps);
        QVERIFY(std::abs(stops - 1.25) < 0.011);
        QCOMPARE(w.document()->param(AdjustParam::Exposure), stops);
        QCOMPARE(w.document()->undoStack()->count(), 1); // one drag, one undo step
        QVERIFY(w.isWindowModified());
        QCOMPARE(w.adjustmentsPanel()->spinBox(AdjustParam::Exposure)->value(),
                 std::round(stops * 100) / 100);

        w.waitForPreview();
        QVERIFY(w.currentFrame()->image.pixels() != before->image.pixels());

        const QString out = dir.filePath("edited.cube");
        QVERIFY(w.exportLut(out, QStringLiteral("cube"), {}, ExportTarget::Grading));
        const Lut3D base =
            formats::readLut(samplePath("sample_grade.cube").toStdString()).toLut3D();
        const Lut3D back = formats::readLut(out.toStdString()).toLut3D();
        QCOMPARE(back.size(), base.size());
        double worst = 0;
        for (std::size_t i = 0; i < base.entryCount(); ++i)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(double(back.entries()[i][c]) -
                                                 exposureRef(base.entries()[i][c], stops)));
        QVERIFY2(worst < 2e-5, qPrintable(QString::number(worst)));

        // Undo through the window's action: slider, spin box, document and title follow.
        QAction* undo = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->shortcut() == QKeySequence(QKeySequence::Undo))
                undo = a;
        QVERIFY(undo);
        undo->trigger();
        QCOMPARE(w.document()->param(AdjustParam::Exposure), 0.0);
        QCOMPARE(slider->value(), paramToSlider(info, 0.0, AdjustmentsPanel::kSteps));
        QCOMPARE(w.adjustmentsPanel()->spinBox(AdjustParam::Exposure)->value(), 0.0);
        QVERIFY(!w.isWindowModified());
        w.waitForPreview();
        QVERIFY(w.currentFrame()->image.pixels() == before->image.pixels());
    }

    void exportsEveryWritableFormat() {
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        w.document()->newNeutral(16);
        w.document()->editParam(AdjustParam::Contrast, 0.3);
        const QList<ExportChoice> choices = exportChoices();
        QVERIFY(!choices.isEmpty());
        int n = 0;
        for (const ExportChoice& c : choices) {
            const QString path = dir.filePath(QStringLiteral("x%1%2").arg(n++).arg(c.extension));
            FormatOptions o;
            o.layout = lut::parseOptionalLayout(c.layout.toStdString());
            QVERIFY2(w.exportLut(path, c.format, o, ExportTarget::Grading),
                     qPrintable(c.label + ": " + w.lastError()));
            QVERIFY2(QFileInfo(path).size() > 0, qPrintable(c.label));
        }
        // The Smash export is the game LUT for the edit, what the preview grades with.
        const QString path = dir.filePath("color_grading_lut.nutexb");
        QVERIFY(w.exportLut(path, QStringLiteral("nutexb"), {}, ExportTarget::Smash));
        const Lut3D back = formats::readLut(path.toStdString()).toLut3D();
        QCOMPARE(back.size(), 16);
        w.waitForPreview();
        QVERIFY(w.preview()->targetLut());
        QVERIFY(back.entries() == w.preview()->targetLut()->shown->entries());
        // An existing file is not replaced without consent (headless: refused).
        QVERIFY(!w.exportLut(path, QStringLiteral("nutexb"), {}, ExportTarget::Smash));
        QVERIFY(w.lastError().contains(QStringLiteral("not replaced")));
        QVERIFY(w.exportLut(path, QStringLiteral("nutexb"), {}, ExportTarget::Smash, true));
    }

    void closeAsksAndCancelKeepsTheWindow() {
        MainWindow w;
        w.show();
        w.document()->editParam(AdjustParam::Tint, 0.2);
        QVERIFY(w.isWindowModified());
        QString seen;
        QAbstractButton* defaultButton = nullptr;
        QAbstractButton* cancelButton = nullptr;
        auto answer = [&](const char* which) {
            QTimer::singleShot(0, [&, which] {
                for (QWidget* top : QApplication::topLevelWidgets())
                    if (auto* box = qobject_cast<QMessageBox*>(top); box && box->isVisible()) {
                        seen = box->text();
                        defaultButton = box->defaultButton();
                        cancelButton = box->button(QMessageBox::Cancel);
                        QAbstractButton* b = which ? box->findChild<QAbstractButton*>(which)
                                                   : box->button(QMessageBox::Cancel);
                        b->click();
                    }
            });
        };
        answer(nullptr);
        QVERIFY(!w.close());
        QVERIFY(seen.contains(QStringLiteral("unsaved")));
        // No default that loses anything: Enter means Cancel.
        QVERIFY(defaultButton && defaultButton == cancelButton);
        QVERIFY(w.isVisible());
        answer("discard");
        QVERIFY(w.close());
    }

    // Responsiveness on a 1920x1080 frame: logged, not asserted (timing depends on the machine).
    void sliderUpdateTimingOn1080p() {
        QTemporaryDir dir;
        Image img(1920, 1080);
        for (int y = 0; y < 1080; ++y)
            for (int x = 0; x < 1920; ++x) {
                float* p = img.pixel(x, y);
                p[0] = float(x) / 1919.0f;
                p[1] = float(y) / 1079.0f;
                p[2] = float((x ^ y) & 255) / 255.0f;
                p[3] = 1.0f;
            }
        const QString path = dir.filePath("frame1080.png");
        formats::writeImage(path.toStdString(), img, {});
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QElapsedTimer t;
        t.start();
        QVERIFY(w.openImageFile(path));
        const double openMs = t.nsecsElapsed() / 1e6; // waited for the worker's read
        w.waitForPreview();
        const double openToFullMs = t.nsecsElapsed() / 1e6;
        QSlider* slider = w.adjustmentsPanel()->slider(AdjustParam::Saturation);
        QList<double> full, proxy, fullLut, proxyLut, fullCpu, proxyCpu, firstFrame, proxyTarget,
            proxyScopes;
        double firstAt = -1;
        connect(w.preview(), &PreviewController::frameReady, this, [&] {
            if (firstAt < 0)
                firstAt = t.nsecsElapsed() / 1e6;
        });
        const double firstAllStages = w.currentFrame()->totalMilliseconds;
        for (int i = 0; i < 5; ++i) {
            t.restart();
            firstAt = -1;
            double cpu = processCpuMs();
            slider->setValue(slider->value() + 20); // a click step: proxy, then full resolution
            w.preview()->waitForIdle();
            full << t.nsecsElapsed() / 1e6;
            firstFrame << firstAt;
            fullCpu << processCpuMs() - cpu;
            fullLut << w.currentFrame()->milliseconds;
        }
        slider->setSliderDown(true); // dragging: proxy frames
        for (int i = 0; i < 5; ++i) {
            t.restart();
            double cpu = processCpuMs();
            slider->setValue(slider->value() + 20);
            w.preview()->waitForIdle();
            proxy << t.nsecsElapsed() / 1e6;
            proxyCpu << processCpuMs() - cpu;
            proxyLut << w.currentFrame()->milliseconds;
            proxyTarget << w.currentFrame()->targetMilliseconds;
            proxyScopes << w.currentFrame()->scopesMilliseconds;
        }
        slider->setSliderDown(false);
        w.waitForPreview();
        auto fmt = [](const QList<double>& l) {
            QStringList s;
            for (double v : l)
                s << QString::number(v, 'f', 1);
            return s.join(QStringLiteral(", "));
        };
        qInfo("1920x1080 open image: read %.1f ms (on the worker), full frame after %.1f ms",
              openMs, openToFullMs);
        qInfo("1920x1080 first frame (every stage + 8-bit conversion): %.1f ms", firstAllStages);
        qInfo("1920x1080 click step -> first (proxy) frame: %s ms", qPrintable(fmt(firstFrame)));
        qInfo("1920x1080 click step -> full-resolution frame: %s ms (its LUT stages %s)",
              qPrintable(fmt(full)), qPrintable(fmt(fullLut)));
        qInfo("1920x1080 slider -> frame on screen, drag proxy:      %s ms (LUT stages %s)",
              qPrintable(fmt(proxy)), qPrintable(fmt(proxyLut)));
        qInfo("drag proxy frames on the worker: export LUT %s ms, scopes %s ms",
              qPrintable(fmt(proxyTarget)), qPrintable(fmt(proxyScopes)));
        qInfo("CPU time per update (all threads), full: %s ms; proxy: %s ms; hardware threads %d",
              qPrintable(fmt(fullCpu)), qPrintable(fmt(proxyCpu)), QThread::idealThreadCount());
        QCOMPARE(w.currentFrame()->image.width(), 1920);
    }
};

QTEST_MAIN(EditorTest)
#include "test_editor.moc"
