// The preview controller without widgets (QT_QPA_PLATFORM=offscreen): what it renders, in which
// order, what it caches and drops. The expected pixels come from lut::Pipeline run directly on
// the scene (the `lutkit preview` path), not from the controller's own helpers.
#include "PreviewController.h"

#include "lut/Downscale.h"
#include "lut/Quantize.h"
#include "lut/pipeline/Pipeline.h"

#include <QSignalSpy>
#include <QtTest>

using namespace lut;
using namespace lut::gui;

Q_DECLARE_METATYPE(std::shared_ptr<const lut::gui::PreviewFrame>)

namespace {

// A linear HDR scene with highlights for the bloom, w wide (the proxy factor follows w).
std::shared_ptr<const Image> makeScene(int w, int h, float tint) {
    auto img = std::make_shared<Image>(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img->pixel(x, y);
            p[0] = tint * float(x) / float(w);
            p[1] = float(y) / float(h);
            p[2] = ((x / 16 + y / 16) % 5 == 0) ? 4.0f : 0.2f;
            p[3] = 1.0f;
        }
    return img;
}

std::shared_ptr<const Lut3D> makeLut(float warm) {
    Lut3D l = Lut3D::identity(17);
    for (std::size_t i = 0; i < l.entryCount(); ++i) {
        glm::vec3& e = l.entries()[i];
        e = glm::vec3(std::min(1.0f, e.x * warm), e.y * e.y, 1.0f - 0.5f * (1.0f - e.z));
    }
    return std::make_shared<const Lut3D>(std::move(l));
}

// The independent path: the pipeline with the same settings, whole.
Image pipelineRun(const Image& scene, const std::shared_ptr<const Lut3D>& lut, Preset preset,
                  bool bloom, Interpolation m = Interpolation::Trilinear) {
    PipelineSettings s;
    s.preset = preset;
    s.lut = lut;
    s.bloom = bloom;
    s.interpolation = m;
    return Pipeline(s).run(scene);
}

struct FrameLog {
    QList<std::shared_ptr<const PreviewFrame>> frames;
    explicit FrameLog(PreviewController& c) {
        QObject::connect(&c, &PreviewController::frameReady,
                         [this](std::shared_ptr<const PreviewFrame> f) { frames << f; });
    }
};

} // namespace

class PreviewControllerTest : public QObject {
    Q_OBJECT
private slots:
    void newSceneGivesBeforeThenProxyThenFullFrame() {
        PreviewController c;
        const auto lut = makeLut(1.2f);
        c.setLut(lut);
        const auto scene = makeScene(2500, 120, 1.0f); // proxy 1/3
        QSignalSpy sceneChanged(&c, &PreviewController::sceneChanged);
        QSignalSpy before(&c, &PreviewController::beforeReady);
        FrameLog log(c);
        c.setScene(scene);
        QCOMPARE(sceneChanged.count(), 1);
        // Nothing was rendered on this thread: the before picture comes from the worker.
        QVERIFY(c.beforeImage().isNull());
        QVERIFY(c.isBusy());
        c.waitForIdle();
        QCOMPARE(before.count(), 1);
        QCOMPARE(c.proxyFactor(), 3);

        // Before: the scene with the sRGB display encoding only (the `none` preset), 8-bit.
        const Image none = Pipeline(Preset::None).run(*scene);
        const QImage& b = c.beforeImage();
        QCOMPARE(b.size(), QSize(2500, 120));
        int mismatches = 0;
        for (int y = 0; y < 120; y += 7)
            for (int x = 0; x < 2500; x += 13)
                mismatches += qGreen(b.pixel(x, y)) != toUnorm8(none.pixel(x, y)[1]);
        QCOMPARE(mismatches, 0);

        // The proxy frame first, then the full frame, both the pipeline's pixels.
        QCOMPARE(log.frames.size(), 2);
        const auto& proxy = log.frames[0];
        const auto& full = log.frames[1];
        QCOMPARE(proxy->proxyFactor, 3);
        QCOMPARE(proxy->image.width(), 834); // ceil(2500 / 3)
        QVERIFY(proxy->image.pixels() ==
                pipelineRun(downscale(*scene, 3), lut, Preset::Smash, true).pixels());
        QCOMPARE(full->proxyFactor, 1);
        QVERIFY(full->image.pixels() == pipelineRun(*scene, lut, Preset::Smash, true).pixels());
        QCOMPARE(c.currentFrame(), full);
        QVERIFY(c.isCurrent(*full));
        QCOMPARE(c.fullResolutionTimes().size(), 1);
    }

