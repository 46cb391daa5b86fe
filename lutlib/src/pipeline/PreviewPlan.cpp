// SPDX-License-Identifier: Apache-2.0
// The preview recipe, once for both programs; see lut/pipeline/PreviewPlan.h.
#include "lut/pipeline/PreviewPlan.h"
#include "lut/pipeline/PreviewPreparation.h"

#include "lut/Parallel.h"
#include "lut/pipeline/Transfer.h"

#include <algorithm>

namespace lut {

namespace {

bool endsWithBloom(const std::string& name) {
    return name.size() >= 5 && name.compare(name.size() - 5, 5, "bloom") == 0;
}

Diagnostic info(std::string message) {
    Diagnostic d;
    d.severity = Diagnostic::Severity::Info;
    d.message = std::move(message);
    return d;
}

} // namespace

const char* toString(PreviewChain chain) {
    switch (chain) {
    case PreviewChain::Game:
        return "game";
    case PreviewChain::EncodedLut:
        return "encoded";
    case PreviewChain::EngineScene:
        return "engine";
    }
    return "game";
}

LutPurpose previewLutPurpose(Preset preset) {
    return preset == Preset::Smash ? LutPurpose::Smash : LutPurpose::Raw;
}

PreviewPlan planPreview(const PreviewRequest& q, bool stageLutGiven) {
    PreviewPlan p;
    p.scene = decideSceneKind(q.evidence, q.forced);
    const bool screenshot = p.scene.kind == SceneKind::Screenshot;
    const bool storedLinear = p.scene.storedIsLinear && !q.storedEncoded;
    if (q.preset == Preset::Smash)
        p.chain = PreviewChain::Game;
    else if (screenshot || q.preset == Preset::None)
        p.chain = PreviewChain::EncodedLut;
    else
        p.chain = PreviewChain::EngineScene;
    p.lutPurpose = previewLutPurpose(q.preset);

    PipelineSettings& s = p.settings;
    s.interpolation = q.interpolation;
    s.enable = q.enable;
    s.disable = q.disable;
    s.assignments = q.assignments;
    const bool bloomAsked = std::any_of(q.enable.begin(), q.enable.end(), endsWithBloom);
    std::string said = p.scene.reason;
    switch (p.chain) {
    case PreviewChain::Game:
        s.preset = Preset::Smash;
        p.decode = !storedLinear;
        p.undoGrading = screenshot;
        // A screenshot has the game's bloom in it already: none is added again unless asked for.
        s.bloom = q.bloom && (!screenshot || bloomAsked);
        p.bloomLeftToTheScreenshot = screenshot && q.bloom && !bloomAsked;
        if (p.bloomLeftToTheScreenshot)
            said += "; no bloom added (the screenshot has the game's; --enable bloom adds it "
                    "again)";
        break;
    case PreviewChain::EncodedLut:
        // The LUT on the frame as it is (encoded values), nothing after it: lutkit apply.
        s.preset = Preset::None;
        s.bloom = false;
        s.enable.insert(s.enable.begin(), "lut");
        s.disable.insert(s.disable.begin(), "display");
        p.decode = !screenshot && !storedLinear;
        p.displayEncode = !screenshot;
        if (screenshot && q.preset != Preset::None)
            said += std::string("; the LUT on its stored values (a screenshot has its engine's "
                                "post-processing already; --scene runs the ") +
                    toString(q.preset) + " chain on it)";
        break;
    case PreviewChain::EngineScene:
        s.preset = q.preset;
        s.bloom = q.bloom;
        p.decode = !storedLinear;
        break;
    }
    p.notes.push_back(info(said));
    if (stageLutGiven && !p.undoGrading) {
        Diagnostic ignored;
        ignored.message = screenshot ? "--original-lut is ignored: only the game's chain undoes "
                                       "the game's grading"
                                     : "--original-lut is ignored: a scene went through no "
                                       "grading";
        p.notes.push_back(ignored);
    }
    // The pipeline checks every name and value now: a bad one is an error before any frame.
    const Pipeline check(s);
    p.bloomAdded = false;
    for (const auto& stage : check.stages())
        if (stage->enabled() && endsWithBloom(stage->name()))
            p.bloomAdded = true;
    return p;
}

// The 8-bit decode goes by table: the values are exactly k / 255 (lut/formats/ImageIO.h), so the
// table gives the same floats as the per-value call at a fraction of the cost (the power function
// ran 6 million times for a 1080p frame), and the code's own float k / 255 is tabled too (a
// division per value was most of this pass). A value that is not a code takes the function.
PreviewPreparation::PreviewPreparation(const PreviewPlan& p, const Lut3D* stageLut, bool stored8Bit)
    : m_decode(p.decode), m_table(stored8Bit), m_quietBloom(p.bloomLeftToTheScreenshot) {
    for (int k = 0; k < 256; ++k) {
        m_codes[k] = static_cast<float>(k) / 255.0f;
        m_linear[k] = srgbDecode(m_codes[k]);
    }
    if (p.undoGrading)
        m_ungrader.emplace(stageLut, p.settings.interpolation);
    // A screenshot taken with the neutral stage LUT (the default): an 8-bit code's decode and
    // undo together are one table per channel (what the decode, then SmashUngrader::apply give).
    m_undoneTable = m_decode && m_table && m_ungrader && m_ungrader->neutral();
    if (m_undoneTable)
        for (int k = 0; k < 256; ++k)
            m_undone[k] = SmashUngrader::neutralChannel(m_linear[k]);
    if (p.displayEncode)
        m_display.emplace(Preset::None);
}

PreviewPreparation::~PreviewPreparation() = default;

void PreviewPreparation::apply(float* rgba, std::size_t count) const {
    if (m_undoneTable) {
        std::size_t unconverged = 0;
        float* p = rgba;
        for (std::size_t i = 0; i < count; ++i, p += 4) {
            int k[3];
            bool codes = p[3] >= 1.0f; // clamp01(alpha) >= 1, as the ungrader tests it
            for (int c = 0; c < 3; ++c) {
                k[c] = code(p[c]);
                codes = codes && k[c] >= 0;
            }
            if (codes) {
                for (int c = 0; c < 3; ++c)
                    p[c] = m_undone[k[c]];
                continue;
            }
            for (int c = 0; c < 3; ++c)  // not all 8-bit codes (or alpha < 1): step by step
                p[c] = srgbDecode(p[c]); // m_linear[k] for a code, by construction
            unconverged += m_ungrader->apply(p, 1);
        }
        m_unconverged += unconverged;
        return;
    }
    if (m_decode) {
        float* p = rgba;
        if (m_table) {
            for (std::size_t i = 0; i < count; ++i, p += 4)
                for (int c = 0; c < 3; ++c) {
                    const int k = code(p[c]);
                    p[c] = k >= 0 ? m_linear[k] : srgbDecode(p[c]);
                }
        } else {
            for (std::size_t i = 0; i < count; ++i, p += 4)
                for (int c = 0; c < 3; ++c)
                    p[c] = srgbDecode(p[c]);
        }
    }
    if (m_ungrader)
        m_unconverged += m_ungrader->apply(rgba, count);
    if (m_display)
        m_display->runPixels(rgba, count);
}

Diagnostics PreviewPreparation::notes() const {
    if (!m_ungrader)
        return {};
    Diagnostics d = ungradeNotes(m_unconverged.load());
    if (m_quietBloom) // said in the reason: no bloom added to the shot's own
        d.erase(std::remove_if(d.begin(), d.end(),
                               [](const Diagnostic& x) { return x.id == NoteId::BloomNotUndone; }),
                d.end());
    return d;
}

Diagnostics preparePreviewFrame(const PreviewPlan& p, const ImageView& frame, const Lut3D* stageLut,
                                bool stored8Bit, int nthreads) {
    const PreviewPreparation prep(p, stageLut, stored8Bit);
    if (!prep.active() || frame.empty())
        return prep.notes();
    parallelFor(frame.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            prep.apply(frame.row(y), static_cast<std::size_t>(frame.width));
    });
    return prep.notes();
}

int preparationKey(const PreviewPlan& p) {
    return (p.decode ? 1 : 0) | (p.undoGrading ? 2 : 0) | (p.displayEncode ? 4 : 0) |
           (p.scene.kind == SceneKind::Screenshot ? 8 : 0);
}

} // namespace lut
