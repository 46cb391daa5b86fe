// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reads pictures and LUT files on a worker thread so the window never waits for a file: a 4K PNG
// takes seconds to decode, and a small file may hold a huge picture (a 16384x16384 PNG of one
// colour is 780 KB and decodes to 4.3 GB). The result (or the error text) is delivered as a signal
// on the loader's thread, where the window adopts it into the Document. Reads report their
// progress (progressChanged, from the rows decoded) and stop when cancelled: cancel() stops every
// read in flight, and a newer request of the same kind cancels an older one still running (its
// decoding stops at the next chunk of rows; its result is dropped). QtCore only.
#include "lut/LutFile.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/FormatOptions.h"

#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>

#include <atomic>
#include <memory>

namespace lut::gui {

class FileLoader : public QObject {
    Q_OBJECT
public:
    explicit FileLoader(QObject* parent = nullptr);
    // Cancels the reads in flight and waits for them to stop; their results are dropped.
    ~FileLoader() override;

    void loadImage(const QString& path);
    void loadLut(const QString& path, const FormatOptions& options = {});
    // Stops every read in flight: nothing is delivered, the document stays as it was.
    void cancel();
    bool isBusy() const { return m_image != nullptr || m_lut != nullptr; }
    // The fraction of the picture read so far (0 while only a LUT loads).
    double fraction() const;
    // Reads whose threads have not returned yet, cancelled ones included (tests: a cancelled read
    // stops decoding).
    int threadsRunning() const { return m_threads.load(); }
    // Processes events until no read is running (tests, headless modes, scripts).
    void waitForIdle();

signals:
    void imageLoaded(const QString& path, std::shared_ptr<lut::formats::LoadedImage> image);
    void lutLoaded(const QString& path, std::shared_ptr<lut::LutFile> file);
    // The read's error in words for people (humanErrorText, ErrorText.h).
    void failed(const QString& path, const QString& message, bool isLut);
    void busyChanged(bool busy);
    void progressChanged(double fraction);
    // A read that was cancelled or superseded returned, having read `fraction` of the file.
    void readStopped(const QString& path, double fraction);

private:
    struct Read; // shared with the worker thread
    template <class Result, class ReadFn, class Deliver>
    void start(std::shared_ptr<Read>& slot, bool isLut, const QString& path, ReadFn read,
               Deliver deliver);
    void setBusy(bool wasBusy);

    QThreadPool m_pool;
    QTimer m_poll;
    std::shared_ptr<Read> m_image; // the current reads (null: none)
    std::shared_ptr<Read> m_lut;
    std::atomic<int> m_threads{0};
};

} // namespace lut::gui
