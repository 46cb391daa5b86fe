// SPDX-License-Identifier: Apache-2.0
#include "PreviewController.h"

#include "PreviewWorker.h"

#include "lut/Downscale.h"

#include <algorithm>

namespace lut::gui {

PreviewController::PreviewController(QObject* parent)
    : QObject(parent), m_worker(new PreviewWorker(this)) {}

PreviewController::~PreviewController() = default;

template <class T> void PreviewController::retire(std::shared_ptr<T>& p) {
    m_worker->retire(std::move(p));
    p.reset();
}

int PreviewController::proxyFactorFor(int width) {
    // At most ~1000 pixels wide: what a drag needs to feel live on a 1080p frame.
    return std::max(1, (width + 999) / 1000);
}

QSize PreviewController::imageSize() const {
    return m_stored ? QSize(m_stored->width(), m_stored->height()) : QSize();
}

PreviewController::BeforeKey PreviewController::beforeKey(const PreviewOptions& o,
                                                          ExportTarget target) {
    // What the before picture depends on: a screenshot is shown as stored; a scene goes through
    // the target's chain with the neutral export (the LUT and brighten switches do not matter).
    if (o.input == SceneKind::Screenshot)
        return {};
    BeforeKey b{o, target};
    b.options.lutEnabled = true;
    b.options.brighten = true;
    return b;
}

void PreviewController::setDocument(const Document* document) {
    if (document == m_doc)
        return;
    const ExportTarget before = target();
    if (m_doc)
        disconnect(m_doc, nullptr, this, nullptr);
    m_doc = document;
    if (m_doc)
        connect(m_doc, &Document::targetChanged, this, &PreviewController::rerender);
    if (target() != before)
        rerender();
}

ExportTarget PreviewController::target() const {
    return m_doc ? m_doc->target() : ExportTarget::Smash;
}

LutSource PreviewController::jobSource() const {
    return m_options.lutEnabled ? m_source : LutSource{};
}

void PreviewController::setImage(std::shared_ptr<const Image> stored, bool storedIsFloat) {
    if (stored == m_stored)
        return;
    retire(m_stored);
    m_stored = std::move(stored);
    m_storedIsFloat = storedIsFloat;
    retire(m_scene);
    retire(m_proxy);
    m_sceneKey = -1;
    m_before = QImage();
    retire(m_frame);
    retire(m_beforeLutSource[0]);
    retire(m_beforeLutSource[1]);
    m_sceneReady = false;
    m_proxyReady = false;
    m_proxyFactor = m_stored ? proxyFactorFor(m_stored->width()) : 1;
    emit imageChanged();
    if (m_stored)
        requestScene();
    else
        requestPreview(); // the export still follows the document
}

void PreviewController::requestScene() {
    m_sceneReady = false;
    const ExportTarget target = this->target();
    const int key = scenePreparationKey(m_options, target);
    // The same preparation with other before options keeps the scene and its proxy.
    std::shared_ptr<const Image> reuse = key == m_sceneKey ? m_scene : nullptr;
    std::shared_ptr<const Image> reuseProxy = key == m_sceneKey ? m_proxy : nullptr;
    const bool firstLook = !reuse && m_proxyFactor > 1;
    if (!reuse) {
        m_proxyReady = false;
        if (firstLook)
            requestFirstLook(key);
    }
    m_worker->request(
        [this, stored = m_stored, isFloat = m_storedIsFloat, options = m_options, target, key,
         reuse, reuseProxy, firstLook, factor = m_proxyFactor]() -> PreviewWorker::Delivery {
            std::shared_ptr<const Image> scene = reuse, proxy = reuseProxy;
            QImage before;
            try {
                if (!scene)
                    scene = std::make_shared<const Image>(
                        prepareScene(*stored, isFloat, options, target));
                // After a first look its proxy stays the proxy (onSceneReady).
                if (!proxy && !firstLook)
                    proxy = factor > 1 ? std::make_shared<const Image>(downscale(*scene, factor))
                                       : scene;
                if (options.input == SceneKind::Screenshot) {
                    before = toDisplayImage(*stored); // a screenshot's before is the file
                } else {
                    const TargetLut neutral = makeTargetLut(LutSource{}, target);
                    before = toDisplayImage(
                        renderBefore(*stored, *scene, options, target, neutral.shown));
                }
            } catch (const std::exception&) {
                // Out of memory: what can be shown is shown; the frames say what failed.
                if (!scene)
                    scene = stored;
                if (!proxy && !firstLook)
                    proxy = scene;
            }
            const BeforeKey bk = beforeKey(options, target);
            return [this, stored, key, bk, scene, proxy, before] {
                onSceneReady(stored, key, bk, scene, proxy, before);
            };
        },
        PreviewWorker::Lane::Scene);
}

void PreviewController::requestFirstLook(int key) {
    // A large picture's first look, before its full-resolution scene exists (a 4K screenshot's
    // scene takes ~0.4 s of CPU): the proxy scene made from the picture reduced first, and a
    // proxy-sized before picture, so the first graded frame is a proxy render away. The proxy
    // stays; the full scene brings the full-resolution before picture.
    m_worker->request([this, stored = m_stored, isFloat = m_storedIsFloat, options = m_options,
                       target = target(), key,
                       factor = m_proxyFactor]() -> PreviewWorker::Delivery {
        std::shared_ptr<const Image> proxy;
        QImage before;
        try {
            const Image small = downscale(*stored, factor);
            proxy = std::make_shared<const Image>(prepareScene(small, isFloat, options, target));
            if (options.input == SceneKind::Screenshot) {
                before = toDisplayImage(small);
            } else {
                const TargetLut neutral = makeTargetLut(LutSource{}, target);
                before =
                    toDisplayImage(renderBefore(small, *proxy, options, target, neutral.shown));
            }
        } catch (const std::exception&) {
            return {}; // the full scene still comes, or says what failed
        }
        return [this, stored, key, proxy, before] {
            if (stored != m_stored || key != scenePreparationKey(m_options, this->target()) ||
                m_sceneReady)
                return; // replaced meanwhile, or the full scene came first
            m_proxy = proxy;
            m_proxyReady = true;
            if (m_before.isNull() || m_before.size() == before.size()) {
                m_before = before;
                emit beforeReady(m_before);
            }
            requestPreview();
        };
    });
}

void PreviewController::onSceneReady(const std::shared_ptr<const Image>& stored, int key,
                                     const BeforeKey& before,
                                     const std::shared_ptr<const Image>& scene,
                                     const std::shared_ptr<const Image>& proxy,
                                     const QImage& beforeImage) {
    if (stored != m_stored || key != scenePreparationKey(m_options, target()) ||
        !(before == beforeKey(m_options, target())))
        return; // replaced meanwhile: a newer request is on its way
    if (scene != m_scene) {
        retire(m_beforeLutSource[0]);
        retire(m_beforeLutSource[1]);
    }
    // A first look's proxy stays the proxy: its frame on screen stays current (no second proxy
    // frame before the full one). Without one (it failed), the scene is its own proxy.
    const std::shared_ptr<const Image> keptProxy =
        proxy ? proxy : (m_proxyReady && m_proxy ? m_proxy : scene);
    if (keptProxy != m_proxy)
        retire(m_beforeLutSource[1]);
    retire(m_scene);
    m_scene = scene;
    m_proxy = keptProxy;
    m_sceneKey = key;
    m_sceneBefore = before;
    if (m_proxy == scene)
        m_proxyFactor = 1;
    m_before = beforeImage;
    m_sceneReady = true;
    m_proxyReady = true;
    emit beforeReady(m_before);
    requestPreview();
}

void PreviewController::setSource(LutSource source) {
    if (source == m_source)
        return;
    m_source = std::move(source);
    requestPreview();
}

void PreviewController::setOptions(const PreviewOptions& options) {
    if (options == m_options)
        return;
    m_options = options;
    emit optionsChanged(m_options);
    rerender();
}

void PreviewController::rerender() {
    if (m_stored && (scenePreparationKey(m_options, target()) != m_sceneKey ||
                     !(beforeKey(m_options, target()) == m_sceneBefore)))
        requestScene();
    else
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
    if (frame.proxyFactor > 1 ? !m_proxyReady : !m_sceneReady)
        return false;
    const auto& scene = frame.proxyFactor > 1 ? m_proxy : m_scene;
    return frame.scene && frame.scene == scene && frame.source == jobSource() &&
           frame.target == target() && frame.options == m_options;
}

std::shared_ptr<const TargetLut> PreviewController::targetLut() const {
    if (m_target && m_targetSource == jobSource() && m_targetKind == target())
        return m_target;
    return nullptr;
}

std::shared_ptr<const Image>
PreviewController::cachedBeforeLut(const std::shared_ptr<const Image>& scene,
                                   const PreviewOptions& options, ExportTarget target) const {
    const auto& cached = m_beforeLutSource[scene == m_scene ? 0 : 1];
    if (!cached || cached->scene != scene)
        return nullptr;
    if ((cached->options == options && cached->target == target) ||
        sameBeforeLut(cached->options, cached->target, options, target))
        return cached->beforeLut;
    return nullptr;
}

PreviewJob PreviewController::makeJob(bool proxy) const {
    PreviewJob j;
    j.target = target();
    if (m_stored && (proxy ? m_proxyReady : m_sceneReady)) {
        j.scene = proxy ? m_proxy : m_scene;
        j.proxyFactor = proxy ? m_proxyFactor : 1;
        j.beforeLut = cachedBeforeLut(j.scene, m_options, j.target);
    }
    j.source = jobSource();
    j.options = m_options;
    j.targetLut = targetLut();
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
    if (!m_stored) {
        if (!targetLut())
            submit(makeJob(false)); // no picture: the export alone (clipping count, LUT dock)
        return;
    }
    if (!m_sceneReady) {
        // Only the first look of a large picture: its proxy frame (the scene's delivery asks for
        // the full frame).
        if (m_proxyReady && !(m_frame && m_frame->proxyFactor > 1 && isCurrent(*m_frame)))
            submit(makeJob(true));
        return;
    }
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
    if (frame->targetLut && frame->targetLut != m_target && frame->source == jobSource() &&
        frame->target == target()) {
        m_target = frame->targetLut;
        m_targetSource = frame->source;
        m_targetKind = frame->target;
        emit targetLutChanged(m_target);
    }
    if (!frame->scene || !(m_sceneReady || m_proxyReady) ||
        (frame->scene != m_scene && frame->scene != m_proxy))
        return; // no picture, or made for an image or scene that was replaced meanwhile
    if (frame->error.isEmpty()) {
        retire(m_frame);
        m_frame = frame;
        if (frame->beforeLut && !frame->reusedBeforeLut) {
            retire(m_beforeLutSource[frame->proxyFactor > 1 ? 1 : 0]);
            m_beforeLutSource[frame->proxyFactor > 1 ? 1 : 0] = frame;
        }
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
    waitForIdle();
    if (!m_stored) {
        if (!targetLut()) {
            submit(makeJob(false));
            waitForIdle();
        }
        return;
    }
    if (!m_sceneReady)
        return; // the scene failed: nothing more will come
    if (!m_frame || m_frame->proxyFactor != 1 || !isCurrent(*m_frame)) {
        // The latest frame was a proxy, or failed: ask for (and wait for) a full-resolution one.
        m_interactive = false;
        submit(makeJob(false));
        waitForIdle();
    }
}

bool PreviewController::hasFullResolutionFrame() const {
    return m_frame && m_frame->proxyFactor == 1 && isCurrent(*m_frame);
}

std::function<Image(const Progress&)> PreviewController::fullResolutionRenderer() const {
    if (!m_stored)
        return [](const Progress&) { return Image(); };
    if (hasFullResolutionFrame())
        return [frame = m_frame](const Progress&) { return frame->image; };
    std::shared_ptr<const Image> scene = m_sceneReady ? m_scene : nullptr;
    const ExportTarget target = this->target();
    std::shared_ptr<const Image> beforeLut =
        scene ? cachedBeforeLut(scene, m_options, target) : nullptr;
    return [stored = m_stored, isFloat = m_storedIsFloat, options = m_options, target, scene,
            beforeLut, targetLut = targetLut(), source = jobSource()](const Progress& progress) {
        std::shared_ptr<const Image> s = scene, b = beforeLut;
        if (!s)
            s = std::make_shared<const Image>(prepareScene(*stored, isFloat, options, target));
        progress.check("preview");
        if (!b)
            b = std::make_shared<const Image>(renderBeforeLut(*s, options, target));
        progress.check("preview");
        auto t = targetLut ? targetLut
                           : std::make_shared<const TargetLut>(makeTargetLut(source, target));
        progress.check("preview");
        return renderFromLut(*b, options, target, t->shown).image;
    };
}

Image PreviewController::renderFullResolution() const {
    return fullResolutionRenderer()(Progress());
}

} // namespace lut::gui
