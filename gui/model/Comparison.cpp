// SPDX-License-Identifier: Apache-2.0
#include "Comparison.h"

#include "Document.h"
#include "PreviewFrame.h"

#include "lut/formats/Registry.h"

#include <QDir>

#include <optional>

namespace lut::gui {

namespace {

QString g3(double v) {
    return QString::number(v, 'g', 3);
}

QString triple(glm::vec3 v) {
    return g3(v.x) + ' ' + g3(v.y) + ' ' + g3(v.z);
}

QString steps(glm::dvec3 v) {
    return QStringLiteral("R %1  G %2  B %3").arg(g3(v.x), g3(v.y), g3(v.z));
}

} // namespace

CompareInput compareInput(const Document& doc, ExportTarget target, const QString& otherPath) {
    CompareInput in;
    in.source = doc.lutSource();
    in.target = target;
    in.image = doc.storedImage();
    in.imagePath = doc.imagePath();
    in.otherPath = otherPath;
    return in;
}

Comparison compareLuts(const CompareInput& in, const Progress* progress) {
    checkCancelled(progress, in.otherPath.toStdString());
    const std::shared_ptr<const Lut3D> a = makeTargetLut(in.source, in.target).shown;
    const Lut3D b = formats::readLut(in.otherPath.toStdString()).toLut3D();
    Comparison c;
    c.otherPath = in.otherPath;
    const Progress* root = progress;
    std::optional<Progress> diffPart, heatPart;
    if (root) {
        diffPart.emplace(*root, 0.0, 0.6);
        heatPart.emplace(*root, 0.6, 1.0);
    }
    DiffOptions diff;
    diff.progress = root ? &*diffPart : nullptr;
    HeatMapOptions heat;
    heat.progress = root ? &*heatPart : nullptr;
    if (in.image) {
        c.over = in.imagePath;
        c.report = diffLutsOnImage(*a, b, in.image->view(), diff);
        c.heat = diffHeatMap(*a, b, in.image->view(), heat);
    } else {
        c.report = diffLuts(*a, b, diff);
        c.heat = diffHeatMapSlices(*a, b, heat);
    }
    c.heatPicture = toDisplayImage(c.heat.image);
    return c;
}

Comparison compareWithFile(const Document& doc, ExportTarget target, const QString& otherPath) {
    return compareLuts(compareInput(doc, target, otherPath));
}

QString comparisonText(const Comparison& c) {
    const DiffReport& r = c.report;
    QString t;
    t += QStringLiteral("A  the export (what the editor writes now)\nB  %1\n")
             .arg(QDir::toNativeSeparators(c.otherPath));
    t += QStringLiteral("compared %1 colours %2\n")
             .arg(r.count)
             .arg(c.over.isEmpty() ? QStringLiteral("on a lattice over A's domain")
                                   : "of " + QDir::toNativeSeparators(c.over));
    if (r.identical())
        return t + QStringLiteral("identical: ΔE2000 0, 0 8-bit steps\n");
    t += QStringLiteral("ΔE2000   max %1, mean %2, 95th percentile %3 (entries taken as "
                        "sRGB-encoded)\n")
             .arg(g3(r.maxDeltaE), g3(r.meanDeltaE), g3(r.p95DeltaE));
    t += QStringLiteral("8-bit    max   %1\n         mean  %2\n")
             .arg(steps(r.maxSteps8), steps(r.meanSteps8));
    t += QStringLiteral("worst    input %1: A %2, B %3 (ΔE %4)\n")
             .arg(triple(r.worst.input), triple(r.worst.a), triple(r.worst.b), g3(r.worst.deltaE));
    t += QStringLiteral("where    (largest mean ΔE first)\n");
    for (const RegionDiff& g : r.rankedRegions())
        t += QStringLiteral("  %1mean ΔE %2, max %3 at %4 (%5 colours)\n")
                 .arg(QString::fromLatin1(toString(g.region)).leftJustified(12), g3(g.meanDeltaE),
                      g3(g.maxDeltaE), triple(g.worstInput))
                 .arg(g.count);
    if (r.sanitizedEntriesA || r.sanitizedEntriesB)
        t += QStringLiteral("note     NaN/Inf entries counted as 0 or +-65504: A %1, B %2\n")
                 .arg(r.sanitizedEntriesA)
                 .arg(r.sanitizedEntriesB);
    return t;
}

} // namespace lut::gui
