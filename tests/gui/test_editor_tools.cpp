// SPDX-License-Identifier: Apache-2.0
// Issue 15, problem 5: the grading tools driven with the mouse as a colourist would, each one
// undo step per gesture, checked against what the tool must do written out here: a curve passes
// through its points, hue curves leave greys alone, a colour wheel keeps luminance, strength
// mixes with the identity, Shift makes a slider ten times finer, the scopes count the frame's
// pixels, the clipping count and overlay mark what is out of range. Issue 16: the Tools menu's
// plot and comparison dialogs show the library's results for the target's export. Issue 25: the
// export dialog's Strength writes the float64 Oklab blend of tests/support/OklabReference.h.
#include "../support/OklabReference.h"
#include "GuiTestSupport.h"

#include "AdjustmentsPanel.h"
#include "ColorWheel.h"
#include "CompareDialog.h"
#include "CurveEditor.h"
#include "CurvesPanel.h"
#include "Document.h"
#include "ExportDialog.h"
#include "MainWindow.h"
#include "PlotDialog.h"
#include "PreviewController.h"
#include "PreviewView.h"
#include "ScopesView.h"
#include "WheelsPanel.h"
#include "WindowActions.h"

#include "lut/formats/Registry.h"

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QSlider>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::samplePath;

namespace {

void mouse(QWidget* w, QEvent::Type type, QPointF at, Qt::MouseButtons buttons,
           Qt::KeyboardModifiers mods = Qt::NoModifier) {
    QMouseEvent e(type, at, w->mapToGlobal(at), Qt::LeftButton, buttons, mods);
    QApplication::sendEvent(w, &e);
}

// Press at `from`, move to `to` in steps, release: one gesture.
void drag(QWidget* w, QPointF from, QPointF to, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    mouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, mods);
    for (int i = 1; i <= 6; ++i)
        mouse(w, QEvent::MouseMove, from + (to - from) * (i / 6.0), Qt::LeftButton, mods);
    mouse(w, QEvent::MouseButtonRelease, to, Qt::NoButton, mods);
}

void raiseDock(MainWindow& w, const char* name) {
    auto* dock = w.findChild<QDockWidget*>(QString::fromLatin1(name));
    dock->show();
    dock->raise();
    QApplication::processEvents();
}

QPointF sliderHandle(QSlider* s) {
    QStyleOptionSlider opt;
    opt.initFrom(s);
    opt.orientation = s->orientation();
    opt.minimum = s->minimum();
    opt.maximum = s->maximum();
    opt.sliderPosition = opt.sliderValue = s->value();
    return s->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, s).center();
}

} // namespace

class EditorToolsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void aCurvePointDraggedIsOneStepAndTheCurvePassesThroughIt() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        raiseDock(w, "dock.curves");
        CurveEditor* ed = w.curvesPanel()->editor();
        QCOMPARE(ed->curveId(), CurveId::Master);
        drag(ed, ed->toWidget({0.5, 0.5}), ed->toWidget({0.5, 0.7}));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        const auto& pts = w.document()->adjustments().curveMaster.points();
        QCOMPARE(int(pts.size()), 3);
        QCOMPARE(pts[1].x, ed->fromWidget(ed->toWidget({0.5, 0.5})).x);
        const double pixel = 1.0 / (ed->height() - 16);
        QVERIFY2(std::abs(pts[1].y - 0.7) < 1.5 * pixel, qPrintable(QString::number(pts[1].y)));
        // The 33^3 lattice has input 0.5 on a point: a grey there comes out at the point's y.
        const glm::vec3 mid = w.document()->effectiveLut().at(16, 16, 16);
        const double x = pts[1].x, y = pts[1].y;
        QCOMPARE(x, 0.5); // the press was at x = 0.5 exactly
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(mid[c] - y) < 1e-6, qPrintable(QString::number(mid[c])));
        // Black and white stay (end points), the curve is monotone along the greys.
        QVERIFY(std::abs(w.document()->effectiveLut().at(0, 0, 0).x) < 1e-6);
        QVERIFY(std::abs(w.document()->effectiveLut().at(32, 32, 32).x - 1.0f) < 1e-6);
        for (int i = 1; i < 33; ++i)
            QVERIFY(w.document()->effectiveLut().at(i, i, i).x >=
                    w.document()->effectiveLut().at(i - 1, i - 1, i - 1).x);
        // A double-click on the point removes it: one more step, back to the identity.
        QTest::mouseDClick(ed, Qt::LeftButton, {}, ed->toWidget(pts[1]).toPoint());
        QVERIFY(w.document()->adjustments().curveMaster.isNeutral());
        w.document()->undoStack()->undo();
        w.document()->undoStack()->undo();
        QVERIFY(w.document()->effectiveLut().isIdentity());
    }

    void hueCurvesChangeColoursAndLeaveGreysAlone() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        raiseDock(w, "dock.curves");
        w.findChild<QAbstractButton*>(
             QStringLiteral("curve.%1").arg(static_cast<int>(CurveId::HueVsSat)))
            ->click();
        CurveEditor* ed = w.curvesPanel()->editor();
        QCOMPARE(ed->curveId(), CurveId::HueVsSat);
        drag(ed, ed->toWidget({120.0, 0.0}), ed->toWidget({120.0, -0.8}));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QVERIFY(!w.document()->adjustments().hueVsSat.isNeutral());
        const Lut3D& base = w.document()->baseLut();
        const Lut3D& eff = w.document()->effectiveLut();
        int greys = 0, changed = 0;
        for (std::size_t i = 0; i < base.entryCount(); ++i) {
            const glm::vec3 b = base.entries()[i], e = eff.entries()[i];
            if (b.x == b.y && b.y == b.z) {
                ++greys;
                QCOMPARE(e, b); // no chroma, no hue: untouched
            } else if (std::abs(e.x - b.x) + std::abs(e.y - b.y) + std::abs(e.z - b.z) > 1e-3) {
                ++changed;
            }
        }
        QVERIFY(greys > 0);
        QVERIFY(changed > 1000);
    }

    void aColourWheelDragIsOneStepAndKeepsLuminance() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        raiseDock(w, "dock.wheels");
        ColorWheel* lift = w.wheelsPanel()->wheel(0);
        QCOMPARE(lift->range(), ColorWheel::Range::Lift);
        const QPointF centre = lift->toWidget(0.0, 0.0);
        // Towards hue 0 (red, to the right), half way out.
        drag(lift, centre + QPointF(2, 0), lift->toWidget(0.0, lift->maxAmount() / 2));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        const glm::dvec3 o = w.document()->adjustments().lift;
        QVERIFY2(o.x > 0.02 && o.y < 0 && o.z < 0,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(o.x).arg(o.y).arg(o.z)));
        QVERIFY(std::abs(0.2126 * o.x + 0.7152 * o.y + 0.0722 * o.z) < 1e-12);
        QVERIFY(std::abs(std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)}) -
                         lift->maxAmount() / 2) < 0.01);
        // The per-channel sliders show the same numbers.
        QCOMPARE(w.adjustmentsPanel()->spinBox(AdjustParam::LiftR)->value(),
                 std::round(o.x * 1000) / 1000);
        // Double-click: back to neutral, one more step.
        QTest::mouseDClick(lift, Qt::LeftButton, {}, centre.toPoint());
        QCOMPARE(w.document()->adjustments().lift, glm::dvec3(0.0));
        QCOMPARE(w.document()->undoStack()->count(), 2);
    }

    void strengthMixesTheGradeWithTheIdentity() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        QDoubleSpinBox* spin = w.adjustmentsPanel()->spinBox(AdjustParam::Strength);
        spin->setValue(0.5);
        QCOMPARE(w.document()->undoStack()->count(), 1);
        const Lut3D& base = w.document()->baseLut();
        const Lut3D& eff = w.document()->effectiveLut();
        double worst = 0;
        for (int b = 0; b < base.size(); ++b)
            for (int g = 0; g < base.size(); ++g)
                for (int r = 0; r < base.size(); ++r) {
                    const int idx[3] = {r, g, b};
                    for (int c = 0; c < 3; ++c) {
                        const double in = idx[c] / double(base.size() - 1);
                        const double want = 0.5 * in + 0.5 * base.at(r, g, b)[c];
                        worst = std::max(worst, std::abs(eff.at(r, g, b)[c] - want));
                    }
                }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
    }

    void shiftMakesASliderTenTimesFinerOnAUsefulScale() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        raiseDock(w, "dock.adjustments");
        QSlider* s = w.adjustmentsPanel()->slider(AdjustParam::Exposure);
        const AdjustParamInfo& info = adjustParamInfo(AdjustParam::Exposure);
        // Before: +-5 stops on ~113 pixels (0.088 stop per pixel); now the slider spans the dock
        // and +-3 stops.
        const double stopsPerPixel = (info.sliderMax - info.sliderMin) / s->width();
        QVERIFY2(s->width() >= 250, qPrintable(QString::number(s->width())));
        QVERIFY2(stopsPerPixel <= 0.025, qPrintable(QString::number(stopsPerPixel)));
        const QPointF at = sliderHandle(s);
        drag(s, at, at + QPointF(60, 0));
        const double normal = w.document()->param(AdjustParam::Exposure);
        QCOMPARE(w.document()->undoStack()->count(), 1);
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->param(AdjustParam::Exposure), 0.0);
        const QPointF again = sliderHandle(s);
        drag(s, again, again + QPointF(60, 0), Qt::ShiftModifier);
        const double fine = w.document()->param(AdjustParam::Exposure);
        QVERIFY2(normal > 0.5 && std::abs(fine - normal / 10) < 0.002,
                 qPrintable(QStringLiteral("normal %1, fine %2").arg(normal).arg(fine)));
        QCOMPARE(w.document()->undoStack()->count(), 1);
    }

    void scopesCountTheFrameAndFollowIt() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.waitForPreview();
        auto check = [&] {
            const QImage& d = w.currentFrame()->display;
            std::array<std::uint32_t, 256> red{};
            for (int y = 0; y < d.height(); ++y)
                for (int x = 0; x < d.width(); ++x)
                    ++red[qRed(d.pixel(x, y))];
            return red == w.scopesView()->scopes().histogram[0];
        };
        QVERIFY(check());
        const auto before = w.scopesView()->scopes().histogram[0];
        w.document()->editParam(AdjustParam::Exposure, -1.0);
        w.waitForPreview();
        QVERIFY(check());
        QVERIFY(w.scopesView()->scopes().histogram[0] != before);
        QCOMPARE(w.scopesView()->scopes().parade.height(), 256);
    }

    void clippingIsCountedLiveAndMarked() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        w.waitForPreview();
        QVERIFY2(w.clipText().contains(QStringLiteral("outside 0..1: 0 of 4096")),
                 qPrintable(w.clipText()));
        // Lift below 0: black wanted for inputs the game shows brighter, which its table reaches
        // only below 0 (above white it never leaves 1: the one rule above white, issue 40).
        w.document()->editParam(AdjustParam::LiftMaster, -0.2);
        w.waitForPreview();
        // The count is of the export's table (before the file clamps it), counted here.
        const Lut3D& table = w.preview()->targetLut()->table;
        int outside = 0;
        for (const glm::vec3& e : table.entries())
            outside += !(e.x >= 0 && e.x <= 1 && e.y >= 0 && e.y <= 1 && e.z >= 0 && e.z <= 1);
        QVERIFY(outside > 0);
        QVERIFY2(w.clipText().contains(QStringLiteral("outside 0..1: %1 of 4096").arg(outside)),
                 qPrintable(w.clipText()));
        // The overlay marks exactly the pixels with a channel at 255 (or at 0).
        const auto frame = w.currentFrame();
        int marked = 0, clipped = 0;
        for (int y = 0; y < frame->display.height(); ++y)
            for (int x = 0; x < frame->display.width(); ++x) {
                const QRgb p = frame->display.pixel(x, y);
                const bool c = qRed(p) == 255 || qGreen(p) == 255 || qBlue(p) == 255 ||
                               qRed(p) == 0 || qGreen(p) == 0 || qBlue(p) == 0;
                clipped += c;
                marked += qAlpha(frame->clipOverlay.pixel(x, y)) > 0;
                QCOMPARE(qAlpha(frame->clipOverlay.pixel(x, y)) > 0, c);
            }
        QVERIFY(clipped > 100);
        QCOMPARE(marked, clipped);
        w.windowActions()->clippingAction()->trigger();
        QVERIFY(w.previewView()->showsClipping());
    }

    void toolsMenuShowsThePlotAndTheComparison() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.document()->setTarget(ExportTarget::Grading);
        // The toolbar's target follows the document's (as after a script or --target).
        QCOMPARE(w.findChild<QComboBox*>("target")->currentData().toInt(),
                 int(ExportTarget::Grading));
        w.waitForPreview();

        // Plot: lut::plotLut of the export, shown.
        {
            PlotDialog dlg(&w, *w.document(), ExportTarget::Grading, w.fileActions());
            dlg.show();
            const Image expected = plotExportedLut(*w.document(), ExportTarget::Grading);
            QCOMPARE(dlg.plot().width(), expected.width());
            QVERIFY(dlg.plot().pixels() == expected.pixels());
            auto* picture = dlg.findChild<QLabel*>("plotPicture");
            QVERIFY(picture && !picture->pixmap().isNull());
        }
        // The menu entries open their dialogs (closed here as a user would).
        QAction* plot = w.findChild<QAction*>("plotLut");
        QVERIFY(plot);
        bool shown = false;
        QTimer::singleShot(50, [&] {
            if (auto* d = qobject_cast<PlotDialog*>(QApplication::activeModalWidget())) {
                shown = true;
                d->reject();
            }
        });
        plot->trigger();
        QVERIFY(shown);
        QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
        QVERIFY(w.findChild<QAction*>("compareLut"));

        // Compare with the opened file itself: over the image's colours, identical.
        Comparison c =
            compareWithFile(*w.document(), ExportTarget::Grading, samplePath("sample_grade.cube"));
        QCOMPARE(c.over, w.document()->imagePath());
        QCOMPARE(c.report.count, std::size_t(w.document()->storedImage()->width()) *
                                     std::size_t(w.document()->storedImage()->height()));
        QVERIFY(c.report.identical());
        QCOMPARE(c.heat.image.width(), w.document()->storedImage()->width());
        CompareDialog dlg(&w, c, w.fileActions());
        dlg.show();
        auto* report = dlg.findChild<QPlainTextEdit*>("compareReport");
        QVERIFY(report);
        QCOMPARE(report->toPlainText(), comparisonText(c));
        QVERIFY2(report->toPlainText().contains(QStringLiteral("identical")),
                 qPrintable(report->toPlainText()));
    }

    void exportAtStrengthIsTheOklabBlend() {
        // The export dialog's Strength (lutkit --luma-strength/--chroma-strength): the file holds
        // the float64 Oklab blend of each entry with its input (tests/support/OklabReference.h).
        QTemporaryDir dir;
        MainWindow w;
        w.setInteractiveErrors(false);
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        StrengthOptions s;
        s.luma = 0.25;
        s.chroma = 0.75;
        const QString out = dir.filePath("blend.cube");
        QVERIFY(w.exportLut(out, QStringLiteral("cube"), {}, ExportTarget::Grading, false, s));
        const Lut3D base =
            formats::readLut(samplePath("sample_grade.cube").toStdString()).toLut3D();
        const Lut3D back = formats::readLut(out.toStdString()).toLut3D();
        QCOMPARE(back.size(), base.size());
        double worst = 0;
        const int n = base.size();
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::dvec3 want =
                        lut::test::strengthBlend(glm::dvec3(base.latticeInput(r, g, b)),
                                                 glm::dvec3(base.at(r, g, b)), 0.25, 0.75);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(worst, std::abs(back.at(r, g, b)[c] - want[c]));
                }
        QVERIFY2(worst < 2e-6, qPrintable(QString::number(worst)));

        // The dialog: the amounts it returns, and it says the file is not what the preview shows.
        ExportDialog dlg(ExportTarget::Grading, {});
        QVERIFY(dlg.matchesPreview());
        dlg.setStrength(s);
        const StrengthAmounts a = strengthAmounts(dlg.strength());
        QCOMPARE(a.luma, 0.25);
        QCOMPARE(a.chroma, 0.75);
        QVERIFY(!dlg.matchesPreview());
        auto* note = dlg.findChild<QLabel*>(QStringLiteral("note"));
        QVERIFY(note && note->text().contains(QLatin1String("lightness 0.25")));
        auto* apart = dlg.findChild<QCheckBox*>(QStringLiteral("separate"));
        QVERIFY(apart && apart->isChecked());
        apart->setChecked(false);
        dlg.findChild<QDoubleSpinBox*>(QStringLiteral("strength"))->setValue(0.5);
        QCOMPARE(strengthAmounts(dlg.strength()).chroma, 0.5);

        // Smash at strength 0: the game's LUT for no edit, the neutral document's export.
        const QString zero = dir.filePath("zero.nutexb");
        StrengthOptions none;
        none.strength = 0;
        QVERIFY(w.exportLut(zero, QStringLiteral("nutexb"), {}, ExportTarget::Smash, false, none));
        MainWindow neutral;
        neutral.setInteractiveErrors(false);
        neutral.document()->newNeutral(33);
        const QString plain = dir.filePath("neutral.nutexb");
        QVERIFY(neutral.exportLut(plain, QStringLiteral("nutexb"), {}, ExportTarget::Smash));
        QFile fa(zero), fb(plain);
        QVERIFY(fa.open(QIODevice::ReadOnly) && fb.open(QIODevice::ReadOnly));
        QVERIFY(fa.readAll() == fb.readAll());
    }
};

QTEST_MAIN(EditorToolsTest)
#include "test_editor_tools.moc"
