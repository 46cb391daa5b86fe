// SPDX-License-Identifier: Apache-2.0
// The preview controller without widgets (QT_QPA_PLATFORM=offscreen): what it renders, in which
// order, what it caches and drops. The expected pixels come from lut::Pipeline run directly on
// the scene (the `lutkit preview` path) with the LUT the export writes, read back from a real
// file, not from the controller's own helpers.
#include "PreviewController.h"

#include "lut/Downscale.h"
#include "lut/Quantize.h"
#include "lut/formats/Registry.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/smash/SmashAuthoring.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace lut;
using namespace lut::gui;

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

LutSource source(std::shared_ptr<const Lut3D> lut) {
    LutSource s;
    s.effective = std::move(lut);
    return s;
}

// Grading target (.cube: the file holds the LUT exactly; the document's) on a linear scene with
// the filmic chain: the pipeline's pilot preset with the LUT itself.
void gradingFilmic(PreviewController& c, Document& doc) {
    doc.setTarget(ExportTarget::Grading);
    c.setDocument(&doc);
    PreviewOptions o;
    o.input = SceneKind::Scene;
    o.preset = Preset::Pilot;
    c.setOptions(o);
}

// The independent path: the pipeline with the same settings, whole.
Image pipelineRun(const Image& scene, const std::shared_ptr<const Lut3D>& lut, Preset preset,
                  bool bloom, Interpolation m = Interpolation::Trilinear) {
    PipelineSettings s;
    s.preset = preset;
    s.lut = lut ? lut : std::make_shared<const Lut3D>(Lut3D::identity(33));
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
        Document doc;
        PreviewController c;
        gradingFilmic(c, doc);
        const auto lut = makeLut(1.2f);
        c.setSource(source(lut));
        c.waitForIdle();
        const auto scene = makeScene(2500, 120, 1.0f); // proxy 1/3
        QSignalSpy imageChanged(&c, &PreviewController::imageChanged);
        QSignalSpy before(&c, &PreviewController::beforeReady);
        FrameLog log(c);
        c.setImage(scene, true);
        QCOMPARE(imageChanged.count(), 1);
        // Nothing was rendered on this thread: the before picture comes from the worker.
        QVERIFY(c.beforeImage().isNull());
        QVERIFY(c.isBusy());
        c.waitForIdle();
        // A first look's proxy-sized before picture may come first (PreviewController.h), then
        // the full one.
        QVERIFY(before.count() >= 1 && before.count() <= 2);
        QCOMPARE(c.proxyFactor(), 3);

        // Before: the scene through the same chain with the neutral LUT, 8-bit.
        const Image neutral = pipelineRun(*scene, nullptr, Preset::Pilot, true);
        const QImage& b = c.beforeImage();
        QCOMPARE(b.size(), QSize(2500, 120));
        int mismatches = 0;
        for (int y = 0; y < 120; y += 7)
            for (int x = 0; x < 2500; x += 13)
                mismatches += qGreen(b.pixel(x, y)) != toUnorm8(neutral.pixel(x, y)[1]);
        QCOMPARE(mismatches, 0);

        // The proxy frame first, then the full frame, both the pipeline's pixels.
        QCOMPARE(log.frames.size(), 2);
        const auto& proxy = log.frames[0];
        const auto& full = log.frames[1];
        QCOMPARE(proxy->proxyFactor, 3);
        QCOMPARE(proxy->image.width(), 834); // ceil(2500 / 3)
        QVERIFY(proxy->image.pixels() ==
                pipelineRun(downscale(*scene, 3), lut, Preset::Pilot, true).pixels());
        QCOMPARE(full->proxyFactor, 1);
        QVERIFY(full->image.pixels() == pipelineRun(*scene, lut, Preset::Pilot, true).pixels());
        QCOMPARE(c.currentFrame(), full);
        QVERIFY(c.isCurrent(*full));
        QCOMPARE(c.fullResolutionTimes().size(), 1);
        // The scopes come with the frame: every pixel counted once per channel.
        std::uint64_t total = 0;
        for (auto n : full->scopes.histogram[1])
            total += n;
        QCOMPARE(total, std::uint64_t(2500) * 120);
    }

    void smashPreviewGradesWithTheWrittenFile() {
        // The Smash target: the frame is the game's chain run with the nutexb the export writes,
        // read back from a file written here.
        QTemporaryDir dir;
        PreviewController c;
        PreviewOptions o;
        o.input = SceneKind::Scene;
        c.setOptions(o);
        const auto edit = makeLut(1.1f);
        c.setSource(source(edit));
        const auto scene = makeScene(400, 60, 1.0f);
        c.setImage(scene, true);
        c.waitForFullResolution();
        LutFile file;
        file.cube = authorSmashLutForEdit(*edit, Interpolation::Tetrahedral,
                                          SmashAuthoringOptions{.measure = false})
                        .exact;
        const std::string path = dir.filePath("color_grading_lut.nutexb").toStdString();
        formats::writeLut(path, file);
        const auto written = std::make_shared<const Lut3D>(formats::readLut(path).toLut3D());
        QVERIFY(c.targetLut());
        QCOMPARE(c.targetLut()->shown->size(), 16);
        QVERIFY(c.targetLut()->shown->entries() == written->entries());
        QVERIFY(c.currentFrame()->image.pixels() ==
                pipelineRun(*scene, written, Preset::Smash, true).pixels());
    }

    void lutEditsReuseTheStagesBeforeTheLut() {
        Document doc;
        PreviewController c;
        gradingFilmic(c, doc);
        const auto scene = makeScene(900, 90, 1.0f); // no proxy
        c.setImage(scene, true);
        c.waitForFullResolution();
        QVERIFY(!c.currentFrame()->reusedBeforeLut);
        FrameLog log(c);

        const auto lut = makeLut(0.8f);
        c.setSource(source(lut));
        c.waitForIdle();
        QCOMPARE(log.frames.size(), 1);
        QVERIFY(log.frames.last()->reusedBeforeLut);
        QVERIFY(log.frames.last()->image.pixels() ==
                pipelineRun(*scene, lut, Preset::Pilot, true).pixels());

        // Interpolation is a LUT-part setting: still cached.
        PreviewOptions o = c.options();
        o.interpolation = Interpolation::Tetrahedral;
        c.setOptions(o);
        c.waitForIdle();
        QVERIFY(log.frames.last()->reusedBeforeLut);
        QVERIFY(log.frames.last()->image.pixels() ==
                pipelineRun(*scene, lut, Preset::Pilot, true, Interpolation::Tetrahedral).pixels());

        // Bloom is before the LUT: the cache no longer applies.
        o.bloom = false;
        c.setOptions(o);
        c.waitForIdle();
        QVERIFY(!log.frames.last()->reusedBeforeLut);
        QVERIFY(
            log.frames.last()->image.pixels() ==
            pipelineRun(*scene, lut, Preset::Pilot, false, Interpolation::Tetrahedral).pixels());
    }

    void whileInteractiveOnlyProxiesThenTheFullFrame() {
        Document doc;
        PreviewController c;
        gradingFilmic(c, doc);
        c.setImage(makeScene(2100, 60, 1.0f), true); // proxy 1/3
        c.waitForFullResolution();
        FrameLog log(c);
        c.setInteractive(true);
        for (float warm : {1.1f, 1.2f, 1.3f}) {
            c.setSource(source(makeLut(warm)));
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

    void framesOfAReplacedImageAreDropped() {
        Document doc;
        PreviewController c;
        gradingFilmic(c, doc);
        const auto a = makeScene(1500, 80, 0.3f);
        const auto b = makeScene(1500, 80, 1.0f);
        QSignalSpy before(&c, &PreviewController::beforeReady);
        FrameLog log(c);
        c.setImage(a, true);
        c.setImage(b, true); // before the worker delivered anything for a
        c.waitForIdle();
        QVERIFY(before.count() >= 1 && before.count() <= 2); // b's first look, b's picture
        QCOMPARE(c.beforeImage().size(), QSize(1500, 80));
        QCOMPARE(c.storedImage(), b);
        for (const auto& f : log.frames)
            QVERIFY(f->scene == c.scene() || f->scene == c.proxyScene());
        QVERIFY(c.currentFrame());
        QVERIFY(c.currentFrame()->image.pixels() ==
                pipelineRun(*b, nullptr, Preset::Pilot, true).pixels());
        c.setImage(nullptr, false);
        QVERIFY(!c.currentFrame());
        QVERIFY(c.beforeImage().isNull());
    }

    void changingThePictureKindPreparesTheSceneAgain() {
        // An 8-bit picture is a screenshot: the Smash chain ungrades it and adds no bloom; the
        // same pixels as a scene are decoded and bloomed. Before = the screenshot as stored.
        PreviewController c;
        auto stored = std::make_shared<Image>(300, 40);
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 300; ++x) {
                float* p = stored->pixel(x, y);
                p[0] = std::round(255.0f * x / 299) / 255;
                p[1] = std::round(255.0f * y / 39) / 255;
                p[2] = 0.5f;
                p[3] = 1.0f;
            }
        c.setImage(stored, false);
        c.waitForFullResolution();
        QCOMPARE(c.options().input, SceneKind::Screenshot);
        int differ = 0;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 300; ++x)
                differ += c.beforeImage().pixel(x, y) != c.currentFrame()->display.pixel(x, y);
        QCOMPARE(differ, 0); // neutral document: no difference across the divider
        Image ungraded = *stored;
        preparePreviewFrame(planPreview(PreviewRequest{}), ungraded.view(), nullptr);
        QVERIFY(c.currentFrame()->image.pixels() ==
                pipelineRun(ungraded, std::make_shared<const Lut3D>(Lut3D::identity(16)),
                            Preset::Smash, false)
                    .pixels());
        PreviewOptions o = c.options();
        o.input = SceneKind::Scene;
        c.setOptions(o);
        c.waitForFullResolution();
        Image decoded = *stored;
        PreviewRequest asScene;
        asScene.forced = SceneKind::Scene;
        preparePreviewFrame(planPreview(asScene), decoded.view(), nullptr);
        QVERIFY(c.currentFrame()->image.pixels() ==
                pipelineRun(decoded, std::make_shared<const Lut3D>(Lut3D::identity(16)),
                            Preset::Smash, true)
                    .pixels());
    }

    void documentTargetChangeRerendersWithThatTargetsExport() {
        // The target is the document's (issue 26): setting it re-renders the preview with that
        // target's export, the frame a controller whose document had the target from the start
        // gives, and the pipeline's pixels with the LUT the .cube export holds exactly.
        const auto scene = makeScene(400, 60, 1.0f); // no proxy
        const auto lut = makeLut(1.2f);
        PreviewOptions o;
        o.input = SceneKind::Scene;
        o.preset = Preset::Pilot; // the engine chain, used by the Grading target only
        // A controller over `d` showing the scene at full resolution.
        auto show = [&](PreviewController& pc, const Document& d) {
            pc.setDocument(&d);
            pc.setOptions(o);
            pc.setSource(source(lut));
            pc.setImage(scene, true);
            pc.waitForFullResolution();
        };
        Document doc;
        QCOMPARE(doc.target(), ExportTarget::Smash); // the default
        PreviewController c;
        show(c, doc);
        const auto smashFrame = c.currentFrame();
        QCOMPARE(smashFrame->target, ExportTarget::Smash);

        QSignalSpy changed(&doc, &Document::targetChanged);
        FrameLog log(c);
        doc.setTarget(ExportTarget::Grading);
        QCOMPARE(changed.count(), 1);
        doc.setTarget(ExportTarget::Grading); // the same value: no signal
        QCOMPARE(changed.count(), 1);
        QCOMPARE(c.target(), ExportTarget::Grading);
        QVERIFY(!c.isCurrent(*smashFrame));
        c.waitForIdle(); // no request from here: the controller re-rendered on the signal
        QVERIFY(!log.frames.isEmpty());
        const auto gradingFrame = c.currentFrame();
        QVERIFY(c.isCurrent(*gradingFrame));
        QCOMPARE(gradingFrame->target, ExportTarget::Grading);
        QCOMPARE(gradingFrame->proxyFactor, 1);
        const Image want = pipelineRun(*scene, lut, Preset::Pilot, true);
        QVERIFY(gradingFrame->image.pixels() == want.pixels());
        QVERIFY(smashFrame->image.pixels() != want.pixels()); // the target matters here
        // The before picture follows the target's chain too (the neutral LUT through it).
        const Image neutral = pipelineRun(*scene, nullptr, Preset::Pilot, true);
        QCOMPARE(qGreen(c.beforeImage().pixel(200, 30)), int(toUnorm8(neutral.pixel(200, 30)[1])));

        Document fromStart;
        fromStart.setTarget(ExportTarget::Grading);
        PreviewController d;
        show(d, fromStart);
        QVERIFY(d.currentFrame()->image.pixels() == gradingFrame->image.pixels());
        QVERIFY(d.targetLut() && c.targetLut());
        QVERIFY(d.targetLut()->shown->entries() == c.targetLut()->shown->entries());

        // Back to Smash: the first frame's pixels again, bit for bit.
        doc.setTarget(ExportTarget::Smash);
        QCOMPARE(changed.count(), 2);
        c.waitForIdle();
        QVERIFY(c.isCurrent(*c.currentFrame()));
        QVERIFY(c.currentFrame()->image.pixels() == smashFrame->image.pixels());
    }

    void documentTargetIsAChoiceNotAnEdit() {
        // Not an undo step, not a modification, and kept when another LUT is opened.
        Document doc;
        doc.setTarget(ExportTarget::Engine);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.isModified());
        doc.newNeutral(17);
        QCOMPARE(doc.target(), ExportTarget::Engine);
        LutFile file;
        file.cube = Lut3D::identity(5);
        doc.adoptLut(file, QStringLiteral("other.cube"));
        QCOMPARE(doc.target(), ExportTarget::Engine);
        QCOMPARE(PreviewController().target(), ExportTarget::Smash); // no document
    }

    void fullResolutionImageWithOrWithoutAFrame() {
        const auto scene = makeScene(1200, 50, 1.0f);
        const auto lut = makeLut(1.3f);
        const Image want = pipelineRun(*scene, lut, Preset::Pilot, true);
        Document doc;
        PreviewController c;
        gradingFilmic(c, doc);
        c.setSource(source(lut));
        c.setImage(scene, true);
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
    }
};

QTEST_GUILESS_MAIN(PreviewControllerTest)
#include "test_preview_controller.moc"
