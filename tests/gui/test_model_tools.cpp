// SPDX-License-Identifier: Apache-2.0
// The Tools menu's model without widgets (gui/model/Comparison.h, ExportedLut.h): the table the
// export gives, and the comparison of the export with a LUT file over the lattice and over the
// picture's colours. Expectations are .cube files and offsets written plainly here.
#include "GuiTestSupport.h"

#include "Comparison.h"
#include "Document.h"
#include "ExportedLut.h"

#include "lut/formats/Registry.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace lut;
using namespace lut::gui;

namespace {

// A size^3 .cube whose entry at input (r, g, b) is f(r, g, b), red fastest (the .cube order).
template <class F> QString writeCube(const QTemporaryDir& dir, const char* name, int size, F f) {
    const QString path = dir.filePath(QString::fromLatin1(name));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return {};
    QByteArray text = "LUT_3D_SIZE " + QByteArray::number(size) + "\n";
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r) {
                const double in[3] = {double(r) / (size - 1), double(g) / (size - 1),
                                      double(b) / (size - 1)};
                const std::array<double, 3> out = f(in[0], in[1], in[2]);
                text += QByteArray::number(out[0], 'f', 6) + ' ' +
                        QByteArray::number(out[1], 'f', 6) + ' ' +
                        QByteArray::number(out[2], 'f', 6) + '\n';
            }
    file.write(text);
    return path;
}

constexpr double kRedOffset = 0.1; // B = A + (0.1, 0, 0): 25.5 8-bit steps in red, 0 elsewhere

std::array<double, 3> identity(double r, double g, double b) {
    return {r, g, b};
}

std::array<double, 3> redder(double r, double g, double b) {
    return {r + kRedOffset, g, b};
}

} // namespace

class ModelToolsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { formats::registerBuiltinFormats(); }

    void theExportedTableIsTheFilesEntries() {
        // A grade written here, opened, exported for a grading app (.cube): the table is the
        // file's entries (6 decimals written, float32 kept).
        QTemporaryDir dir;
        const auto grade = [](double r, double g, double b) {
            return std::array<double, 3>{0.9 * r + 0.05, std::sqrt(g), 1.0 - 0.5 * b};
        };
        const QString path = writeCube(dir, "grade.cube", 9, grade);
        Document doc;
        doc.openLut(path);
        const std::shared_ptr<const Lut3D> lut = exportedLut(doc, ExportTarget::Grading);
        QVERIFY(lut);
        QCOMPARE(lut->size(), 9);
        double worst = 0;
        for (int b = 0; b < 9; ++b)
            for (int g = 0; g < 9; ++g)
                for (int r = 0; r < 9; ++r) {
                    const auto want = grade(r / 8.0, g / 8.0, b / 8.0);
                    const glm::vec3 got = lut->at(r, g, b);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(worst, std::abs(double(got[c]) - want[c]));
                }
        QVERIFY2(worst < 2e-6, qPrintable(QString::number(worst)));
        // Its plot is a picture (lutkit plot's layout: wider than tall).
        const Image plot = plotExportedLut(doc, ExportTarget::Grading);
        QVERIFY(plot.width() > plot.height() && plot.height() > 0);
    }

    void aComparisonOverTheLatticeMeasuresTheOffset() {
        QTemporaryDir dir;
        const QString same = writeCube(dir, "same.cube", 17, identity);
        const QString red = writeCube(dir, "red.cube", 17, redder);
        Document doc;
        doc.openLut(same);
        const Comparison c0 = compareWithFile(doc, ExportTarget::Grading, same);
        QVERIFY(c0.over.isEmpty());
        QCOMPARE(c0.report.count, std::size_t(17 * 17 * 17));
        QVERIFY(c0.report.identical());
        QVERIFY(comparisonText(c0).contains(QStringLiteral("identical")));

        const Comparison c = compareWithFile(doc, ExportTarget::Grading, red);
        QCOMPARE(c.otherPath, red);
        QCOMPARE(c.report.count, std::size_t(17 * 17 * 17));
        const double steps = kRedOffset * 255.0;
        QVERIFY2(std::abs(c.report.maxSteps8.x - steps) < 1e-3 &&
                     std::abs(c.report.meanSteps8.x - steps) < 1e-3,
                 qPrintable(QString::number(c.report.maxSteps8.x)));
        QVERIFY(c.report.maxSteps8.y < 1e-3 && c.report.maxSteps8.z < 1e-3);
        QVERIFY(c.report.maxDeltaE > 0);
        QCOMPARE(c.heat.image.width() > 0, true);
        const QString text = comparisonText(c);
        QVERIFY2(
            text.contains(QStringLiteral("compared 4913 colours on a lattice over A's domain")),
            qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("8-bit    max   R 25.5  G ")), qPrintable(text));
    }

    void aComparisonOverThePictureCountsItsPixels() {
        QTemporaryDir dir;
        const QString same = writeCube(dir, "same.cube", 17, identity);
        const QString red = writeCube(dir, "red.cube", 17, redder);
        Document doc;
        doc.openLut(same);
        doc.adoptImage(lut::gui::test::noisyPicture(64, 40), QStringLiteral("shot.png"));
        const CompareInput in = compareInput(doc, ExportTarget::Grading, red);
        QVERIFY(in.image);
        const Comparison c = compareLuts(in);
        QCOMPARE(c.over, QStringLiteral("shot.png"));
        QCOMPARE(c.report.count, std::size_t(64 * 40));
        QVERIFY(std::abs(c.report.maxSteps8.x - kRedOffset * 255.0) < 1e-3);
        QCOMPARE(c.heat.image.width(), 64);
        QCOMPARE(c.heat.image.height(), 40);
        QCOMPARE(c.heatPicture.size(), QSize(64, 40));
        QVERIFY(comparisonText(c).contains(QStringLiteral("compared 2560 colours of shot.png")));
    }

    void aCancelledComparisonThrows() {
        QTemporaryDir dir;
        const QString same = writeCube(dir, "same.cube", 17, identity);
        Document doc;
        doc.openLut(same);
        Progress progress;
        progress.cancel();
        QVERIFY_THROWS_EXCEPTION(
            CancelledError, compareLuts(compareInput(doc, ExportTarget::Grading, same), &progress));
    }
};

QTEST_GUILESS_MAIN(ModelToolsTest)
#include "test_model_tools.moc"
