// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tools > Match to Reference… without widgets: the match of the document's picture to a
// reference picture, fitted once (lut::fitMatch, the same as `lutkit match`), then baked again
// for every strength and preserve setting (lut::bakeMatch and the table sampled: 50-100 ms at
// 33^3, on MatchBaker's worker), so the dialog's sliders show the result live. The editor's
// document holds one 3D table: the match's shaper is baked into it by sampling
// (lut::LutFile::toLut3D).
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/Progress.h"
#include "lut/match/Match.h"

#include <QString>

#include <memory>

namespace lut::gui {

class MatchSession {
public:
    // Reads the reference (lut::formats::readImage: the same checks as the CLI) and fits the
    // match of `source` (the document's stored picture; float = scene-linear by lutkit's rule)
    // to it with `options`. Seconds at 1080p: the window runs it on a worker (BackgroundTask)
    // with `progress` (the read its first 30 %, the fit the rest; a cancel throws
    // lut::CancelledError). Throws lut::Error.
    MatchSession(std::shared_ptr<const Image> source, bool sourceIsFloat,
                 const QString& referencePath, const MatchOptions& options = {},
                 const Progress* progress = nullptr);

    const QString& referencePath() const { return m_referencePath; }
    const MatchOptions& options() const { return m_options; }
    // Strength, luma and chroma strength, preserve and size (the method is the fit's).
    void setOptions(const MatchOptions& options) { m_options = options; }

    // The LUT for the current options: shaper and table (throws lut::Error for a bad amount).
    LutFile lutFile() const;
    // The same as one table of options().size (what the document takes).
    Lut3D table() const;
    // The fitted transfer, shared with the worker that re-bakes it (MatchBaker.h).
    std::shared_ptr<const MatchTransfer> transfer() const { return m_transfer; }
    // The table's title: "match to <reference's file name>".
    std::string tableTitle() const;
    // lut::bakeMatch of `transfer` with `options`, as one table of options.size titled `title`:
    // table() and MatchBaker's worker (no state: any thread).
    static Lut3D bakeTable(const MatchTransfer& transfer, const MatchOptions& options,
                           const std::string& title);
    const MatchReport& fitReport() const { return m_fit.report; }
    const Diagnostics& fitDiagnostics() const { return m_fit.diagnostics; }
    // The fit's report and warnings as text.
    QString reportText() const;

private:
    std::shared_ptr<const Image> m_source;
    std::shared_ptr<const Image> m_reference;
    QString m_referencePath;
    MatchOptions m_options;
    MatchFitResult m_fit; // its transfer moved to m_transfer
    std::shared_ptr<const MatchTransfer> m_transfer;
};

} // namespace lut::gui
