// SPDX-License-Identifier: Apache-2.0
// Issue 23 in the editor: Tools > Match to Reference… on the sample scene, the reference being
// the scene graded by a formula written here and shuffled. The preview takes the matched LUT
// while the sliders move (strength 0: the neutral LUT; 1: near the true grade), Cancel gives the
// document's LUT back, OK makes the match the document's LUT (exported like every other edit).
#include "GuiTestSupport.h"
#include "TestPaths.h"

#include "Document.h"
#include "MainWindow.h"
#include "MatchDialog.h"
#include "MatchSession.h"
#include "PreviewController.h"

#include "lut/formats/ImageIO.h"
#include "lut/interp/Sampler.h"

#include <QAction>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSlider>
#include <QStandardPaths>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::samplePath;

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
        auto* buttons = again.findChild<QDialogButtonBox*>();
        QVERIFY(buttons);
        buttons->button(QDialogButtonBox::Ok)->click();
        QVERIFY(stepsToGrade(w.document()->baseLut(), scene) < 1.5);
        QVERIFY(w.document()->lutOrigin().contains("matched to"));
        QVERIFY2(w.lastError().isEmpty(), qPrintable(w.lastError()));
    }
};

QTEST_MAIN(EditorMatchTest)
#include "test_editor_match.moc"