    void lutEditsReuseTheStagesBeforeTheLut() {
        PreviewController c;
        const auto scene = makeScene(900, 90, 1.0f); // no proxy
        c.setScene(scene);
        c.waitForFullResolution();
        QVERIFY(!c.currentFrame()->reusedBeforeLut);
        FrameLog log(c);

        const auto lut = makeLut(0.8f);
        c.setLut(lut);
        c.waitForIdle();
        QCOMPARE(log.frames.size(), 1);
        QVERIFY(log.frames.last()->reusedBeforeLut);
        QVERIFY(log.frames.last()->image.pixels() ==
                pipelineRun(*scene, lut, Preset::Smash, true).pixels());

        // Interpolation and brighten are LUT-part settings: still cached.
        PreviewOptions o = c.options();
        o.interpolation = Interpolation::Tetrahedral;
        c.setOptions(o);
        c.waitForIdle();
        QVERIFY(log.frames.last()->reusedBeforeLut);
        QVERIFY(log.frames.last()->image.pixels() ==
                pipelineRun(*scene, lut, Preset::Smash, true, Interpolation::Tetrahedral).pixels());

        // Bloom is before the LUT: the cache no longer applies.
        o.bloom = false;
        c.setOptions(o);
        c.waitForIdle();
        QVERIFY(!log.frames.last()->reusedBeforeLut);
        QVERIFY(
            log.frames.last()->image.pixels() ==
            pipelineRun(*scene, lut, Preset::Smash, false, Interpolation::Tetrahedral).pixels());
    }

    void whileInteractiveOnlyProxiesThenTheFullFrame() {
        PreviewController c;
        c.setScene(makeScene(2100, 60, 1.0f)); // proxy 1/3
        c.waitForFullResolution();
        FrameLog log(c);
        c.setInteractive(true);
        for (float warm : {1.1f, 1.2f, 1.3f}) {
            c.setLut(makeLut(warm));
            c.waitForIdle();
        }
        QVERIFY(!log.frames.isEmpty());
        for (const auto& f : log.frames)
            QCOMPARE(f->proxyFactor, 3);
        QVERIFY(c.isCurrent(*log.frames.last()));
        const int proxies = int(log.frames.size());
        c.setInteractive(false); // released: the full frame of the last state
        c.waitForIdle();
        QCOMPARE(int(log.frames.size()), proxies + 1);
        QCOMPARE(log.frames.last()->proxyFactor, 1);
        QVERIFY(c.isCurrent(*log.frames.last()));
    }

    void framesOfAReplacedSceneAreDropped() {
        PreviewController c;
        const auto a = makeScene(1500, 80, 0.3f);
        const auto b = makeScene(1500, 80, 1.0f);
        QSignalSpy before(&c, &PreviewController::beforeReady);
        FrameLog log(c);
        c.setScene(a);
        c.setScene(b); // before the worker delivered anything for a
        c.waitForIdle();
        QCOMPARE(before.count(), 1);
        QCOMPARE(c.scene(), b);
        for (const auto& f : log.frames)
            QVERIFY(f->scene == b || f->scene == c.proxyScene());
        QVERIFY(c.currentFrame());
        QVERIFY(c.currentFrame()->image.pixels() ==
                pipelineRun(*b, nullptr, Preset::Smash, true).pixels());
        c.setScene(nullptr);
        QVERIFY(!c.currentFrame());
        QVERIFY(c.beforeImage().isNull());
    }

    void fullResolutionImageWithOrWithoutAFrame() {
        const auto scene = makeScene(1200, 50, 1.0f);
        const auto lut = makeLut(1.3f);
        PreviewOptions o;
        o.preset = Preset::Pilot;
        const Image want = pipelineRun(*scene, lut, Preset::Pilot, true);
        PreviewController c;
        c.setOptions(o);
        c.setLut(lut);
        c.setScene(scene);
        QVERIFY(c.renderFullResolution().pixels() == want.pixels()); // no frame yet: rendered
        c.waitForFullResolution();
        QVERIFY(c.currentFrame()->image.pixels() == want.pixels());
        QVERIFY(c.renderFullResolution().pixels() == want.pixels()); // the current frame
        QVERIFY(PreviewController().renderFullResolution().empty());
    }

    void optionsChangeOnlyWhenTheyDiffer() {
        PreviewController c;
        QSignalSpy changed(&c, &PreviewController::optionsChanged);
        c.setOptions(c.options());
        QCOMPARE(changed.count(), 0);
        PreviewOptions o = c.options();
        o.brighten = false;
        c.setOptions(o);
        QCOMPARE(changed.count(), 1);
        QVERIFY(!c.options().brighten);
        QVERIFY(!c.isBusy()); // no scene: nothing to render
    }
};

QTEST_GUILESS_MAIN(PreviewControllerTest)
#include "test_preview_controller.moc"
