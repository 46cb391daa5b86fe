// SPDX-License-Identifier: Apache-2.0
#include "BackgroundTask.h"

#include "CpuState.h"
#include "ErrorText.h"

#include <QCoreApplication>
#include <QEventLoop>

namespace lut::gui {

struct BackgroundTask::State {
    std::atomic<double> fraction{0.0};
    Progress progress{[this](double f) { fraction.store(f, std::memory_order_relaxed); }};
};

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(2); // a cancelled task may still be stopping when the next starts
    m_poll.setInterval(50);
    connect(&m_poll, &QTimer::timeout, this, [this] { emit progressChanged(fraction()); });
}

BackgroundTask::~BackgroundTask() {
    if (m_state)
        m_state->progress.cancel();
    m_pool.waitForDone();
}

double BackgroundTask::fraction() const {
    return m_state ? m_state->fraction.load(std::memory_order_relaxed) : 0.0;
}

void BackgroundTask::start(const QString& label, Work work, Failure failed) {
    const bool wasBusy = isBusy();
    if (m_state)
        m_state->progress.cancel(); // its delivery is dropped: it is no longer m_state
    auto state = std::make_shared<State>();
    m_state = state;
    m_label = label;
    m_pool.start([this, state, work = std::move(work), failed = std::move(failed)] {
        clearUpperVectorState(); // CpuState.h
        Delivery delivery;
        QString error;
        Outcome outcome = Outcome::Done;
        try {
            delivery = work(state->progress);
        } catch (const CancelledError&) {
            outcome = Outcome::Cancelled;
        } catch (const std::exception& e) {
            outcome = Outcome::Failed;
            error = QString::fromStdString(humanErrorText(e));
        } catch (...) {
            outcome = Outcome::Failed;
            error = tr("unknown error");
        }
        if (outcome == Outcome::Done && state->progress.cancelled())
            outcome = Outcome::Cancelled; // cancelled after its last check: drop it all the same
        QMetaObject::invokeMethod(
            this,
            [this, state, outcome, delivery, failed, error] {
                if (state != m_state)
                    return; // replaced by a newer task
                finish(state, outcome);
                if (outcome == Outcome::Done && delivery)
                    delivery();
                else if (outcome == Outcome::Failed && failed)
                    failed(error);
            },
            Qt::QueuedConnection);
    });
    m_poll.start();
    emit progressChanged(0.0);
    if (!wasBusy)
        emit busyChanged(true);
}

void BackgroundTask::finish(const std::shared_ptr<State>&, Outcome outcome) {
    m_state.reset();
    m_outcome = outcome;
    m_poll.stop();
    emit busyChanged(false);
}

void BackgroundTask::cancel() {
    if (!m_state)
        return;
    auto state = m_state;
    state->progress.cancel();
    finish(state, Outcome::Cancelled); // the window is free at once; the thread stops soon
}

void BackgroundTask::waitForIdle() {
    while (isBusy()) {
        QEventLoop loop;
        connect(this, &BackgroundTask::busyChanged, &loop, [&loop](bool busy) {
            if (!busy)
                loop.quit();
        });
        loop.exec();
    }
    QCoreApplication::processEvents();
}

} // namespace lut::gui
