// SPDX-License-Identifier: Apache-2.0
// The editor's document model without widgets: LUT + adjustments + undo + modified state,
// export, and the preview path. Expectations are float64 formulas written here.
#include "GuiTestSupport.h"

#include "Document.h"
#include "ExportTarget.h"
#include "PreviewRenderer.h"

#include "lut/Error.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/ops/AdjustmentList.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/roundtrip/Embed.h"
#include "lut/smash/SmashAuthoring.h"
#include "lut/smash/SmashCompensation.h"

#include <glm/common.hpp>

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
        doc.exportLut(out, {}, {}, ExportTarget::Grading);
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
        // The CLI's path written out for the default target (Smash) on an 8-bit screenshot: the
        // export written to a file, read back; the picture read, decoded and ungraded (lutkit
        // preview --from-screenshot); the smash preset without bloom.
        QTemporaryDir dir;
        Document doc;
        doc.openImage(samplePath("sample_scene.png"));
        doc.openLut(samplePath("sample_grade.cube"));
        const QString nutexb = dir.filePath("color_grading_lut.nutexb");
        doc.exportLut(nutexb, {}, {}, ExportTarget::Smash);
        formats::LoadedImage loaded =
            formats::readImage(samplePath("sample_scene.png").toStdString());
        preparePreviewFrame(planPreview(PreviewRequest{}), loaded.image.view(), nullptr);
        PipelineSettings s;
        s.preset = Preset::Smash;
        s.bloom = false;
        s.lut = std::make_shared<const Lut3D>(formats::readLut(nutexb.toStdString()).toLut3D());
        const Image want = Pipeline(s).run(loaded.image);

        PreviewOptions o; // the defaults: a screenshot; and the document's target: Smash
        const Image scene = prepareScene(*doc.storedImage(), false, o, doc.target());
        const TargetLut target = makeTargetLut(doc.lutSource(), doc.target());
        const PreviewResult got = renderPreview(scene, o, doc.target(), target.shown);
        QCOMPARE(got.image.width(), want.width());
        QCOMPARE(got.image.height(), want.height());
        QVERIFY(got.image.pixels() == want.pixels());
        // And the LUT matters: the neutral document's preview differs.
        const auto neutral = makeTargetLut(LutSource{}, doc.target()).shown;
        QVERIFY(renderPreview(scene, o, doc.target(), neutral).image.pixels() != want.pixels());
    }

    void everyTargetPreviewsTheFileItWrites() {
        // For each target the LUT the preview grades with is the default export, written to a
        // file with the target's format and settings and read back.
        QTemporaryDir dir;
        Document doc;
        doc.openLut(samplePath("sample_grade.cube"));
        doc.editParam(AdjustParam::Saturation, 1.4);
        for (const ExportTargetInfo& t : exportTargets()) {
            const TargetLut target = makeTargetLut(doc.lutSource(), t.id);
            const QString path = dir.filePath(QString::fromStdString("x" + t.extension));
            doc.exportLut(path, QString::fromStdString(t.format), targetFormatOptions(t.id), t.id);
            const Lut3D back =
                formats::readLut(path.toStdString(), targetFormatOptions(t.id), t.format).toLut3D();
            QVERIFY2(back.size() == target.shown->size() &&
                         back.entries() == target.shown->entries(),
                     t.key.c_str());
            QCOMPARE(target.clip, countOutOfRange(target.table));
        }
        // Smash: 16^3; the engine strip: 16^3 (256x16) from the 33^3 grade; the cube: as edited.
        QCOMPARE(makeTargetLut(doc.lutSource(), ExportTarget::Smash).shown->size(), 16);
        QCOMPARE(makeTargetLut(doc.lutSource(), ExportTarget::Engine).shown->size(), 16);
        QCOMPARE(makeTargetLut(doc.lutSource(), ExportTarget::Grading).shown->size(), 33);
    }

    void thePreviewOfEveryTargetWritesNoFile() {
        // Each adjustment makes and reads back the target's bytes in memory: no temporary folder.
        Document doc;
        doc.openLut(samplePath("sample_grade.cube"));
        QTemporaryDir dir;
        const QByteArray old =
            qEnvironmentVariableIsSet("TMPDIR") ? qgetenv("TMPDIR") : QByteArray();
        qputenv("TMPDIR", dir.filePath("no-such-folder").toUtf8());
        std::string error;
        try {
            for (const ExportTargetInfo& t : exportTargets())
                (void)makeTargetLut(doc.lutSource(), t.id);
        } catch (const std::exception& e) {
            error = e.what();
        }
        old.isNull() ? qunsetenv("TMPDIR") : qputenv("TMPDIR", old);
        QVERIFY2(error.empty(), error.c_str());
    }

    void aGameLutOpensAsWhatTheGameShows() {
        // A .nutexb is what the game applies: opened and exported for Smash unchanged, it is the
        // same file; an edit applies to the picture the game shows with it.
        QTemporaryDir dir;
        Lut3D game = Lut3D::identity(16);
        for (std::size_t i = 0; i < game.entryCount(); ++i)
            game.entries()[i] =
                glm::round(glm::vec3(game.entries()[i].x * 0.9f, game.entries()[i].y,
                                     0.2f + 0.8f * game.entries()[i].z) *
                           255.0f) /
                255.0f;
        const QString path = dir.filePath("color_grading_lut.nutexb");
        LutFile f;
        f.cube = game;
        formats::writeLut(path.toStdString(), f);
        Document doc;
        doc.openLut(path);
        QCOMPARE(doc.lutPurpose(), LutPurpose::Smash); // a .nutexb is the game's LUT
        const TargetLut same = makeTargetLut(doc.lutSource(), ExportTarget::Smash);
        QCOMPARE(maxDiff(*same.shown, game), 0.0);
        doc.editParam(AdjustParam::Exposure, 0.3);
        const Lut3D want =
            authorSmashLutForEdit(applyAdjustments(Lut3D::identity(33), doc.adjustments()),
                                  Interpolation::Tetrahedral,
                                  SmashAuthoringOptions{.gameLut = &game, .measure = false})
                .exact;
        QCOMPARE(maxDiff(exportTable(doc.lutSource(), ExportTarget::Smash), want), 0.0);
    }

    void splitAtTheLutIsBitIdentical() {
        Document doc;
        doc.openImage(samplePath("sample_scene.exr"));
        doc.openLut(samplePath("sample_grade.cube"));
        doc.editParam(AdjustParam::Saturation, 1.3);
        const auto lut = doc.effectiveLutShared();
        for (ExportTarget target : {ExportTarget::Smash, ExportTarget::Grading})
            for (Preset preset : {Preset::Pilot, Preset::Lecture, Preset::None})
                for (SceneKind input : {SceneKind::Screenshot, SceneKind::Scene})
                    for (bool bloom : {true, false}) {
                        PreviewOptions o;
                        o.preset = preset;
                        o.input = input;
                        o.bloom = bloom;
                        const Image scene = prepareScene(*doc.storedImage(), true, o, target);
                        const Image whole = renderPreview(scene, o, target, lut).image;
                        const Image before = renderBeforeLut(scene, o, target);
                        const Image split = renderFromLut(before, o, target, lut).image;
                        QVERIFY2(whole.pixels() == split.pixels(),
                                 qPrintable(QStringLiteral("%1 %2 bloom %3")
                                                .arg(toString(effectivePreset(o, target)))
                                                .arg(toString(input))
                                                .arg(bloom)));
                    }
    }

    void brightenOffShowsTheLutAlone() {
        // Smash without bloom and brighten, neutral LUT: the grading pass is the identity
        // (up to the shader's 0.454545 * 2.2 != 1 and table pows), so the picture equals the
        // display-only chain.
        Document doc;
        doc.openImage(samplePath("sample_scene.exr"));
        constexpr ExportTarget kSmash = ExportTarget::Smash, kGrading = ExportTarget::Grading;
        PreviewOptions smash; // for the Smash target
        smash.input = SceneKind::Scene;
        smash.bloom = false;
        smash.brighten = false;
        smash.lutEnabled = false;
        PreviewOptions none = smash; // for the Grading target
        none.preset = Preset::None;
        const Image smashScene = prepareScene(*doc.storedImage(), true, smash, kSmash);
        const Image a = renderPreview(smashScene, smash, kSmash, nullptr).image;
        const Image b = Pipeline(Preset::None).run(*doc.storedImage());
        double worst = 0;
        for (std::size_t i = 0; i < a.pixels().size(); ++i)
            if (i % 4 != 3 && b.pixels()[i] < 1.0f) // values clipped by display are not compared
                worst = std::max(worst, std::abs(double(a.pixels()[i]) - double(b.pixels()[i])));
        QVERIFY2(worst < 2e-3, qPrintable(QString::number(worst)));
        QVERIFY(!showsTheExport(smash, kSmash)); // an inspection view, and the window says so
        smash.brighten = true;
        const Image c = renderPreview(smashScene, smash, kSmash, nullptr).image;
        QVERIFY(c.pixel(160, 150)[1] > a.pixel(160, 150)[1] + 0.05f); // about 2x in linear light
        // Brighten off grades with smashWithoutBrighten(LUT): the same picture as the pipeline
        // run with that LUT directly.
        doc.openLut(samplePath("sample_grade.cube"));
        smash.brighten = false;
        smash.lutEnabled = true;
        PipelineSettings direct;
        direct.bloom = false;
        direct.lut = std::make_shared<const Lut3D>(smashWithoutBrighten(doc.effectiveLut()));
        QVERIFY(renderPreview(smashScene, smash, kSmash, doc.effectiveLutShared()).image.pixels() ==
                Pipeline(direct).run(smashScene).pixels());
        // Only the game chain has a brighten step; it is switchable for every interpolation.
        for (Interpolation m :
             {Interpolation::Trilinear, Interpolation::Tetrahedral, Interpolation::Nearest}) {
            smash.interpolation = m;
            QVERIFY(brightenSwitchable(smash, kSmash));
        }
        QVERIFY(!brightenApplied(smash, kSmash));
        none.brighten = true;
        QVERIFY(!brightenSwitchable(none, kGrading));
        QVERIFY(!brightenApplied(none, kGrading));
        // Brighten off with another chain changes nothing.
        none.brighten = false;
        QVERIFY(pipelineSettings(none, kGrading, doc.effectiveLutShared()).lut ==
                doc.effectiveLutShared());
        none.lutEnabled = true;
        QVERIFY(showsTheExport(none, kGrading));
    }

    void sliderMappingRoundTrips() {
        for (const AdjustParamInfo& p : adjustParams()) {
            const int pos = paramToSlider(p, p.defaultValue, 1000);
            QCOMPARE(sliderToParam(p, pos, 1000), p.defaultValue);
            QCOMPARE(sliderToParam(p, 0, 1000), p.sliderMin);
            QCOMPARE(sliderToParam(p, 1000, 1000), p.sliderMax);
            QVERIFY(p.min <= p.sliderMin && p.sliderMax <= p.max);
            QVERIFY(sliderToParam(p, 300, 1000) < sliderToParam(p, 700, 1000));
            QCOMPARE(paramToSlider(p, std::nan(""), 1000), pos);
            Adjustments a;
            setParam(a, p.id, 0.125);
            QCOMPARE(getParam(a, p.id), 0.125);
        }
    }

    void adjustmentListIsWhatLutkitApplies() {
        // File > Save Adjustments writes the list lutlib parses; applied to the base it gives
        // the document's LUT bit for bit; loading it back is one undo step.
        QTemporaryDir dir;
        Document doc;
        doc.openLut(samplePath("sample_grade.cube"));
        doc.editParam(AdjustParam::Exposure, 0.25);
        doc.endGesture();
        doc.editCurve(CurveId::Master, Curve(CurveKind::Tone, {{0, 0}, {0.3, 0.25}, {1, 1}}));
        doc.endGesture();
        doc.editCurve(CurveId::HueVsSat, Curve(CurveKind::Hue, {{120, -0.4}, {240, 0.2}}));
        doc.endGesture();
        doc.editParam(AdjustParam::Strength, 0.8);
        doc.endGesture();
        const QString path = dir.filePath("adjust.txt");
        doc.saveAdjustmentList(path);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        const Adjustments parsed = parseAdjustmentList(text.toStdString(), "adjust.txt");
        QVERIFY(parsed == doc.adjustments());
        QCOMPARE(maxDiff(applyAdjustments(doc.baseLut(), parsed), doc.effectiveLut()), 0.0);

        Document other;
        other.openLut(samplePath("sample_grade.cube"));
        other.loadAdjustmentList(path);
        QCOMPARE(other.undoStack()->count(), 1);
        QCOMPARE(maxDiff(other.effectiveLut(), doc.effectiveLut()), 0.0);
        other.undoStack()->undo();
        QVERIFY(other.adjustments() == Adjustments{});
    }

    void curveAndWheelDragsAreOneUndoStepEach() {
        Document doc;
        for (double y : {0.3, 0.35, 0.4})
            doc.editCurve(CurveId::Red, Curve(CurveKind::Tone, {{0, 0}, {0.5, y}, {1, 1}}));
        doc.endGesture();
        QCOMPARE(doc.undoStack()->count(), 1);
        Adjustments a = doc.adjustments();
        for (double amount : {0.02, 0.04, 0.06}) {
            a.lift = colorWheelOffset(30.0, amount);
            doc.editAdjustments(a, 200, QStringLiteral("Move lift wheel"));
        }
        doc.endGesture();
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        QCOMPARE(doc.adjustments().lift, glm::dvec3(0.0));
        QCOMPARE(doc.adjustments().curveRed.points()[1].y, 0.4);
        doc.undoStack()->undo();
        QVERIFY(doc.adjustments().isNeutral());
    }
};

QTEST_GUILESS_MAIN(ModelTest)
#include "test_model.moc"
