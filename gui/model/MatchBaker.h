// SPDX-License-Identifier: Apache-2.0
#pragma once
// The match dialog's re-bake (MatchDialog.h) off the window's thread: every slider move asks for
// the LUT of its options (request()), the bake (lut::bakeMatch, then the one table the document
// takes: MatchSession::bakeTable) runs on a worker thread of its own, and the window only shows
// what it delivers. Latest wins: while a bake runs, new requests replace the waiting one (the
// values a drag passed over are never baked), and the worker then bakes the latest. What a bake
// delivers carries whether its options are still the latest (exact) or were overtaken while it
// ran (a proxy: the dialog may show it while the slider moves; the exact one follows). A result
// older than one already delivered never arrives (one worker, in order); after drop() nothing
// arrives. QtCore only.
#include "lut/Lut3D.h"
#include "lut/match/MatchOptions.h"
#include "lut/match/MatchTransfer.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace lut::gui {

class MatchBaker : public QObject {
    Q_OBJECT
public:
    MatchBaker(std::shared_ptr<const MatchTransfer> transfer, std::string title,
               QObject* parent = nullptr);
    ~MatchBaker() override; // waits for the bake running (milliseconds)

    // Asks for the table of `options`; returns at once.
    void request(const MatchOptions& options);
    // Forgets the requests: nothing more is delivered (the dialog closing).
    void drop();
    // A bake runs or waits.
    bool isBusy() const { return m_running || m_waiting.has_value(); }
    // The table of the latest request once baked (none while it is on its way or failed).
    std::shared_ptr<const Lut3D> exactTable() const { return m_exact; }
    // Processes events until no bake runs or waits (tests, scripts, OK pressed mid-bake).
    void waitForIdle();
    // Bakes done since construction, and requests that were replaced before they ran.
    int bakes() const { return m_bakes; }
    int skipped() const { return m_skipped; }

signals:
    // A table baked: `exact` when its options are the latest requested.
    void baked(std::shared_ptr<const lut::Lut3D> table, bool exact);
    // The latest request cannot be baked (lut::Error's text in words for people, humanErrorText:
    // a bad amount).
    void failed(const QString& message);

private:
    void launch(const MatchOptions& options, std::uint64_t generation);
    void delivered(std::shared_ptr<const Lut3D> table, const QString& error,
                   std::uint64_t generation);

    std::shared_ptr<const MatchTransfer> m_transfer;
    std::string m_title;
    QThreadPool m_pool;
    bool m_running = false;
    std::optional<MatchOptions> m_waiting;
    std::uint64_t m_generation = 0; // of the latest request
    std::uint64_t m_waitingGeneration = 0;
    std::uint64_t m_droppedUpTo = 0; // requests up to this one are delivered to nobody
    std::shared_ptr<const Lut3D> m_exact;
    int m_bakes = 0, m_skipped = 0;
};

} // namespace lut::gui
