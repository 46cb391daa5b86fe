#pragma once
// The editor's preview without widgets: the options, the scene and its proxy, the before-LUT
// cache, the worker thread, the frames and their timings. The window gives it the scene and the
// LUT (from the Document) and draws what it delivers; tests drive it headless.
//
// What runs where: on a new scene the worker makes the proxy (lut::downscale, at most ~1000 px
// wide) and the "before" picture; then each change renders on the worker, the proxy first unless
// the worker is busy, then (unless a slider is held) the full-resolution frame. The stages before
// the LUT are cached per scene (full and proxy) and reused while lut::Pipeline::sameBeforeLut
// says they still apply, so a LUT edit re-runs only the LUT part. The UI thread never renders.
#include "PreviewFrame.h"
#include "PreviewRenderer.h"

#include <QImage>
#include <QList>
#include <QObject>

#include <memory>

namespace lut::gui {

class PreviewWorker;

class PreviewController : public QObject {
    Q_OBJECT
public:
    explicit PreviewController(QObject* parent = nullptr);
    ~PreviewController() override;

    // ---- inputs --------------------------------------------------------------------------
    // The prepared linear scene (Document::sceneImage), null = no image. A new scene drops the
    // frames, the caches and the before picture (sceneChanged); the worker then makes the proxy
    // and the before picture (beforeReady) and the first frames.
    void setScene(std::shared_ptr<const Image> scene);
    void setLut(std::shared_ptr<const Lut3D> lut); // null = neutral
    const PreviewOptions& options() const { return m_options; }
    void setOptions(const PreviewOptions& options);
    // True while a slider is held: proxy frames only; on release the full frame follows.
    void setInteractive(bool on);
    bool isInteractive() const { return m_interactive; }

    // ---- state ---------------------------------------------------------------------------
    std::shared_ptr<const Image> scene() const { return m_scene; }
    std::shared_ptr<const Lut3D> lut() const { return m_lut; }
    // The proxy the worker made for the scene (null until then; the scene itself when the scene
    // is small enough), and its reduction factor.
    std::shared_ptr<const Image> proxyScene() const { return m_proxy; }
    int proxyFactor() const { return m_proxyFactor; }
    static int proxyFactorFor(int width);
    // The scene with only the display encoding, 8-bit (null until the worker made it).
    const QImage& beforeImage() const { return m_before; }
    // The latest frame delivered for the current scene (a proxy or full resolution; null after
    // a scene change). Failed renders do not replace it.
    std::shared_ptr<const PreviewFrame> currentFrame() const { return m_frame; }
    // Whether the frame was made from the current scene (or its proxy), LUT and options.
    bool isCurrent(const PreviewFrame& frame) const;
    // Total times (ms) of the last full-resolution frames, oldest first (at most 1000).
    const QList<double>& fullResolutionTimes() const { return m_times; }

    // ---- waiting and rendering on the calling thread -----------------------------------
    bool isBusy() const;
    // Processes events until the worker has nothing running or pending.
    void waitForIdle();
    // Processes events until a current full-resolution frame is delivered (or failed), asking
    // for one if the latest frame is a proxy. Returns at once without a scene.
    void waitForFullResolution();
    // The full-resolution preview for the current state, bit for bit what `lutkit preview`
    // computes: the current frame's image when it is that, else rendered on the calling thread
    // (with the cached before-LUT frame when it applies). Empty without a scene.
    Image renderFullResolution() const;

signals:
    void sceneChanged(); // the new scene's size is scene()->width()/height() (null: no image)
    void beforeReady(const QImage& before);
    // Every render the worker finishes for the current scene; frame->error says if it failed.
    void frameReady(std::shared_ptr<const lut::gui::PreviewFrame> frame);
    void optionsChanged(const lut::gui::PreviewOptions& options);

private:
    void requestPreview();
    PreviewJob makeJob(bool proxy);
    void submit(PreviewJob job);
    void onSceneReady(const std::shared_ptr<const Image>& scene,
                      const std::shared_ptr<const Image>& proxy, const QImage& before);
    void onFrame(const std::shared_ptr<const PreviewFrame>& frame);
    // The cached before-LUT frame for `scene` that applies to `options`, or null.
    std::shared_ptr<const Image> cachedBeforeLut(const std::shared_ptr<const Image>& scene,
                                                 const PreviewOptions& options) const;

    PreviewWorker* m_worker;
    PreviewOptions m_options;
    std::shared_ptr<const Image> m_scene;
    std::shared_ptr<const Image> m_proxy;
    std::shared_ptr<const Lut3D> m_lut;
    int m_proxyFactor = 1;
    bool m_sceneReady = false; // the worker delivered the proxy and the before picture
    bool m_interactive = false;
    QImage m_before;
    std::shared_ptr<const PreviewFrame> m_frame;
    // The last frames whose before-LUT part the worker computed, full scene [0] and proxy [1].
    std::shared_ptr<const PreviewFrame> m_beforeLutSource[2];
    quint64 m_serial = 0;
    QList<double> m_times;
};

} // namespace lut::gui
