// SPDX-License-Identifier: Apache-2.0
// The preview recipe, once for both programs; see lut/pipeline/PreviewPlan.h.
#include "lut/pipeline/PreviewPlan.h"

#include "lut/Parallel.h"
#include "lut/pipeline/Transfer.h"

#include <algorithm>

namespace lut {

namespace {

constexpr const char* kBloomNotUndone = "bloom cannot be undone";

bool endsWithBloom(const std::string& name) {
    return name.size() >= 5 && name.compare(name.size() - 5, 5, "bloom") == 0;
}

Diagnostic info(std::string message) {
    Diagnostic d;
    d.severity = Diagnostic::Severity::Info;
    d.message = std::move(message);
    return d;
}

// lut::srgbDecode of every R, G, B of a frame read from an 8-bit file, by table: the values are
// exactly k / 255 (lut/formats/ImageIO.h), so the table gives the same floats as the per-value
// call at a fraction of the cost (the power function ran 6 million times for a 1080p frame). The
// code's own float k / 255 is tabled too (a division per value was most of this pass), and the
// rows are shared among the threads (one thread took 10-19 ms of a 1080p preview).
void decodeSrgbCodes8(const ImageView& frame, int nthreads) {
    float table[256];
    float codes[256];
    for (int k = 0; k < 256; ++k) {
        codes[k] = static_cast<float>(k) / 255.0f;
        table[k] = srgbDecode(codes[k]);
    }
    parallelFor(frame.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* p = frame.row(y);
            for (int x = 0; x < frame.width; ++x, p += 4)
                for (int c = 0; c < 3; ++c) {
                    const float v = p[c];
                    const int k = static_cast<int>(v * 255.0f + 0.5f);
                    p[c] = k >= 0 && k < 256 && codes[k] == v ? table[k] : srgbDecode(v);
                }
        }
    });
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

Diagnostics preparePreviewFrame(const PreviewPlan& p, const ImageView& frame, const Lut3D* stageLut,
                                bool stored8Bit, int nthreads) {
    Diagnostics d;
    if (p.decode) {
        if (stored8Bit)
            decodeSrgbCodes8(frame, nthreads); // exact: 8-bit values are k/255
        else
            srgbDecode(frame, nthreads);
    }
    if (p.undoGrading) {
        d = prepareSceneFrame(frame, true, true, stageLut, p.settings.interpolation, nthreads);
        if (p.bloomLeftToTheScreenshot) // said in the reason: no bloom added to the shot's own
            d.erase(std::remove_if(d.begin(), d.end(),
                                   [](const Diagnostic& x) {
                                       return x.message.rfind(kBloomNotUndone, 0) == 0;
                                   }),
                    d.end());
    }
    if (p.displayEncode) {
        Pipeline none(Preset::None);
        RunOptions run;
        run.nthreads = nthreads;
        none.run(frame, run);
    }
    return d;
}

int preparationKey(const PreviewPlan& p) {
    return (p.decode ? 1 : 0) | (p.undoGrading ? 2 : 0) | (p.displayEncode ? 4 : 0) |
           (p.scene.kind == SceneKind::Screenshot ? 8 : 0);
}

} // namespace lut
