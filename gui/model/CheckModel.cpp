// SPDX-License-Identifier: Apache-2.0
#include "CheckModel.h"

#include "lut/check/CheckFinding.h"
#include "lut/smash/SmashShownEdit.h"

namespace lut::gui {

namespace {

// Colours pictures rarely hold, so the marked pixels stand out: magenta for a failing finding,
// cyan for a warning.
QColor severityColour(CheckStatus s) {
    return s == CheckStatus::Fail ? QColor(255, 0, 255, 200) : QColor(0, 255, 255, 200);
}

// The check of `lut` (a game LUT judged by what the game shows), over `picture` when not null.
std::shared_ptr<CheckReport> runCheck(const Lut3D& lut, bool game,
                                      const std::shared_ptr<const Image>& picture) {
    LutFile file;
    file.cube = game ? smashShownEdit(lut) : lut;
    CheckOptions options;
    ImageView view;
    if (picture && !picture->empty()) {
        view = picture->view();
        options.image = &view;
    }
    auto report = std::make_shared<CheckReport>(checkLut(file, options));
    if (game)
        report->description = "Smash Ultimate game LUT, checked as the edit the game shows (" +
                              report->description + ")";
    return report;
}

} // namespace

CheckModel::CheckModel(QObject* parent) : QObject(parent), m_checks(this), m_highlights(this) {
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &CheckModel::startCheck);
}

void CheckModel::setLut(std::shared_ptr<const Lut3D> lut, bool gameLut) {
    if (lut == m_lut && gameLut == m_game)
        return;
    m_lut = std::move(lut);
    m_game = gameLut;
    schedule();
}

void CheckModel::setPicture(std::shared_ptr<const Image> picture) {
    if (picture == m_picture)
        return;
    m_picture = std::move(picture);
    requestHighlight(-1);
    if (m_overPicture)
        schedule();
}

void CheckModel::setOverPicture(bool on) {
    if (on == m_overPicture)
        return;
    m_overPicture = on;
    schedule();
}

void CheckModel::schedule() {
    if (m_lut)
        m_settle.start(); // restarted by every change
}

CheckModel::Subject CheckModel::current() const {
    return {m_lut, m_game, m_overPicture ? m_picture : nullptr};
}

void CheckModel::setReport(std::shared_ptr<const CheckReport> report, const Subject& of) {
    m_report = std::move(report);
    m_reportOf = of;
    emit reportChanged();
    requestHighlight(-1); // the findings changed
}

void CheckModel::startCheck() {
    m_settle.stop();
    if (!m_lut)
        return;
    const Subject of = current();
    m_checks.request([this, of]() -> PreviewWorker::Delivery {
        auto report = runCheck(*of.lut, of.game, of.picture);
        return [this, report, of] {
            // An older LUT's report does not replace the current one's (failingChecks() may
            // have checked the current LUT meanwhile).
            if (!(of == current()) && m_reportOf == current())
                return;
            setReport(report, of);
        };
    });
}

void CheckModel::requestHighlight(int index) {
    const std::shared_ptr<const CheckReport> report = m_report;
    const std::shared_ptr<const Image> picture = m_picture;
    if (index < 0 || !report || !picture || picture->empty() ||
        index >= static_cast<int>(report->findings.size())) {
        m_highlight = QImage();
        m_highlighted = -1;
        m_highlightedPixels = 0;
        emit highlightReady();
        return;
    }
    m_highlights.request([this, report, picture, index]() -> PreviewWorker::Delivery {
        const CheckFinding& f = report->findings[static_cast<std::size_t>(index)];
        const std::vector<std::uint8_t> mask = regionMask(f.region, picture->view());
        QImage overlay(picture->width(), picture->height(), QImage::Format_ARGB32_Premultiplied);
        overlay.fill(Qt::transparent);
        const QRgb mark = qPremultiply(severityColour(f.severity).rgba());
        int pixels = 0;
        for (int y = 0; y < picture->height(); ++y) {
            auto* line = reinterpret_cast<QRgb*>(overlay.scanLine(y));
            for (int x = 0; x < picture->width(); ++x)
                if (mask[static_cast<std::size_t>(y) * picture->width() + x]) {
                    line[x] = mark;
                    ++pixels;
                }
        }
        return [this, overlay, index, pixels, report] {
            if (report != m_report)
                return; // a newer check replaced the findings
            m_highlight = overlay;
            m_highlighted = index;
            m_highlightedPixels = pixels;
            emit highlightReady();
        };
    });
}

void CheckModel::waitForIdle() {
    if (m_settle.isActive())
        startCheck();
    while (isBusy()) {
        m_checks.waitForIdle();
        m_highlights.waitForIdle();
    }
}

QStringList CheckModel::failingChecks() {
    QStringList lines;
    if (m_lut && !(m_reportOf == current())) {
        // The latest report is of an older LUT (still settling or being checked): check this
        // one now, an export must warn about what it writes.
        m_settle.stop();
        const Subject of = current();
        setReport(runCheck(*of.lut, of.game, of.picture), of);
    }
    if (!m_report)
        return lines;
    for (const CheckSummary& c : m_report->checks) {
        if (c.status != CheckStatus::Fail)
            continue;
        QString worst = QString::fromStdString(c.text);
        for (const CheckFinding& f : m_report->findings)
            if (checkOf(f.kind) == c.kind && f.severity == CheckStatus::Fail) {
                worst = QString::fromStdString(f.text(m_report->image));
                break;
            }
        lines << tr("Check: %1 fails: %2").arg(QString::fromLatin1(toString(c.kind)), worst);
    }
    return lines;
}

} // namespace lut::gui
