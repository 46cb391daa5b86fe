#include "PreviewWorker.h"

#include "CpuState.h"

#include <QCoreApplication>
#include <QEventLoop>

namespace lut::gui {

PreviewWorker::PreviewWorker(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(1); // the pipeline itself runs parallel loops on every core
}

PreviewWorker::~PreviewWorker() {
    m_pending = nullptr;
    m_pool.waitForDone();
}

void PreviewWorker::request(Task task) {
    if (m_running)
        m_pending = std::move(task);
    else
        start(std::move(task));
}

void PreviewWorker::start(Task task) {
    m_running = true;
    m_pool.start([this, task = std::move(task)] {
        clearUpperVectorState(); // CpuState.h: a 20x slower pipeline otherwise
        Delivery delivery;
        try {
            delivery = task();
        } catch (...) {
        }
        // Queued to this object's thread; dropped if the worker is gone by then.
        QMetaObject::invokeMethod(
            this, [this, delivery = std::move(delivery)] { finished(delivery); },
            Qt::QueuedConnection);
    });
}

void PreviewWorker::finished(const Delivery& delivery) {
    m_running = false;
    if (m_pending) {
        Task next = std::move(m_pending);
        m_pending = nullptr;
        start(std::move(next));
    }
    if (delivery)
        delivery();
    if (!isBusy())
        emit idle();
}

void PreviewWorker::waitForIdle() {
    while (isBusy()) {
        QEventLoop loop;
        connect(this, &PreviewWorker::idle, &loop, &QEventLoop::quit);
        loop.exec(); // idle is emitted from this thread's event loop, never before exec()
    }
    QCoreApplication::processEvents();
}

} // namespace lut::gui
