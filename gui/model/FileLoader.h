#pragma once
// Reads pictures and LUT files on a worker thread so the window never waits for a file: a 4K PNG
// takes seconds to decode. The result (or the error text) is delivered as a signal on the
// loader's thread, where the window adopts it into the Document. A newer request of the same
// kind supersedes an older one still running (its result is dropped). QtCore only.
#include "lut/LutFile.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/FormatOptions.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <memory>

namespace lut::gui {

class FileLoader : public QObject {
    Q_OBJECT
public:
    explicit FileLoader(QObject* parent = nullptr);
    // Waits for the reads in flight; their results are dropped.
    ~FileLoader() override;

    void loadImage(const QString& path);
    void loadLut(const QString& path, const FormatOptions& options = {});
    bool isBusy() const { return m_running > 0; }
    // Processes events until no read is running (tests, headless modes, scripts).
    void waitForIdle();

signals:
    void imageLoaded(const QString& path, std::shared_ptr<lut::formats::LoadedImage> image);
    void lutLoaded(const QString& path, std::shared_ptr<lut::LutFile> file);
    void failed(const QString& path, const QString& message, bool isLut);
    void busyChanged(bool busy);

private:
    template <class Read, class Deliver>
    void start(quint64 generation, bool isLut, const QString& path, Read read, Deliver deliver);

    QThreadPool m_pool;
    quint64 m_imageGeneration = 0;
    quint64 m_lutGeneration = 0;
    int m_running = 0;
};

} // namespace lut::gui
