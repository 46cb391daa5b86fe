// SPDX-License-Identifier: Apache-2.0
// Issue 28, the colourist's tools: hue curves with local influence (a point changes only the hues
// near it; six hue-range presets; the active curve visible) and the luma waveform and vectorscope.
// The oracles are written here from the definitions: the Fritsch-Carlson curve through a point
// and its neutral anchors 60 degrees either side is the Hermite blend 3t^2 - 2t^3 between them,
// the saturation by hue is Y + (1 + s)(e - Y) with Rec. 709 luma (lut/ops/Adjust.h), the hue
// shift turns the HSV hue keeping max and min; the waveform and vectorscope counts are computed
// from the preview frame's 8-bit pixels with the Rec. 709 formulas of gui/model/Scopes.h.
#include "GuiTestSupport.h"

#include "CurveEditor.h"
#include "CurvesPanel.h"
#include "Document.h"
#include "MainWindow.h"
#include "PreviewController.h"
#include "ScopesView.h"

#include <QAbstractButton>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QStandardPaths>
#include <QUndoStack>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::samplePath;

namespace {

void mouse(QWidget* w, QEvent::Type type, QPointF at, Qt::MouseButtons buttons) {
    QMouseEvent e(type, at, w->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

void drag(QWidget* w, QPointF from, QPointF to) {
    mouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton);
    for (int i = 1; i <= 6; ++i)
        mouse(w, QEvent::MouseMove, from + (to - from) * (i / 6.0), Qt::LeftButton);
    mouse(w, QEvent::MouseButtonRelease, to, Qt::NoButton);
}

void raiseDock(MainWindow& w, const char* name) {
    auto* dock = w.findChild<QDockWidget*>(QString::fromLatin1(name));
    dock->show();
    dock->raise();
    QApplication::processEvents();
}

// The influence of a point at hue c with value y, anchored at c +- 60 (the editor's rule): the
// Hermite curve with zero tangents at the three points (an extremum and two flat ends).
double localCurve(double hue, double c, double y) {
    double d = std::fmod(hue - c + 540.0, 360.0) - 180.0; // -180..180
    d = std::abs(d);
    if (d >= 60.0)
        return 0.0;
    const double t = 1.0 - d / 60.0;
    return y * (3 * t * t - 2 * t * t * t);
}

double hsvHue(glm::dvec3 e) {
    const double mx = std::max({e.x, e.y, e.z}), mn = std::min({e.x, e.y, e.z}), c = mx - mn;
    double h = mx == e.x ? (e.y - e.z) / c : mx == e.y ? (e.z - e.x) / c + 2 : (e.x - e.y) / c + 4;
    h *= 60;
    return h < 0 ? h + 360 : h;
}

// Saturation by hue on an encoded colour (Adjust.h): luma kept.
glm::dvec3 saturated(glm::dvec3 e, double s) {
    const double y = 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
    return glm::dvec3(y) + std::max(0.0, 1.0 + s) * (e - glm::dvec3(y));
}

// The mean colour of a widget's pixels inside `r`.
QColor meanColour(QWidget* w, QRect r) {
    const QImage img = w->grab(r).toImage();
    double sum[3] = {};
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QRgb p = img.pixel(x, y);
            sum[0] += qRed(p);
            sum[1] += qGreen(p);
            sum[2] += qBlue(p);
        }
    const double n = std::max(1, img.width() * img.height());
    return QColor(int(sum[0] / n), int(sum[1] / n), int(sum[2] / n));
}

} // namespace

class EditorScopesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void onePointOnHueVsSatMovesOnlyTheHuesNearIt() {
        // The issue: one point on Hue vs Sat at yellow, dragged down, dropped red too.
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        raiseDock(w, "dock.curves");
        w.curvesPanel()->curveButton(CurveId::HueVsSat)->click();
        CurveEditor* ed = w.curvesPanel()->editor();
        QCOMPARE(ed->curveId(), CurveId::HueVsSat);
        drag(ed, ed->toWidget({60.0, 0.0}), ed->toWidget({60.0, -0.5}));
        QCOMPARE(w.document()->undoStack()->count(), 1); // point and anchors: one step
        const Curve& curve = w.document()->adjustments().hueVsSat;
        // The point where it was clicked and its hue range's neutral anchors.
        const auto pts = curve.points();
        QCOMPARE(int(pts.size()), 3);
        auto near = [](double a, double b) {
            return std::abs(std::remainder(a - b, 360.0)) < 1e-6;
        };
        // Sorted by hue; which one is first depends on the click's last bits (0 may be 359.99...).
        glm::dvec2 point(0.0);
        int anchorsAt0 = 0, anchorsAt120 = 0;
        for (const glm::dvec2& q : pts) {
            if (q.y != 0.0)
                point = q;
            else
                (near(q.x, 0.0) ? anchorsAt0 : anchorsAt120) += near(q.x, 0.0) || near(q.x, 120.0);
        }
        QCOMPARE(anchorsAt0, 1);
        QCOMPARE(anchorsAt120, 1);
        const double x = point.x, y = point.y;
        QVERIFY2(near(x, 60.0), qPrintable(QString::number(x, 'g', 17)));
        QVERIFY2(y < -0.4, qPrintable(QString::number(y)));
        // The effective 33^3 LUT at lattice colours, against the formulas written here.
        const Lut3D& lut = w.document()->effectiveLut();
        struct Probe {
            int r, g, b;
        };
        const Probe probes[] = {{32, 0, 0},  {32, 32, 0}, {0, 32, 0},   {32, 16, 0},
                                {16, 32, 0}, {0, 32, 32}, {0, 0, 32},   {32, 0, 32},
                                {32, 8, 0},  {24, 32, 8}, {16, 16, 16}, {32, 24, 16}};
        for (const Probe& p : probes) {
            const glm::dvec3 in(p.r / 32.0, p.g / 32.0, p.b / 32.0);
            const double mx = std::max({in.x, in.y, in.z}), mn = std::min({in.x, in.y, in.z});
            glm::dvec3 want = in;
            if (mx > mn) {
                // Exact at the anchors and the point; between them the Hermite blend.
                const double t = hsvHue(in);
                want = saturated(in, localCurve(t, x, y));
            }
            const glm::vec3 got = lut.at(p.r, p.g, p.b);
            for (int c = 0; c < 3; ++c)
                QVERIFY2(std::abs(got[c] - want[c]) < 2e-3,
                         qPrintable(QStringLiteral("%1 %2 %3 channel %4: %5, want %6")
                                        .arg(p.r)
                                        .arg(p.g)
                                        .arg(p.b)
                                        .arg(c)
                                        .arg(got[c])
                                        .arg(want[c])));
        }
        // Pure red, green, cyan, blue and magenta: exactly as they were.
        for (const Probe& p : {Probe{32, 0, 0}, Probe{0, 32, 0}, Probe{0, 32, 32}, Probe{0, 0, 32},
                               Probe{32, 0, 32}})
            QCOMPARE(lut.at(p.r, p.g, p.b), Lut3D::identity(33).at(p.r, p.g, p.b));
    }

    void theSixHueRangesSelectAndSetTheirPoint() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.show();
        raiseDock(w, "dock.curves");
        CurvesPanel* panel = w.curvesPanel();
        panel->curveButton(CurveId::HueVsHue)->click();
        QDoubleSpinBox* amount = panel->amountBox();
        QVERIFY(amount->isVisible());
        QVERIFY(!amount->isEnabled()); // nothing selected yet
        panel->rangeButton("yellows")->click();
        QVERIFY(amount->isEnabled());
        amount->setValue(20.0); // yellows 20 degrees towards green
        panel->rangeButton("reds")->click();
        amount->setValue(-10.0);                         // reds 10 degrees towards magenta
        QCOMPARE(w.document()->undoStack()->count(), 4); // two points added, two values set
        const auto pts = w.document()->adjustments().hueVsHue.points();
        // Yellows: 0 (its anchor, then the reds' point), 60, 120; the reds added 300.
        QCOMPARE(int(pts.size()), 4);
        QCOMPARE(pts[0], glm::dvec2(0.0, -10.0));
        QCOMPARE(pts[1], glm::dvec2(60.0, 20.0));
        QCOMPARE(pts[2], glm::dvec2(120.0, 0.0));
        QCOMPARE(pts[3], glm::dvec2(300.0, 0.0));
        const Lut3D& lut = w.document()->effectiveLut();
        // Pure yellow turned to hue 80 (max 1, min 0 kept): (2/3, 1, 0); red to hue 350.
        const glm::vec3 yellow = lut.at(32, 32, 0), red = lut.at(32, 0, 0);
        QVERIFY(std::abs(yellow.x - 2.0f / 3.0f) < 1e-5 && std::abs(yellow.y - 1.0f) < 1e-6 &&
                std::abs(yellow.z) < 1e-6);
        QVERIFY(std::abs(red.x - 1.0f) < 1e-6 && std::abs(red.y) < 1e-6 &&
                std::abs(red.z - 1.0f / 6.0f) < 1e-5);
        // Green, cyan, blue: untouched.
        for (const glm::ivec3 p :
             {glm::ivec3(0, 32, 0), glm::ivec3(0, 32, 32), glm::ivec3(0, 0, 32)})
            QCOMPARE(lut.at(p.x, p.y, p.z), Lut3D::identity(33).at(p.x, p.y, p.z));
        // The selected point is the reds' one, shown in Amount.
        QCOMPARE(amount->value(), -10.0);
    }

    void theActiveCurveIsLitAndNamed() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1480, 920);
        w.show();
        raiseDock(w, "dock.curves");
        CurvesPanel* panel = w.curvesPanel();
        for (CurveId id : {CurveId::Master, CurveId::Green, CurveId::HueVsSat}) {
            panel->curveButton(id)->click();
            QApplication::processEvents();
            for (CurveId other : {CurveId::Master, CurveId::Red, CurveId::Green, CurveId::Blue,
                                  CurveId::HueVsHue, CurveId::HueVsSat, CurveId::HueVsLum}) {
                QPushButton* b = panel->curveButton(other);
                const QColor c = meanColour(b, b->rect().adjusted(3, 3, -3, -3));
                // The chosen one in the highlight blue, the others grey.
                const int blueness = c.blue() - c.red();
                if (other == id)
                    QVERIFY2(blueness > 60,
                             qPrintable(QStringLiteral("%1: %2").arg(int(other)).arg(blueness)));
                else
                    QVERIFY2(blueness < 20,
                             qPrintable(QStringLiteral("%1: %2").arg(int(other)).arg(blueness)));
            }
            // The editor names the curve in its top left corner (light text on the dark plot).
            CurveEditor* ed = panel->editor();
            const QImage img = ed->grab(QRect(12, 10, 70, 14)).toImage();
            int bright = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x)
                    bright += qGray(img.pixel(x, y)) > 110;
            QVERIFY2(bright > 15, qPrintable(QString::number(bright)));
        }
    }

    void waveformAndVectorscopeCountThePreviewPixels() {
        MainWindow w;
        w.setInteractiveErrors(false);
        w.resize(1480, 920);
        w.show();
        QVERIFY(w.openImageFile(samplePath("sample_scene.png")));
        QVERIFY(w.openLutFile(samplePath("sample_grade.cube")));
        w.waitForPreview();
        const auto frame = w.currentFrame();
        QVERIFY(frame && frame->proxyFactor == 1);
        const QImage& d = frame->display;
        const Scopes& s = w.scopesView()->scopes();
        QCOMPARE(s.pixels, std::uint64_t(d.width()) * d.height());
        // The waveform: per column (x * 256 / width), the luma level in 16-bit fixed point; the
        // vectorscope: Cb, Cr in 16-bit fixed point (Scopes.h), each within a level or a cell of
        // the float64 Rec. 709 definition.
        const int cols = 256, n = 256;
        std::vector<std::uint32_t> wave(std::size_t(cols) * 256, 0), vec(std::size_t(n) * n, 0);
        int farLevels = 0, farCells = 0;
        for (int y = 0; y < d.height(); ++y) {
            const uchar* p = d.constScanLine(y);
            for (int x = 0; x < d.width(); ++x, p += 4) {
                const int r = p[0], g = p[1], b = p[2];
                const int level = (13933 * r + 46871 * g + 4732 * b + 32768) >> 16;
                ++wave[std::size_t(x) * cols / d.width() * 256 + std::size_t(level)];
                const int u = -7509 * r - 25259 * g + 32768 * b;
                const int v = 32768 * r - 29763 * g - 3005 * b;
                const int col = std::min(n - 1, (u + 8355840) / 65280);
                const int row = n - 1 - std::min(n - 1, (v + 8355840) / 65280);
                ++vec[std::size_t(row) * n + std::size_t(col)];
                // The same in float64 from the Rec. 709 definitions.
                const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
                farLevels += std::abs(level - luma) > 0.5 + 1e-3;
                const double yp = luma / 255, cb = (b / 255.0 - yp) / 1.8556,
                             cr = (r / 255.0 - yp) / 1.5748;
                const int fcol = std::clamp(int(std::floor((cb + 0.5) * n)), 0, n - 1);
                const int frow = n - 1 - std::clamp(int(std::floor((cr + 0.5) * n)), 0, n - 1);
                farCells += std::abs(fcol - col) > 1 || std::abs(frow - row) > 1;
            }
        }
        QCOMPARE(farLevels, 0);
        QCOMPARE(farCells, 0);
        QCOMPARE(s.columns, cols);
        QVERIFY(s.waveform == wave);
        QVERIFY(s.vectorscope == vec);
        QCOMPARE(s.waveformImage.size(), QSize(cols, 256));
        QCOMPARE(s.vectorscopeImage.size(), QSize(n, n));
        // Both are on screen by default, and the skin-tone line is drawn at 123 degrees.
        raiseDock(w, "dock.scopes");
        ScopesView* view = w.scopesView();
        QVERIFY(view->isShown(ScopesView::Kind::Waveform));
        QVERIFY(view->isShown(ScopesView::Kind::Vectorscope));
        QVERIFY(!view->scopeRect(ScopesView::Kind::Vectorscope).isEmpty());
        const QImage shot = view->grab().toImage();
        const double a = kSkinToneDegrees * std::numbers::pi / 180;
        int skin = 0;
        for (double t = 0.2; t < 0.45; t += 0.05) {
            const QPoint at = view->vectorscopePoint(t * std::cos(a), t * std::sin(a)).toPoint();
            bool found = false;
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dx = -1; dx <= 1 && !found; ++dx) {
                    const QRgb c = shot.pixel(at + QPoint(dx, dy));
                    found = qRed(c) > 200 && qGreen(c) > 150 && qBlue(c) > 100 && qBlue(c) < 200;
                }
            skin += found;
        }
        QVERIFY2(skin >= 4, qPrintable(QString::number(skin)));
    }
};

QTEST_MAIN(EditorScopesTest)
#include "test_editor_scopes.moc"
