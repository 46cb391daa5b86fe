#pragma once
// One preview render as plain data: what the worker is asked for (PreviewJob), what it delivers
// (PreviewFrame), and the function that makes one from the other (renderFrame). No Qt objects,
// no shared mutable state: renderFrame runs on the worker thread.
#include "PreviewRenderer.h"

#include <QImage>
#include <QString>
#include <QtGlobal>

#include <memory>

namespace lut::gui {

struct PreviewJob {
    std::shared_ptr<const Image> scene; // prepared linear frame (full size or proxy)
    std::shared_ptr<const Lut3D> lut;
    PreviewOptions options;
    int proxyFactor = 1; // 1 = full resolution
    quint64 serial = 0;
    // The scene after the stages before the LUT (renderBeforeLut), when the caller has it for
    // this scene and these options; else the worker makes it and returns it in the frame.
    std::shared_ptr<const Image> beforeLut;
};

struct PreviewFrame {
    Image image;                    // display-encoded float RGBA, what `lutkit preview` writes
    QImage display;                 // the same as 8-bit for drawing (alpha forced opaque)
    double milliseconds = 0.0;      // pipeline time (the LUT part when the cache was used)
    double totalMilliseconds = 0.0; // pipeline + 8-bit conversion
    int proxyFactor = 1;
    quint64 serial = 0;
    QString error; // non-empty if the pipeline threw; image and display are then empty
    QString report;
    bool reusedBeforeLut = false;
    // What the frame was made from, so the controller can tell a current frame from a stale one
    // and cache the before-LUT frame.
    std::shared_ptr<const Image> scene;
    std::shared_ptr<const Lut3D> lut;
    PreviewOptions options;
    std::shared_ptr<const Image> beforeLut;
};

// 8-bit display copy of a display-encoded float image through lut::toUnorm8.
QImage toDisplayImage(const Image& image);

// Runs the job: the before-LUT part unless the job carries it, the LUT part, the 8-bit copy.
// Never throws: a failure comes back as frame->error.
std::shared_ptr<const PreviewFrame> renderFrame(const PreviewJob& job);

} // namespace lut::gui
