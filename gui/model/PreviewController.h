// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor's preview without widgets: the options, the document's export target, the stored image
// and its prepared scene and proxy, the before picture, the before-LUT cache, the target's export
// (the LUT the preview grades with), the worker thread, the frames and their timings. The window
// gives it the image and the document's LUT source and draws what it delivers; tests drive it
// headless.
//
// What runs where: on a new image, or options that change how the scene is prepared, the worker
// prepares the scene (PreviewRenderer.h: ungrade, decode...), its proxy (lut::downscale, at most
// ~1000 px wide) and the "before" picture; then each change renders on the worker, the proxy
// first unless the worker is busy, then (unless a slider is held) the full-resolution frame. A
// picture larger than its proxy gets a first look before that: the picture reduced, then
// prepared, gives a proxy scene and a proxy-sized before picture within a few tens of ms (a 4K
// screenshot's full scene takes ~0.4 s of CPU), so the first graded frame is a proxy render
// away. That proxy stays the proxy (for a linear scene it is the full scene reduced, bit for bit;
// for a screenshot the reduction comes before the ungrading); the full scene and before picture
// follow. A
// render first makes the target's export of the document (ExportTarget.h, cached while the
// document and target stay; the target is the document's, read when a job is made, and a change
// of it re-renders), then the pipeline; the stages before the LUT are cached per scene
// (full and proxy) and reused while lut::Pipeline::sameBeforeLut says they still apply, so a LUT
// edit re-runs only the LUT part. The UI thread never renders.
#include "Document.h"
#include "PreviewFrame.h"
#include "PreviewRenderer.h"

#include "lut/Progress.h"

#include <QImage>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QSize>

#include <functional>
#include <memory>

namespace lut::gui {

class PreviewWorker;

class PreviewController : public QObject {
    Q_OBJECT
public:
    explicit PreviewController(QObject* parent = nullptr);
    ~PreviewController() override;

    // ---- inputs --------------------------------------------------------------------------
    // The stored pixels of the opened picture (null = no image) and whether the file held floats
    // (lut::formats::ImageInfo::isFloat). A new image drops the frames, the caches and the before
    // picture (imageChanged); the worker then prepares the scene and the first frames.
    void setImage(std::shared_ptr<const Image> stored, bool storedIsFloat);
    // The document whose export target the preview grades for (Document::target), followed on
    // Document::targetChanged; without one (null), the Smash target.
    void setDocument(const Document* document);
    ExportTarget target() const;
    void setSource(LutSource source);
    const LutSource& source() const { return m_source; }
    const PreviewOptions& options() const { return m_options; }
    void setOptions(const PreviewOptions& options);
    // True while a slider is held: proxy frames only; on release the full frame follows.
    void setInteractive(bool on);
    bool isInteractive() const { return m_interactive; }

    // ---- state ---------------------------------------------------------------------------
    std::shared_ptr<const Image> storedImage() const { return m_stored; }
    QSize imageSize() const;
    // The scene the pipeline starts from for the current options (null until the worker made
    // it), its proxy (the scene itself when small enough) and the proxy's reduction factor.
    std::shared_ptr<const Image> scene() const { return m_sceneReady ? m_scene : nullptr; }
    std::shared_ptr<const Image> proxyScene() const { return m_sceneReady ? m_proxy : nullptr; }
    int proxyFactor() const { return m_proxyFactor; }
    static int proxyFactorFor(int width);
    // The input as the user knows it, 8-bit (PreviewRenderer.h renderBefore; null until made).
    const QImage& beforeImage() const { return m_before; }
    // The latest frame delivered for the current image (a proxy or full resolution; null after
    // an image change). Failed renders do not replace it.
    std::shared_ptr<const PreviewFrame> currentFrame() const { return m_frame; }
    // Whether the frame was made from the current scene (or its proxy), source, target and
    // options.
    bool isCurrent(const PreviewFrame& frame) const;
    // The target's export of the current source (null until the worker made it).
    std::shared_ptr<const TargetLut> targetLut() const;
    // Total times (ms) of the last full-resolution frames, oldest first (at most 1000).
    const QList<double>& fullResolutionTimes() const { return m_times; }

