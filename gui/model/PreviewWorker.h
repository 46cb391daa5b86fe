// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs the preview's tasks one at a time on a thread of its own, latest request wins: while one
// task runs, a new request replaces the pending one of its lane, so a fast slider never queues up
// stale work and the window never waits for the pipeline. Two lanes: frames (renders) and scenes
// (preparing a new picture's full-resolution scene); a pending frame starts before a pending
// scene, so a graded proxy frame shows while the full-resolution scene is still to be made, and
// neither kind of request drops the other. A task runs on the worker thread and returns its
// delivery, which runs on the owner's thread from its event loop (so it may touch the owner's
// state). QtCore only.
#include <QObject>
#include <QThreadPool>

#include <functional>
#include <memory>
#include <vector>

namespace lut::gui {

class PreviewWorker : public QObject {
    Q_OBJECT
public:
    using Delivery = std::function<void()>;
    using Task = std::function<Delivery()>; // must not throw (a throw drops the delivery)

    explicit PreviewWorker(QObject* parent = nullptr);
    // Waits for the running task; its delivery and the pending task are dropped.
    ~PreviewWorker() override;

    enum class Lane { Frame, Scene };
    void request(Task task, Lane lane = Lane::Frame);
    // Hands over something large the owner no longer needs (a replaced frame, scene or picture):
    // it is freed on the worker when its next task starts, not on the owner's thread (freeing a
    // 4K float frame there waited up to ~0.2 s for the address space lock while the worker
    // touched fresh pages).
    void retire(std::shared_ptr<const void> garbage);
    bool isBusy() const { return m_running || m_pending[0] != nullptr || m_pending[1] != nullptr; }
    // Blocks (processing events, so deliveries run) until no task is running or pending; for
    // tests and the headless modes.
    void waitForIdle();

signals:
    void idle(); // after a delivery, when nothing runs or waits

private:
    void start(Task task);
    void finished(const Delivery& delivery);

    QThreadPool m_pool;
    Task m_pending[2]; // per lane
    std::vector<std::shared_ptr<const void>> m_retired;
    bool m_running = false;
};

} // namespace lut::gui
