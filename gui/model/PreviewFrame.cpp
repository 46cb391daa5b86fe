// SPDX-License-Identifier: Apache-2.0
#include "PreviewFrame.h"

#include "lut/Parallel.h"
#include "lut/Quantize.h"

#include <QElapsedTimer>

namespace lut::gui {

QImage toDisplayImage(const Image& image) {
    QImage out(image.width(), image.height(), QImage::Format_RGBX8888);
    const int w = image.width();
    uchar* const bits = out.bits(); // detached once here, not per row from the threads
    const std::size_t stride = static_cast<std::size_t>(out.bytesPerLine());
    parallelFor(image.height(), 0, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* src = image.pixel(0, y);
            uchar* dst = bits + stride * static_cast<std::size_t>(y);
            for (int x = 0; x < w; ++x) {
                dst[4 * x + 0] = toUnorm8(src[4 * x + 0]);
                dst[4 * x + 1] = toUnorm8(src[4 * x + 1]);
                dst[4 * x + 2] = toUnorm8(src[4 * x + 2]);
                dst[4 * x + 3] = 255;
            }
        }
    });
    return out;
}

std::shared_ptr<const PreviewFrame> renderFrame(const PreviewJob& job) {
    auto frame = std::make_shared<PreviewFrame>();
    frame->proxyFactor = job.proxyFactor;
    frame->serial = job.serial;
    frame->scene = job.scene;
    frame->source = job.source;
    frame->target = job.target;
    frame->options = job.options;
    QElapsedTimer timer;
    timer.start();
    try {
        frame->targetLut =
            job.targetLut
                ? job.targetLut
                : std::make_shared<const TargetLut>(makeTargetLut(job.source, job.target));
        frame->targetMilliseconds = static_cast<double>(timer.nsecsElapsed()) / 1e6;
        if (job.scene && !job.scene->empty()) {
            frame->reusedBeforeLut = job.beforeLut != nullptr;
            frame->beforeLut = job.beforeLut ? job.beforeLut
                                             : std::make_shared<const Image>(renderBeforeLut(
                                                   *job.scene, job.options, job.target));
            PreviewResult r =
                renderFromLut(*frame->beforeLut, job.options, job.target, frame->targetLut->shown);
            frame->image = std::move(r.image);
            frame->milliseconds = r.milliseconds;
            frame->report = QString::fromStdString(r.report);
            frame->display = toDisplayImage(frame->image);
            const qint64 scopesStart = timer.nsecsElapsed();
            frame->scopes = computeScopes(frame->display);
            frame->clipOverlay = clipOverlay(frame->display);
            frame->scopesMilliseconds =
                static_cast<double>(timer.nsecsElapsed() - scopesStart) / 1e6;
        }
    } catch (const std::exception& e) {
        frame->error = QString::fromUtf8(e.what());
        frame->image = Image();
        frame->display = QImage();
    }
    frame->totalMilliseconds = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    return frame;
}

} // namespace lut::gui
