// SPDX-License-Identifier: Apache-2.0
#pragma once
// One preview render as plain data: what the worker is asked for (PreviewJob), what it delivers
// (PreviewFrame), and the function that makes one from the other (renderFrame). No Qt objects,
// no shared mutable state: renderFrame runs on the worker thread.
#include "ExportTarget.h"
#include "PreviewRenderer.h"
#include "Scopes.h"

#include <QImage>
#include <QString>
#include <QtGlobal>

#include <memory>

namespace lut::gui {

struct PreviewJob {
    std::shared_ptr<const Image> scene; // prepared frame (full size or proxy)
    LutSource source;                   // the document (neutral when the LUT is switched off)
    ExportTarget target = ExportTarget::Smash; // the document's (Document::target)
    PreviewOptions options;
    int proxyFactor = 1; // 1 = full resolution
    quint64 serial = 0;
    // The scene after the stages before the LUT (renderBeforeLut), when the caller has it for
    // this scene, target and options; else the worker makes it and returns it in the frame.
    std::shared_ptr<const Image> beforeLut;
    // The target's export of this source, when the caller has it; else the worker makes it.
    std::shared_ptr<const TargetLut> targetLut;
};

struct PreviewFrame {
    Image image;                     // display-encoded float RGBA, what `lutkit preview` writes
    QImage display;                  // the same as 8-bit for drawing (alpha forced opaque)
    QImage clipOverlay;              // clipped pixels marked (Scopes.h)
    Scopes scopes;                   // histogram, parade and clip counts of `display`
    double milliseconds = 0.0;       // pipeline time (the LUT part when the cache was used)
    double totalMilliseconds = 0.0;  // export LUT + pipeline + 8-bit conversion + scopes
    double targetMilliseconds = 0.0; // the export LUT (0 when the job carried it)
    double scopesMilliseconds = 0.0; // scopes and clipping overlay
    int proxyFactor = 1;
    quint64 serial = 0;
    QString error; // non-empty if the render threw; image and display are then empty
    QString report;
    bool reusedBeforeLut = false;
    // What the frame was made from, so the controller can tell a current frame from a stale one
    // and cache the before-LUT frame and the export.
    std::shared_ptr<const Image> scene;
    LutSource source;
    ExportTarget target = ExportTarget::Smash;
    PreviewOptions options;
    std::shared_ptr<const Image> beforeLut;
    std::shared_ptr<const TargetLut> targetLut;
};

// 8-bit display copy of a display-encoded float image through lut::toUnorm8.
QImage toDisplayImage(const Image& image);

// Runs the job: the target's export unless the job carries it, the before-LUT part unless the
// job carries it, the LUT part, the 8-bit copy, the scopes. Never throws: a failure comes back as
// frame->error.
std::shared_ptr<const PreviewFrame> renderFrame(const PreviewJob& job);

} // namespace lut::gui
