// SPDX-License-Identifier: Apache-2.0
#include "PreviewWorker.h"

#include "CpuState.h"

#include <QCoreApplication>
#include <QEventLoop>

namespace lut::gui {

PreviewWorker::PreviewWorker(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(1); // the pipeline itself runs parallel loops on every core
}

PreviewWorker::~PreviewWorker() {
    m_pending[0] = m_pending[1] = nullptr;
    m_retired.clear();
    m_pool.waitForDone();
}

void PreviewWorker::request(Task task, Lane lane) {
    if (m_running)
        m_pending[static_cast<int>(lane)] = std::move(task);
    else
        start(std::move(task));
}

void PreviewWorker::retire(std::shared_ptr<const void> garbage) {
    if (garbage)
        m_retired.push_back(std::move(garbage));
}

void PreviewWorker::start(Task task) {
    m_running = true;
    m_pool.start([this, task = std::move(task), retired = std::move(m_retired)]() mutable {
        clearUpperVectorState(); // CpuState.h: a 20x slower pipeline otherwise
        retired.clear();         // freed here, not on the owner's thread
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
    // The delivery first: what it asks for (the first graded frame after a picture's first look)
    // starts before the work that was waiting (the full-resolution scene).
    if (delivery)
        delivery();
    if (!m_running)
        for (Task& pending : m_pending) // frames first, then scenes
            if (pending) {
                Task next = std::move(pending);
                pending = nullptr;
                start(std::move(next));
                break;
            }
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
