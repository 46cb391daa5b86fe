#pragma once
// Runs the preview's tasks one at a time on a thread of its own, latest request wins: while one
// task runs, a new request replaces the pending one, so a fast slider never queues up stale work
// and the window never waits for the pipeline. A task runs on the worker thread and returns its
// delivery, which runs on the owner's thread from its event loop (so it may touch the owner's
// state). QtCore only.
#include <QObject>
#include <QThreadPool>

#include <functional>

namespace lut::gui {

class PreviewWorker : public QObject {
    Q_OBJECT
public:
    using Delivery = std::function<void()>;
    using Task = std::function<Delivery()>; // must not throw (a throw drops the delivery)

    explicit PreviewWorker(QObject* parent = nullptr);
    // Waits for the running task; its delivery and the pending task are dropped.
    ~PreviewWorker() override;

    void request(Task task);
    bool isBusy() const { return m_running || m_pending != nullptr; }
    // Blocks (processing events, so deliveries run) until no task is running or pending; for
    // tests and the headless modes.
    void waitForIdle();

signals:
    void idle(); // after a delivery, when nothing runs or waits

private:
    void start(Task task);
    void finished(const Delivery& delivery);

    QThreadPool m_pool;
    Task m_pending;
    bool m_running = false;
};

} // namespace lut::gui
