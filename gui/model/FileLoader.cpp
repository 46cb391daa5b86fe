// SPDX-License-Identifier: Apache-2.0
#include "FileLoader.h"

#include "CpuState.h"
#include "ErrorText.h"

#include "lut/formats/Registry.h"

#include <QCoreApplication>
#include <QEventLoop>

namespace lut::gui {

struct FileLoader::Read {
    std::atomic<double> fraction{0.0};
    Progress progress{[this](double f) { fraction.store(f, std::memory_order_relaxed); }};
};

FileLoader::FileLoader(QObject* parent) : QObject(parent) {
    // A picture and a LUT may load at once, and a cancelled read may still be stopping.
    m_pool.setMaxThreadCount(3);
    m_poll.setInterval(50);
    connect(&m_poll, &QTimer::timeout, this, [this] { emit progressChanged(fraction()); });
}

FileLoader::~FileLoader() {
    cancel();
    m_pool.waitForDone();
}

double FileLoader::fraction() const {
    return m_image ? m_image->fraction.load(std::memory_order_relaxed) : 0.0;
}

void FileLoader::setBusy(bool wasBusy) {
    if (wasBusy == isBusy())
        return;
    if (isBusy()) {
        m_poll.start();
        emit progressChanged(fraction());
    } else {
        m_poll.stop();
    }
    emit busyChanged(isBusy());
}

template <class Result, class ReadFn, class Deliver>
void FileLoader::start(std::shared_ptr<Read>& slot, bool isLut, const QString& path, ReadFn read,
                       Deliver deliver) {
    const bool wasBusy = isBusy();
    if (slot)
        slot->progress.cancel(); // superseded: stops at its next chunk of rows
    auto r = std::make_shared<Read>();
    slot = r;
    ++m_threads;
    m_pool.start([this, r, isLut, path, read, deliver] {
        clearUpperVectorState(); // CpuState.h
        Result result;
        QString error;
        bool cancelled = false;
        try {
            result = read(r->progress);
        } catch (const CancelledError&) {
            cancelled = true;
        } catch (const std::exception& e) {
            error = QString::fromStdString(humanErrorText(e));
        } catch (...) {
            error = tr("unknown error");
        }
        cancelled = cancelled || r->progress.cancelled();
        if (cancelled)
            result = Result(); // free a large picture on the worker, not on the window's thread
        --m_threads;
        QMetaObject::invokeMethod(
            this,
            [this, r, isLut, path, result, error, cancelled, deliver] {
                std::shared_ptr<Read>& current = isLut ? m_lut : m_image;
                if (cancelled || current != r) {
                    emit readStopped(path, r->fraction.load());
                    return;
                }
                const bool wasBusy = isBusy();
                current.reset();
                if (error.isEmpty())
                    deliver(path, result);
                else
                    emit failed(path, error, isLut);
                setBusy(wasBusy);
            },
            Qt::QueuedConnection);
    });
    setBusy(wasBusy);
}

void FileLoader::loadImage(const QString& path) {
    start<std::shared_ptr<formats::LoadedImage>>(
        m_image, false, path,
        [p = path.toStdString()](const Progress& progress) {
            return std::make_shared<formats::LoadedImage>(formats::readImage(p, {}, &progress));
        },
        [this](const QString& p, const std::shared_ptr<formats::LoadedImage>& image) {
            emit imageLoaded(p, image);
        });
}

void FileLoader::loadLut(const QString& path, const FormatOptions& options) {
    formats::registerBuiltinFormats();
    start<std::shared_ptr<LutFile>>(
        m_lut, true, path,
        [p = path.toStdString(), options](const Progress&) {
            return std::make_shared<LutFile>(formats::readLut(p, options));
        },
        [this](const QString& p, const std::shared_ptr<LutFile>& file) {
            emit lutLoaded(p, file);
        });
}

void FileLoader::cancel() {
    const bool wasBusy = isBusy();
    for (std::shared_ptr<Read>* slot : {&m_image, &m_lut})
        if (*slot) {
            (*slot)->progress.cancel();
            slot->reset();
        }
    setBusy(wasBusy);
}

void FileLoader::waitForIdle() {
    while (isBusy()) {
        QEventLoop loop;
        connect(this, &FileLoader::busyChanged, &loop, [&loop](bool busy) {
            if (!busy)
                loop.quit();
        });
        loop.exec();
    }
    QCoreApplication::processEvents();
}

} // namespace lut::gui
