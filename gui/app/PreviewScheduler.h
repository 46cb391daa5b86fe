#pragma once
// Runs preview renders on a worker thread (QtConcurrent), latest request wins: while one render
// runs, new requests replace the pending one, so a fast slider never queues up stale work and
// the window never waits for the pipeline.
#include "PreviewRenderer.h"

#include <QFutureWatcher>
#include <QImage>
#include <QObject>

#include <memory>

namespace lut::gui {

struct PreviewJob {
    std::shared_ptr<const Image> scene; // prepared linear frame (full size or proxy)
    std::shared_ptr<const Lut3D> lut;
    PreviewOptions options;
    int proxyFactor = 1; // 1 = full resolution
    quint64 serial = 0;
    // The scene after the stages before the LUT (PreviewRenderer.h), when the caller has it
    // for this scene and these options; else the worker makes it and returns it in the frame.
    std::shared_ptr<const Image> beforeLut;
};

struct PreviewFrame {
    Image image;                    // display-encoded float RGBA, what `lutkit preview` writes
    QImage display;                 // the same as 8-bit for drawing (alpha forced opaque)
    double milliseconds = 0.0;      // pipeline time
    double totalMilliseconds = 0.0; // pipeline + conversion
    int proxyFactor = 1;
    quint64 serial = 0;
    QString error; // non-empty if the pipeline threw
    QString report;
    bool reusedBeforeLut = false;
    // What the frame was made from, so the caller can cache the before-LUT frame.
    std::shared_ptr<const Image> scene;
    PreviewOptions options;
    std::shared_ptr<const Image> beforeLut;
};

// 8-bit display copy of a display-encoded float image through lut::toUnorm8.
QImage toDisplayImage(const Image& image);

class PreviewScheduler : public QObject {
    Q_OBJECT
public:
    explicit PreviewScheduler(QObject* parent = nullptr);
    ~PreviewScheduler() override;

    // Queues a render; returns its serial number.
    quint64 request(PreviewJob job);
    bool isBusy() const { return m_running || m_hasPending; }
    quint64 lastRequested() const { return m_serial; }
    // Blocks (processing events) until no render is running or pending; for tests and
    // --screenshot.
    void waitForIdle();

signals:
    void frameReady(std::shared_ptr<const lut::gui::PreviewFrame> frame);
    void idle();

private:
    void start(PreviewJob job);
    void onFinished();

    QFutureWatcher<std::shared_ptr<const PreviewFrame>> m_watcher;
    PreviewJob m_pending;
    bool m_hasPending = false;
    bool m_running = false;
    quint64 m_serial = 0;
};

} // namespace lut::gui
