// SPDX-License-Identifier: Apache-2.0
#pragma once
// A long task on a worker thread, with progress and cancel, so the window never waits for it
// (comparing a LUT over a 4K picture, writing the preview image): start() returns at once, the
// work runs on a thread of the task's own and reports through a lut::Progress, the window shows
// label() and fraction() (progressChanged, at most every 50 ms) with a Cancel button, and the
// work's delivery runs on the owner's thread when it is done. One task at a time: starting a new
// one cancels the one running (its delivery is dropped). QtCore only.
//
// The work must check the Progress it is given (the library calls take it: lut/Progress.h); after
// cancel() it throws lut::CancelledError at its next check, and nothing is delivered. Any other
// exception is handed to the failure handler as text, on the owner's thread.
#include "lut/Progress.h"

#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>

namespace lut::gui {

class BackgroundTask : public QObject {
    Q_OBJECT
public:
    using Delivery = std::function<void()>;
    using Work = std::function<Delivery(const Progress&)>;
    // The work's error in words for people (humanErrorText, ErrorText.h).
    using Failure = std::function<void(const QString& message)>;

    explicit BackgroundTask(QObject* parent = nullptr);
    // Cancels the running work and waits for it to stop (it checks within a few ms).
    ~BackgroundTask() override;

    // Starts `work` (labelled e.g. "Comparing grade.cube…"); a running task is cancelled.
    void start(const QString& label, Work work, Failure failed = {});
    void cancel();
    bool isBusy() const { return m_state != nullptr; }
    QString label() const { return m_label; }
    double fraction() const; // 0..1 of the running task
    // Threads still running work, cancelled ones included (they stop at their next check).
    int threadsRunning() const { return m_pool.activeThreadCount(); }
    // Processes events until no task runs (tests, headless modes, scripts).
    void waitForIdle();
    // How the last task ended.
    enum class Outcome { None, Done, Cancelled, Failed };
    Outcome lastOutcome() const { return m_outcome; }

signals:
    void busyChanged(bool busy);
    void progressChanged(double fraction);

private:
    struct State; // shared with the worker thread
    void finish(const std::shared_ptr<State>& state, Outcome outcome);

    QThreadPool m_pool;
    QTimer m_poll;
    std::shared_ptr<State> m_state;
    QString m_label;
    Outcome m_outcome = Outcome::None;
};

} // namespace lut::gui