    // ---- waiting and rendering on the calling thread -----------------------------------
    bool isBusy() const;
    // Processes events until the worker has nothing running or pending.
    void waitForIdle();
    // Processes events until a current full-resolution frame is delivered (or failed), asking
    // for one if the latest frame is a proxy. Without an image, until the export is made.
    void waitForFullResolution();
    // The full-resolution preview for the current state, bit for bit what the CLI computes: the
    // current frame's image when it is that, else rendered on the calling thread (with the
    // caches when they apply). Empty without an image.
    Image renderFullResolution() const;
    // The same as a function that may run on any thread (it holds what it needs, so the
    // controller may change meanwhile): the current frame's image when it is that, else a render
    // that checks `progress` between its steps (lut::CancelledError). Empty without an image.
    std::function<Image(const Progress& progress)> fullResolutionRenderer() const;
    // Whether the current frame already is the full-resolution preview (nothing to render).
    bool hasFullResolutionFrame() const;

signals:
    void imageChanged(); // a new image (imageSize(); empty: no image)
    void beforeReady(const QImage& before);
    // Every render the worker finishes for the current image; frame->error says if it failed.
    void frameReady(std::shared_ptr<const lut::gui::PreviewFrame> frame);
    void optionsChanged(const lut::gui::PreviewOptions& options);
    // A new export of the current source and the document's target (the clipping count, the LUT
    // dock).
    void targetLutChanged(std::shared_ptr<const lut::gui::TargetLut> target);

private:
    // What the before picture depends on (a screenshot's: nothing but the file).
    struct BeforeKey {
        PreviewOptions options;
        ExportTarget target = ExportTarget::Smash;
        bool operator==(const BeforeKey&) const = default;
    };
    static BeforeKey beforeKey(const PreviewOptions& options, ExportTarget target);
    LutSource jobSource() const; // the document's source, or neutral when the LUT is off
    // Lets go of a large frame, scene or picture: freed on the worker (PreviewWorker::retire).
    template <class T> void retire(std::shared_ptr<T>& p);
    void requestScene();
    void requestFirstLook(int key);
    void onSceneReady(const std::shared_ptr<const Image>& stored, int key, const BeforeKey& before,
                      const std::shared_ptr<const Image>& scene,
                      const std::shared_ptr<const Image>& proxy, const QImage& beforeImage);
    void requestPreview();
    // Options or target changed: a new scene when its preparation or before picture changed.
    void rerender();
    PreviewJob makeJob(bool proxy) const;
    void submit(PreviewJob job);
    void onFrame(const std::shared_ptr<const PreviewFrame>& frame);
    std::shared_ptr<const Image> cachedBeforeLut(const std::shared_ptr<const Image>& scene,
                                                 const PreviewOptions& options,
                                                 ExportTarget target) const;

    PreviewWorker* m_worker;
    PreviewOptions m_options;
    QPointer<const Document> m_doc;
    LutSource m_source;
    std::shared_ptr<const Image> m_stored;
    bool m_storedIsFloat = false;
    // The prepared scene, made for scene key m_sceneKey and before picture key m_sceneBefore.
    std::shared_ptr<const Image> m_scene;
    std::shared_ptr<const Image> m_proxy;
    int m_sceneKey = -1;
    BeforeKey m_sceneBefore;
    int m_proxyFactor = 1;
    bool m_sceneReady = false; // the worker delivered the scene for the current options
    bool m_proxyReady = false; // ... or at least its proxy (a large picture's first look)
    bool m_interactive = false;
    QImage m_before;
    std::shared_ptr<const PreviewFrame> m_frame;
    // The last frames whose before-LUT part the worker computed, full scene [0] and proxy [1].
    std::shared_ptr<const PreviewFrame> m_beforeLutSource[2];
    // The last export made by the worker, with what it was made from.
    std::shared_ptr<const TargetLut> m_target;
    LutSource m_targetSource;
    ExportTarget m_targetKind = ExportTarget::Smash;
    quint64 m_serial = 0;
    QList<double> m_times;
};

} // namespace lut::gui
