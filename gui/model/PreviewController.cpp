#include "PreviewController.h"

#include "PreviewWorker.h"

#include "lut/Downscale.h"

#include <algorithm>

namespace lut::gui {

PreviewController::PreviewController(QObject* parent)
    : QObject(parent), m_worker(new PreviewWorker(this)) {}

PreviewController::~PreviewController() = default;

int PreviewController::proxyFactorFor(int width) {
    // At most ~1000 pixels wide: what a drag needs to feel live on a 1080p frame.
    return std::max(1, (width + 999) / 1000);
}

void PreviewController::setScene(std::shared_ptr<const Image> scene) {
    if (scene == m_scene)
        return;
    m_scene = std::move(scene);
    m_proxy.reset();
    m_before = QImage();
    m_frame.reset();
    m_beforeLutSource[0].reset();
    m_beforeLutSource[1].reset();
    m_sceneReady = false;
    m_proxyFactor = m_scene ? proxyFactorFor(m_scene->width()) : 1;
    emit sceneChanged();
    if (!m_scene)
        return;
    m_worker->request([this, scene = m_scene, factor = m_proxyFactor]() -> PreviewWorker::Delivery {
        std::shared_ptr<const Image> proxy = scene;
        QImage before;
        try {
            if (factor > 1)
                proxy = std::make_shared<const Image>(downscale(*scene, factor));
            before = toDisplayImage(renderBefore(*scene));
        } catch (const std::exception&) {
            proxy = scene; // out of memory: no proxy; the frames say what failed
        }
        return [this, scene, proxy, before] { onSceneReady(scene, proxy, before); };
    });
}

void PreviewController::onSceneReady(const std::shared_ptr<const Image>& scene,
                                     const std::shared_ptr<const Image>& proxy,
                                     const QImage& before) {
    if (scene != m_scene)
        return; // an image that was replaced meanwhile
    m_proxy = proxy;
    if (proxy == scene)
        m_proxyFactor = 1;
    m_before = before;
    m_sceneReady = true;
    emit beforeReady(m_before);
    requestPreview();
}

void PreviewController::setLut(std::shared_ptr<const Lut3D> lut) {
    if (lut == m_lut)
        return;
    m_lut = std::move(lut);
    requestPreview();
}

void PreviewController::setOptions(const PreviewOptions& options) {
    if (options == m_options)
        return;
    m_options = options;
    emit optionsChanged(m_options);
    requestPreview();
}

void PreviewController::setInteractive(bool on) {
    if (m_interactive == on)
        return;
    m_interactive = on;
    if (!on)
        requestPreview(); // the full-resolution frame after the drag
}

bool PreviewController::isCurrent(const PreviewFrame& frame) const {
    const auto& scene = frame.proxyFactor > 1 ? m_proxy : m_scene;
    return frame.scene && frame.scene == scene && frame.lut == m_lut && frame.options == m_options;
}

std::shared_ptr<const Image>
PreviewController::cachedBeforeLut(const std::shared_ptr<const Image>& scene,
                                   const PreviewOptions& options) const {
    const auto& cached = m_beforeLutSource[scene == m_scene ? 0 : 1];
    if (!cached || cached->scene != scene)
        return nullptr;
    if (cached->options == options || sameBeforeLut(cached->options, options))
        return cached->beforeLut;
    return nullptr;
}

PreviewJob PreviewController::makeJob(bool proxy) {
    PreviewJob j;
    j.scene = proxy ? m_proxy : m_scene;
    j.proxyFactor = proxy ? m_proxyFactor : 1;
    j.lut = m_lut;
    j.options = m_options;
    j.beforeLut = cachedBeforeLut(j.scene, j.options);
    return j;
}

void PreviewController::submit(PreviewJob job) {
    job.serial = ++m_serial;
    m_worker->request([this, job = std::move(job)]() -> PreviewWorker::Delivery {
        auto frame = renderFrame(job);
        return [this, frame] { onFrame(frame); };
    });
}

void PreviewController::requestPreview() {
    if (!m_scene || !m_sceneReady)
        return; // the scene's delivery asks for the first frames
    // The proxy first, so a change shows within a proxy render (unless the proxy of this very
    // state is on screen: a slider released where the last drag frame was); then, unless a
    // slider is still held, the full frame, which a newer request may replace before it starts.
    const bool proxyShown = m_frame && m_frame->proxyFactor > 1 && isCurrent(*m_frame);
    if (m_proxyFactor > 1 && (m_interactive || !m_worker->isBusy()) && !proxyShown)
        submit(makeJob(true));
    if (!m_interactive || m_proxyFactor == 1)
        submit(makeJob(false));
}

void PreviewController::onFrame(const std::shared_ptr<const PreviewFrame>& frame) {
    if (!frame->scene || (frame->scene != m_scene && frame->scene != m_proxy))
        return; // made for an image that was replaced meanwhile
    if (frame->error.isEmpty()) {
        m_frame = frame;
        if (frame->beforeLut && !frame->reusedBeforeLut)
            m_beforeLutSource[frame->proxyFactor > 1 ? 1 : 0] = frame;
        if (frame->proxyFactor == 1) {
            m_times.append(frame->totalMilliseconds);
            if (m_times.size() > 1000)
                m_times.removeFirst();
        }
    }
    emit frameReady(frame);
}

bool PreviewController::isBusy() const {
    return m_worker->isBusy();
}

void PreviewController::waitForIdle() {
    m_worker->waitForIdle();
}

void PreviewController::waitForFullResolution() {
    if (!m_scene)
        return;
    waitForIdle();
    if (!m_frame || m_frame->proxyFactor != 1 || !isCurrent(*m_frame)) {
        // The latest frame was a proxy, or failed: ask for (and wait for) a full-resolution one.
        m_interactive = false;
        if (m_sceneReady)
            submit(makeJob(false));
        waitForIdle();
    }
}

Image PreviewController::renderFullResolution() const {
    if (!m_scene)
        return {};
    if (m_frame && m_frame->proxyFactor == 1 && isCurrent(*m_frame))
        return m_frame->image;
    auto beforeLut = cachedBeforeLut(m_scene, m_options);
    if (!beforeLut)
        beforeLut = std::make_shared<const Image>(renderBeforeLut(*m_scene, m_options));
    return renderFromLut(*beforeLut, m_options, m_lut).image;
}

} // namespace lut::gui
