// SPDX-License-Identifier: Apache-2.0
#include "MatchBaker.h"

#include "CpuState.h"
#include "ErrorText.h"
#include "MatchSession.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QThread>

namespace lut::gui {

MatchBaker::MatchBaker(std::shared_ptr<const MatchTransfer> transfer, std::string title,
                       QObject* parent)
    : QObject(parent), m_transfer(std::move(transfer)), m_title(std::move(title)) {
    m_pool.setMaxThreadCount(1);
    m_pool.setExpiryTimeout(-1); // the thread stays while the dialog is open
}

MatchBaker::~MatchBaker() {
    m_pool.waitForDone();
}

void MatchBaker::request(const MatchOptions& options) {
    ++m_generation;
    m_exact.reset();
    if (m_running) {
        if (m_waiting)
            ++m_skipped; // replaced before it ran
        m_waiting = options;
        m_waitingGeneration = m_generation;
        return;
    }
    launch(options, m_generation);
}

void MatchBaker::drop() {
    m_droppedUpTo = m_generation; // what is running is delivered to nobody
    if (m_waiting)
        ++m_skipped;
    m_waiting.reset();
    m_exact.reset();
}

void MatchBaker::launch(const MatchOptions& options, std::uint64_t generation) {
    m_running = true;
    m_pool.start([this, options, generation, transfer = m_transfer, title = m_title] {
        clearUpperVectorState(); // CpuState.h
        std::shared_ptr<const Lut3D> table;
        QString error;
        try {
            table =
                std::make_shared<const Lut3D>(MatchSession::bakeTable(*transfer, options, title));
        } catch (const std::exception& e) {
            error = QString::fromStdString(humanErrorText(e));
        }
        QMetaObject::invokeMethod(
            this, [this, table, error, generation] { delivered(table, error, generation); },
            Qt::QueuedConnection);
    });
}

void MatchBaker::delivered(std::shared_ptr<const Lut3D> table, const QString& error,
                           std::uint64_t generation) {
    m_running = false;
    ++m_bakes;
    const bool exact = generation == m_generation;
    const bool dropped = generation <= m_droppedUpTo; // drop() came after it started
    if (m_waiting) {
        const MatchOptions next = *m_waiting;
        m_waiting.reset();
        launch(next, m_waitingGeneration);
    }
    if (dropped)
        return;
    if (!error.isEmpty()) {
        if (exact)
            emit failed(error);
        return;
    }
    if (exact)
        m_exact = table;
    emit baked(table, exact);
}

void MatchBaker::waitForIdle() {
    while (isBusy()) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        if (isBusy())
            QThread::msleep(1);
    }
}

} // namespace lut::gui
