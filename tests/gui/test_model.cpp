// The editor's document model without widgets: LUT + adjustments + undo + modified state,
// export, and the preview path. Expectations are float64 formulas written here.
#include "GuiTestSupport.h"

#include "Document.h"
#include "PreviewRenderer.h"
#include "RecentFiles.h"

#include "lut/Error.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/SmashCompensation.h"
#include "lut/roundtrip/Embed.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace lut;
using namespace lut::gui;
using lut::gui::test::exposureRef;
using lut::gui::test::maxDiff;
using lut::gui::test::samplePath;

class ModelTest : public QObject {
    Q_OBJECT
private slots:
    void newDocumentIsNeutralAndClean() {
        Document doc;
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.effectiveLut().size(), 33);
        QVERIFY(doc.effectiveLut().isIdentity());
        doc.newNeutral(16);
        QCOMPARE(doc.baseLut().size(), 16);
        QCOMPARE(doc.displayName(), QStringLiteral("Untitled"));
        QVERIFY_THROWS_EXCEPTION(lut::Error, doc.newNeutral(1));
        QCOMPARE(doc.baseLut().size(), 16); // unchanged by the failed call
    }

    void sliderGestureMergesIntoOneUndoStep() {
        Document doc;
        QSignalSpy modified(&doc, &Document::modifiedChanged);
        doc.editParam(AdjustParam::Exposure, 0.1);
        doc.editParam(AdjustParam::Exposure, 0.2);
        doc.editParam(AdjustParam::Exposure, 0.3);
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(doc.isModified());
        QCOMPARE(modified.count(), 1);
        doc.endGesture();
        doc.editParam(AdjustParam::Exposure, 0.5);
        doc.editParam(AdjustParam::Contrast, 0.25); // another parameter: its own step
        QCOMPARE(doc.undoStack()->count(), 3);
        doc.undoStack()->undo();
        QCOMPARE(doc.param(AdjustParam::Contrast), 0.0);
        doc.undoStack()->undo();
        QCOMPARE(doc.param(AdjustParam::Exposure), 0.3);
        doc.undoStack()->undo();
        QCOMPARE(doc.param(AdjustParam::Exposure), 0.0);
        QVERIFY(!doc.isModified()); // back at the clean state
        QVERIFY(doc.effectiveLut().isIdentity());
        doc.undoStack()->redo();
        QCOMPARE(doc.param(AdjustParam::Exposure), 0.3);
        QVERIFY(doc.isModified());
    }

    void dragBackToStartIsNoStep() {
        Document doc;
        doc.editParam(AdjustParam::Saturation, 1.5);
        doc.editParam(AdjustParam::Saturation, 1.0);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.isModified());
    }

    void resetIsUndoable() {
        Document doc;
        doc.editParam(AdjustParam::GainR, 1.2);
        doc.endGesture();
        doc.resetAdjustments();
        QVERIFY(doc.adjustments().isNeutral());
        doc.undoStack()->undo();
        QCOMPARE(doc.param(AdjustParam::GainR), 1.2);
    }

    void effectiveLutMatchesFloat64() {
        Document doc;
        doc.newNeutral(17);
        doc.editParam(AdjustParam::Exposure, 1.0);
        doc.endGesture();
        doc.editParam(AdjustParam::Contrast, 0.2);
        const Lut3D& eff = doc.effectiveLut();
        double worst = 0;
        for (int b = 0; b < 17; ++b)
            for (int g = 0; g < 17; ++g)
                for (int r = 0; r < 17; ++r) {
                    const int idx[3] = {r, g, b};
                    for (int c = 0; c < 3; ++c) {
                        const double e = idx[c] / 16.0;
                        const double want = (exposureRef(e, 1.0) - 0.5) * 1.2 + 0.5;
                        worst = std::max(worst, std::abs(double(eff.at(r, g, b)[c]) - want));
                    }
                }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
        // The base LUT is untouched.
        QVERIFY(doc.baseLut().isIdentity());
    }

    void exportCubeMatchesFloat64AndKeepsState() {
        QTemporaryDir dir;
        Document doc;
        doc.openLut(samplePath("sample_grade.cube"));
        const Lut3D base = doc.baseLut();
        doc.editParam(AdjustParam::Exposure, -0.75);
        const QString out = dir.filePath("out.cube");
        doc.exportLut(out);
        QVERIFY(doc.isModified()); // export is not save
        QCOMPARE(doc.lutPath(), samplePath("sample_grade.cube"));
        const Lut3D back = formats::readLut(out.toStdString()).toLut3D();
        QCOMPARE(back.size(), base.size());
        double worst = 0;
        for (std::size_t i = 0; i < base.entryCount(); ++i)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(double(back.entries()[i][c]) -
                                                 exposureRef(base.entries()[i][c], -0.75)));
        QVERIFY2(worst < 2e-5, qPrintable(QString::number(worst)));
    }

    void saveAsMakesCleanAndFailedOpenKeepsDocument() {
        QTemporaryDir dir;
        Document doc;
        doc.editParam(AdjustParam::Tint, 0.4);
        const QString path = dir.filePath("graded.cube");
        doc.saveAs(path);
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.lutPath(), path);
        QCOMPARE(doc.displayName(), QStringLiteral("graded.cube"));
        doc.editParam(AdjustParam::Tint, 0.5);
        QVERIFY(doc.isModified());

        const Lut3D before = doc.effectiveLut();
        const int undoCount = doc.undoStack()->count();
        QFile bad(dir.filePath("bad.cube"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("LUT_3D_SIZE 2\n0 0 0\nnot numbers\n");
        bad.close();
        QVERIFY_THROWS_EXCEPTION(lut::Error, doc.openLut(bad.fileName()));
        QVERIFY_THROWS_EXCEPTION(lut::Error, doc.openLut(dir.filePath("missing.cube")));
        QVERIFY_THROWS_EXCEPTION(lut::Error, doc.openImage(dir.filePath("missing.png")));
        QVERIFY_THROWS_EXCEPTION(lut::Error, doc.openImage(bad.fileName()));
        QCOMPARE(maxDiff(doc.effectiveLut(), before), 0.0);
        QCOMPARE(doc.undoStack()->count(), undoCount);
        QVERIFY(doc.isModified());
        QCOMPARE(doc.lutPath(), path);
        QVERIFY(!doc.hasImage());
    }

    void screenshotWithoutPatchIsRefused() {
        Document doc;
        doc.editParam(AdjustParam::Exposure, 0.5);
        QVERIFY_THROWS_EXCEPTION(lut::Error,
                                 doc.startFromScreenshot(samplePath("sample_scene.png")));
        QCOMPARE(doc.param(AdjustParam::Exposure), 0.5);
    }

    void startsFromAnEditedScreenshot() {
        // Embed a neutral patch, apply a global edit to the whole picture (stored values x 0.8,
        // channel-wise), save at 8 bits: the document's LUT must be that edit.
        QTemporaryDir dir;
        formats::LoadedImage shot =
            formats::readImage(samplePath("sample_scene.png").toStdString());
        Image big(640, 360, 0.25f);
        for (int y = 0; y < 180; ++y)
            for (int x = 0; x < 320; ++x)
                for (int c = 0; c < 4; ++c)
                    big.pixel(x, y)[c] = shot.image.pixel(x, y)[c];
        embedPatch(big.view(), EmbedOptions{});
        // RGB only: PNG colour is stored unassociated, so scaling alpha would cancel the edit.
        for (std::size_t i = 0; i < big.pixels().size(); ++i)
            if (i % 4 != 3)
                big.pixels()[i] *= 0.8f;
        const QString path = dir.filePath("edited.png");
        formats::writeImage(path.toStdString(), big, {});
        Document doc;
        doc.startFromScreenshot(path);
        QVERIFY(doc.isModified());
        QVERIFY(doc.lutOrigin().contains(QStringLiteral("edited.png")));
        const Lut3D& l = doc.effectiveLut();
        double worst = 0;
        for (int b = 0; b < l.size(); ++b)
            for (int g = 0; g < l.size(); ++g)
                for (int r = 0; r < l.size(); ++r) {
                    const glm::vec3 in = l.latticeInput(r, g, b);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(worst, std::abs(double(l.at(r, g, b)[c]) - 0.8 * in[c]));
                }
        const glm::vec3 top = l.at(l.size() - 1, l.size() - 1, l.size() - 1),
                        mid = l.at(l.size() / 2, 0, 0);
        QVERIFY2(worst < 1.5 / 255,
                 qPrintable(QStringLiteral("%1 steps; N %2, top %3 %4 %5, mid-r %6")
                                .arg(worst * 255)
                                .arg(l.size())
                                .arg(top.x)
                                .arg(top.y)
                                .arg(top.z)
                                .arg(mid.x)));
    }

    void startFromMemoryIsModified() {
        Document doc;
        Lut3D l = Lut3D::identity(9);
        doc.startFrom(l, QStringLiteral("test"));
        QVERIFY(doc.isModified());
        QCOMPARE(doc.baseLut().size(), 9);
    }

    void previewEqualsPipelineOnTheCliPath() {
        // The CLI's path written out: read the file, decode to the scene, run the preset.
        Document doc;
        doc.openImage(samplePath("sample_scene.png"));
        doc.openLut(samplePath("sample_grade.cube"));
        formats::LoadedImage loaded =
            formats::readImage(samplePath("sample_scene.png").toStdString());
        prepareSceneFrame(loaded.image.view(), false, false, nullptr);
        PipelineSettings s;
        s.preset = Preset::Smash;
        s.lut = std::make_shared<const Lut3D>(
            formats::readLut(samplePath("sample_grade.cube").toStdString()).toLut3D());
        Pipeline pipeline(s);
        const Image want = pipeline.run(loaded.image);

        PreviewOptions o;
        const PreviewResult got = renderPreview(*doc.sceneImage(), o, doc.effectiveLutShared());
        QCOMPARE(got.image.width(), want.width());
        QCOMPARE(got.image.height(), want.height());
        QVERIFY(got.image.pixels() == want.pixels());
        // And the LUT matters: the neutral preview differs.
        o.lutEnabled = false;
        QVERIFY(renderPreview(*doc.sceneImage(), o, doc.effectiveLutShared()).image.pixels() !=
                want.pixels());
    }

    void splitAtTheLutIsBitIdentical() {
        Document doc;
        doc.openImage(samplePath("sample_scene.exr"));
        doc.openLut(samplePath("sample_grade.cube"));
        doc.editParam(AdjustParam::Saturation, 1.3);
        for (Preset preset : {Preset::Smash, Preset::Pilot, Preset::None})
            for (bool bloom : {true, false}) {
                PreviewOptions o;
                o.preset = preset;
                o.bloom = bloom;
                const Image whole =
                    renderPreview(*doc.sceneImage(), o, doc.effectiveLutShared()).image;
                const Image before = renderBeforeLut(*doc.sceneImage(), o);
                const Image split = renderFromLut(before, o, doc.effectiveLutShared()).image;
                QVERIFY2(
                    whole.pixels() == split.pixels(),
                    qPrintable(QStringLiteral("%1 bloom %2").arg(toString(preset)).arg(bloom)));
            }
    }

    void brightenOffShowsTheLutAlone() {
        // Smash without bloom and brighten, neutral LUT: the grading pass is the identity
        // (up to the shader's 0.454545 * 2.2 != 1 and table pows), so the picture equals the
        // display-only preset.
        Document doc;
        doc.openImage(samplePath("sample_scene.exr"));
        PreviewOptions smash;
        smash.bloom = false;
        smash.brighten = false;
        smash.lutEnabled = false;
        PreviewOptions none;
        none.preset = Preset::None;
        const Image a = renderPreview(*doc.sceneImage(), smash, nullptr).image;
        const Image b = renderPreview(*doc.sceneImage(), none, nullptr).image;
        double worst = 0;
        for (std::size_t i = 0; i < a.pixels().size(); ++i)
            if (i % 4 != 3 && b.pixels()[i] < 1.0f) // values clipped by display are not compared
                worst = std::max(worst, std::abs(double(a.pixels()[i]) - double(b.pixels()[i])));
        QVERIFY2(worst < 2e-3, qPrintable(QString::number(worst)));
        smash.brighten = true;
        const Image c = renderPreview(*doc.sceneImage(), smash, nullptr).image;
        QVERIFY(c.pixel(160, 150)[1] > a.pixel(160, 150)[1] + 0.05f); // about 2x in linear light
        // Brighten off grades with smashWithoutBrighten(LUT): the same picture as the pipeline
        // run with that LUT directly.
        doc.openLut(samplePath("sample_grade.cube"));
        smash.brighten = false;
        smash.lutEnabled = true;
        PipelineSettings direct;
        direct.bloom = false;
        direct.lut = std::make_shared<const Lut3D>(smashWithoutBrighten(doc.effectiveLut()));
        QVERIFY(renderPreview(*doc.sceneImage(), smash, doc.effectiveLutShared()).image.pixels() ==
                Pipeline(direct).run(*doc.sceneImage()).pixels());
        // Only the smash preset has a brighten step; it is switchable for every interpolation.
        for (Interpolation m :
             {Interpolation::Trilinear, Interpolation::Tetrahedral, Interpolation::Nearest}) {
            smash.interpolation = m;
            QVERIFY(brightenSwitchable(smash));
        }
        QVERIFY(!brightenApplied(smash));
        none.brighten = true;
        QVERIFY(!brightenSwitchable(none));
        QVERIFY(!brightenApplied(none));
        // Brighten off with another preset changes nothing.
        none.brighten = false;
        QVERIFY(pipelineSettings(none, doc.effectiveLutShared()).lut == doc.effectiveLutShared());
    }

    void sliderMappingRoundTrips() {
        for (const AdjustParamInfo& p : adjustParams()) {
            const int pos = paramToSlider(p, p.defaultValue, 1000);
            QCOMPARE(sliderToParam(p, pos, 1000), p.defaultValue);
            QCOMPARE(sliderToParam(p, 0, 1000), p.min);
            QCOMPARE(sliderToParam(p, 1000, 1000), p.max);
            QVERIFY(sliderToParam(p, 300, 1000) < sliderToParam(p, 700, 1000));
            QCOMPARE(paramToSlider(p, std::nan(""), 1000), pos);
            Adjustments a;
            setParam(a, p.id, 0.125);
            QCOMPARE(getParam(a, p.id), 0.125);
        }
    }

    void recentFilesAreUniqueAndBounded() {
        QStringList l;
        for (int i = 0; i < 15; ++i)
            l = addRecentFile(l, QStringLiteral("/tmp/f%1.cube").arg(i), 10);
        QCOMPARE(l.size(), 10);
        QCOMPARE(l.first(), QStringLiteral("/tmp/f14.cube"));
        l = addRecentFile(l, QStringLiteral("/tmp/f10.cube"), 10);
        QCOMPARE(l.first(), QStringLiteral("/tmp/f10.cube"));
        QCOMPARE(l.count(QStringLiteral("/tmp/f10.cube")), 1);
    }

    void gameLutInvertsTheBrightenPass() {
        // Edited look: exposure +0.5 on a neutral 33^3. The shipped 16^3 entry at lattice input
        // s must be L = (E(s) / 1.3703 - s) / 0.99961 + s with E the edited colour (gamma space).
        Document doc;
        doc.editParam(AdjustParam::Exposure, 0.5);
        const Lut3D game = smashGameLut(doc.effectiveLut());
        QCOMPARE(game.size(), 16);
        double worst = 0;
        for (int b = 0; b < 16; ++b)
            for (int g = 0; g < 16; ++g)
                for (int r = 0; r < 16; ++r) {
                    const int idx[3] = {r, g, b};
                    for (int c = 0; c < 3; ++c) {
                        const double s = idx[c] / 15.0;
                        // E(s) by trilinear interpolation of the 33^3 edit = the exposure curve
                        // interpolated between lattice points i/32 (s = i/15 falls between them).
                        const double x = s * 32, lo = std::floor(x), f = x - lo;
                        const double e0 = exposureRef(lo / 32, 0.5),
                                     e1 = exposureRef(std::min(lo + 1, 32.0) / 32, 0.5);
                        const double e = e0 + (e1 - e0) * f;
                        const double want = (e / 1.3703 - s) / 0.99961 + s;
                        worst = std::max(worst, std::abs(double(game.at(r, g, b)[c]) - want));
                    }
                }
        QVERIFY2(worst < 1e-4, qPrintable(QString::number(worst)));
    }

    void classifiesDroppedFiles() {
        QVERIFY(looksLikeLutFile(samplePath("sample_grade.cube")));
        QVERIFY(!looksLikeLutFile(samplePath("sample_scene.png")));
        QVERIFY(!looksLikeLutFile(samplePath("sample_scene.exr")));
    }
};

QTEST_GUILESS_MAIN(ModelTest)
#include "test_model.moc"
