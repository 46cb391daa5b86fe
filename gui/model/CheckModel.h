// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor's "Check" panel model: lutkit check (lut::checkLut) on the LUT the export writes,
// run on a worker of its own once the LUT has stayed the same for kSettleMs (a slider drag changes
// it every frame: checking each one took both cores from the preview, 2-3x its time per frame),
// latest request winning, so the window never waits; and the highlight of a finding's colours on
// the picture (also on a worker: a hue band's test costs an Oklab conversion per pixel). A game LUT
// (the Smash target's export) is judged by what the game shows with it
// (lut/smash/SmashShownEdit.h), as `lutkit check` judges a .nutexb. Widget-free (QtCore, QtGui for
// QImage).
#include "PreviewWorker.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/check/CheckLut.h"

#include <QImage>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <memory>

namespace lut::gui {

class CheckModel : public QObject {
    Q_OBJECT
public:
    explicit CheckModel(QObject* parent = nullptr);

    // The export's table as read back; gameLut: Smash Ultimate's compensated LUT.
    void setLut(std::shared_ptr<const Lut3D> lut, bool gameLut);
    // The picture findings are highlighted on (its stored values: a screenshot's colours), and
    // with overPicture(), what the check weighs by (the share of its pixels).
    void setPicture(std::shared_ptr<const Image> picture);
    void setOverPicture(bool on);
    bool overPicture() const { return m_overPicture; }

    // The latest report (null before the first check), for the LUT it was made from.
    std::shared_ptr<const CheckReport> report() const { return m_report; }
    // How long the LUT must stay unchanged before it is checked.
    static constexpr int kSettleMs = 250;
    bool isBusy() const {
        return m_settle.isActive() || m_checks.isBusy() || m_highlights.isBusy();
    }
    void waitForIdle(); // tests and headless modes: a check still settling starts at once

    // Asks for the highlight of finding `index` (0-based) on the picture: highlightReady brings
    // an image of the picture's size, a colour over the finding's pixels and transparent
    // elsewhere; -1 clears it.
    void requestHighlight(int index);
    const QImage& highlight() const { return m_highlight; }
    int highlightedFinding() const { return m_highlighted; }
    int highlightedPixels() const { return m_highlightedPixels; }

    // One line per failing check of the current LUT (what an export warns about): when the
    // latest report is of an older LUT (still settling or running), the check runs here first.
    QStringList failingChecks();

signals:
    void reportChanged();
    void highlightReady();

private:
    void schedule(); // after kSettleMs without a change
    void startCheck();

    QTimer m_settle;
    PreviewWorker m_checks;
    PreviewWorker m_highlights;
    std::shared_ptr<const Lut3D> m_lut;
    bool m_game = false;
    std::shared_ptr<const Image> m_picture;
    bool m_overPicture = false;
    std::shared_ptr<const CheckReport> m_report;
    // What a check is of: the LUT, whether it is the game's, the picture it weighs by (or null).
    struct Subject {
        std::shared_ptr<const Lut3D> lut;
        bool game = false;
        std::shared_ptr<const Image> picture;
        bool operator==(const Subject& o) const {
            return lut == o.lut && game == o.game && picture == o.picture;
        }
    };
    Subject current() const;
    void setReport(std::shared_ptr<const CheckReport> report, const Subject& of);
    Subject m_reportOf; // what m_report was made from
    QImage m_highlight;
    int m_highlighted = -1;
    int m_highlightedPixels = 0;
};

} // namespace lut::gui
