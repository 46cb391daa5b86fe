#include "FileLoader.h"

#include "CpuState.h"

#include "lut/formats/Registry.h"

#include <QCoreApplication>
#include <QEventLoop>

namespace lut::gui {

FileLoader::FileLoader(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(2); // a picture and a LUT may load at once
}

FileLoader::~FileLoader() {
    m_pool.waitForDone();
}

template <class Read, class Deliver>
void FileLoader::start(quint64 generation, bool isLut, const QString& path, Read read,
                       Deliver deliver) {
    if (m_running++ == 0)
        emit busyChanged(true);
    m_pool.start([this, generation, isLut, path, read, deliver] {
        clearUpperVectorState(); // CpuState.h
        auto result = decltype(read())();
        QString error;
        try {
            result = read();
        } catch (const std::exception& e) {
            error = QString::fromUtf8(e.what());
        } catch (...) {
            error = tr("unknown error");
        }
        QMetaObject::invokeMethod(
            this,
            [this, generation, isLut, path, result, error, deliver] {
                const bool current = generation == (isLut ? m_lutGeneration : m_imageGeneration);
                --m_running;
                if (current) {
                    if (error.isEmpty())
                        deliver(path, result);
                    else
                        emit failed(path, error, isLut);
                }
                if (m_running == 0)
                    emit busyChanged(false);
            },
            Qt::QueuedConnection);
    });
}

void FileLoader::loadImage(const QString& path) {
    start(
        ++m_imageGeneration, false, path,
        [p = path.toStdString()] {
            return std::make_shared<formats::LoadedImage>(formats::readImage(p));
        },
        [this](const QString& p, const std::shared_ptr<formats::LoadedImage>& image) {
            emit imageLoaded(p, image);
        });
}

void FileLoader::loadLut(const QString& path, const FormatOptions& options) {
    formats::registerBuiltinFormats();
    start(
        ++m_lutGeneration, true, path,
        [p = path.toStdString(), options] {
            return std::make_shared<LutFile>(formats::readLut(p, options));
        },
        [this](const QString& p, const std::shared_ptr<LutFile>& file) {
            emit lutLoaded(p, file);
        });
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
