// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor's "Check" panel model: lutkit check (lut::checkLut) on the LUT the export writes,
// run on a worker of its own (latest request wins, so dragging a slider never queues checks and
// the window never waits), and the highlight of a finding's colours on the picture (also on a
// worker: a hue band's test costs an Oklab conversion per pixel). A game LUT (the Smash target's
// export) is judged by what the game shows with it (lut/smash/SmashShownEdit.h), as
// `lutkit check` judges a .nutexb. Widget-free (QtCore, QtGui for QImage).
#include "PreviewWorker.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/check/CheckLut.h"

#include <QImage>
#include <QObject>
#include <QStringList>

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
    bool isBusy() const { return m_checks.isBusy() || m_highlights.isBusy(); }
    void waitForIdle(); // tests and headless modes

    // Asks for the highlight of finding `index` (0-based) on the picture: highlightReady brings
    // an image of the picture's size, a colour over the finding's pixels and transparent
    // elsewhere; -1 clears it.
    void requestHighlight(int index);
    const QImage& highlight() const { return m_highlight; }
    int highlightedFinding() const { return m_highlighted; }
    int highlightedPixels() const { return m_highlightedPixels; }

    // One line per failing check of the latest report (what an export warns about).
    QStringList failingChecks() const;

signals:
    void reportChanged();
    void highlightReady();

private:
    void schedule();

    PreviewWorker m_checks;
    PreviewWorker m_highlights;
    std::shared_ptr<const Lut3D> m_lut;
    bool m_game = false;
    std::shared_ptr<const Image> m_picture;
    bool m_overPicture = false;
    std::shared_ptr<const CheckReport> m_report;
    QImage m_highlight;
    int m_highlighted = -1;
    int m_highlightedPixels = 0;
};

} // namespace lut::gui
