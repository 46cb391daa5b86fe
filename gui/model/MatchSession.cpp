// SPDX-License-Identifier: Apache-2.0
#include "MatchSession.h"

#include "lut/formats/ImageIO.h"
#include "lut/pipeline/SceneKind.h"

#include <QFileInfo>

namespace lut::gui {

MatchSession::MatchSession(std::shared_ptr<const Image> source, bool sourceIsFloat,
                           const QString& referencePath, const MatchOptions& options,
                           const Progress* progress)
    : m_source(std::move(source)), m_referencePath(referencePath), m_options(options) {
    if (!m_source || m_source->empty())
        throw Error("match: open a picture first: it is the source the look is matched on");
    const Progress none;
    const Progress& whole = progress ? *progress : none;
    const Progress reading(whole, 0.0, 0.3), fitting(whole, 0.3, 1.0);
    const formats::LoadedImage ref = formats::readImage(referencePath.toStdString(), {}, &reading);
    const auto& i = ref.info;
    const SceneDecision refKind =
        decideSceneKind(SceneEvidence{i.isFloat, i.bitDepth, i.colorSpace, i.format});
    m_reference = std::make_shared<const Image>(ref.image);
    MatchPicture src;
    src.pixels = m_source->view();
    src.linear = decideSceneKind(SceneEvidence{sourceIsFloat, sourceIsFloat ? 32 : 8, {}, {}})
                     .storedIsLinear;
    src.bitDepth = sourceIsFloat ? 0 : 8;
    src.name = "the picture";
    MatchPicture r;
    r.pixels = m_reference->view();
    r.linear = refKind.storedIsLinear;
    r.bitDepth = i.isFloat ? 0 : i.bitDepth;
    r.name = QFileInfo(referencePath).fileName().toStdString();
    m_fit = fitMatch(src, {r}, m_options, &fitting);
    m_transfer = std::make_shared<const MatchTransfer>(std::move(m_fit.transfer));
}

LutFile MatchSession::lutFile() const {
    return bakeMatch(*m_transfer, m_options);
}

Lut3D MatchSession::table() const {
    return bakeTable(*m_transfer, m_options, tableTitle());
}

std::string MatchSession::tableTitle() const {
    return "match to " + QFileInfo(m_referencePath).fileName().toStdString();
}

Lut3D MatchSession::bakeTable(const MatchTransfer& transfer, const MatchOptions& options,
                              const std::string& title) {
    Lut3D t = bakeMatch(transfer, options).toLut3D(options.size);
    t.setTitle(title);
    return t;
}

QString MatchSession::reportText() const {
    const MatchReport& r = m_fit.report;
    QString s = QStringLiteral("method   %1 (%2)\n")
                    .arg(QString::fromLatin1(toString(r.method)), QString::fromStdString(r.choice));
    auto distance = [](const DistributionDistance& d) {
        return QStringLiteral("sliced Wasserstein %1 (CIELAB), quantile ΔE2000 %2")
            .arg(d.slicedWasserstein, 0, 'g', 3)
            .arg(d.quantileDeltaE, 0, 'g', 3);
    };
    for (const auto& c : r.candidates)
        s += QStringLiteral("         %1: %2%3\n")
                 .arg(QString::fromLatin1(toString(c.method)), distance(c.after),
                      QString::fromStdString(c.shapeNote()));
    s += QStringLiteral("before   %1\n").arg(distance(r.before));
    for (const auto& c : r.candidates)
        if (c.method == r.method)
            s += QStringLiteral("after    %1 (full strength)\n").arg(distance(c.after));
    for (const auto& d : m_fit.diagnostics)
        s += QString::fromStdString(d.str()) + "\n";
    return s;
}

} // namespace lut::gui
