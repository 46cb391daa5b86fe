// SPDX-License-Identifier: Apache-2.0
#include "lut/pipeline/Pipeline.h"

#include "StageDetail.h"
#include "lut/pipeline/Transfer.h"
#include "lut/smash/SmashGrading.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <mutex>
#include <sstream>

namespace lut {

const char* toString(Preset p) {
    switch (p) {
    case Preset::Smash:
        return "smash";
    case Preset::Pilot:
        return "filmic";
    case Preset::Lecture:
        return "cinematic";
    case Preset::None:
        return "none";
    }
    return "?";
}

std::vector<std::string> presetAliases(Preset p) {
    switch (p) {
    case Preset::Pilot:
        return {"pilot"};
    case Preset::Lecture:
        return {"lecture"};
    case Preset::Smash:
    case Preset::None:
        break;
    }
    return {};
}

const char* describe(Preset p) {
    switch (p) {
    case Preset::Smash:
        return "Smash Ultimate's chain: its bloom, its grading LUT with brighten, sRGB";
    case Preset::Pilot:
        return "tone mapping (ACES) and a soft bloom, the LUT, gamma 2.2";
    case Preset::Lecture:
        return "exposure, HDR bloom, chromatic aberration, vignette, grain, the LUT, gamma 2.2";
    case Preset::None:
        return "display encoding only";
    }
    return "";
}

const std::vector<Preset>& allPresets() {
    static const std::vector<Preset> presets = {Preset::Smash, Preset::Pilot, Preset::Lecture,
                                                Preset::None};
    return presets;
}

Preset parsePreset(std::string_view n) {
    std::string names, aliases;
    for (const Preset p : allPresets()) {
        if (n == toString(p))
            return p;
        for (const std::string& alias : presetAliases(p)) {
            if (n == alias)
                return p;
            aliases += (aliases.empty() ? "" : ", ") + alias;
        }
        names += (names.empty() ? "" : ", ") + std::string(toString(p));
    }
    throw Error("unknown preset '" + std::string(n) + "' (expected " + names + "; also " + aliases +
                ")");
}

namespace {

using Factory = std::unique_ptr<Stage> (*)();
struct Entry {
    const char* name;
    Factory make;
};
const Entry kStages[] = {
    {"sanitize", detail::makeSanitizeStage},
    {"exposure", detail::makeExposureStage},
    {"tonemap", detail::makeTonemapStage},
    {"hdr-bloom", detail::makeHdrBloomStage},
    {"soft-bloom", detail::makeFilterBloomStage},
    {"glow-bloom", detail::makeSugarBloomStage},
    {"smash-bloom", detail::makeSmashBloomStage},
    {"chromatic-aberration", detail::makeChromaticAberrationStage},
    {"vignette", detail::makeVignetteStage},
    {"grain", detail::makeGrainStage},
    {"smash-grade", detail::makeSmashGradeStage},
    {"lut", detail::makeLutStage},
    {"display", detail::makeDisplayStage},
};

// Older stage names, still accepted wherever a stage is named.
const std::vector<std::pair<std::string, std::string>> kStageAliases = {
    {"filter-bloom", "soft-bloom"},
    {"sugar-bloom", "glow-bloom"},
};

bool isBloom(std::string_view n) {
    return n.size() >= 5 && n.substr(n.size() - 5) == "bloom";
}

std::vector<std::string> presetStages(Preset p) {
    switch (p) {
    case Preset::Smash:
        return {"sanitize", "smash-bloom", "smash-grade", "display"};
    case Preset::Pilot:
        return {"sanitize", "tonemap", "soft-bloom", "lut", "display"};
    case Preset::Lecture:
        return {"sanitize", "exposure", "hdr-bloom", "chromatic-aberration",
                "vignette", "grain",    "lut",       "display"};
    case Preset::None:
        return {"sanitize", "display"};
    }
    return {};
}

} // namespace

const std::vector<std::string>& stageNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const auto& e : kStages)
            v.emplace_back(e.name);
        return v;
    }();
    return names;
}

const std::vector<std::pair<std::string, std::string>>& stageAliases() {
    return kStageAliases;
}

std::string_view canonicalStageName(std::string_view name) {
    for (const auto& [alias, stage] : kStageAliases)
        if (name == alias)
            return stage;
    return name;
}

std::unique_ptr<Stage> makeStage(std::string_view name) {
    name = canonicalStageName(name);
    for (const auto& e : kStages)
        if (name == e.name)
            return e.make();
    std::string list;
    for (const auto& e : kStages)
        list += (list.empty() ? "" : ", ") + std::string(e.name);
    throw Error("unknown stage '" + std::string(name) + "' (stages: " + list + ")");
}

Pipeline::Pipeline() : Pipeline(Preset::None) {}

Pipeline::Pipeline(Preset preset) : m_preset(preset) {
    const auto on = presetStages(preset);
    for (const auto& e : kStages) {
        auto s = e.make();
        s->setEnabled(std::find(on.begin(), on.end(), e.name) != on.end());
        m_stages.push_back(std::move(s));
    }
    if (preset == Preset::Pilot) {
        stage("tonemap").setParam("curve", "aces");
        stage("display").setParam("curve", "gamma");
    } else if (preset == Preset::Lecture) {
        stage("display").setParam("curve", "gamma");
    }
}

Pipeline::Pipeline(const PipelineSettings& s) : Pipeline(s.preset) {
    setLut(s.lut, s.interpolation, s.shaper);
    if (!s.bloom)
        setBloom(false);
    for (const auto& n : s.enable)
        setEnabled(n, true);
    for (const auto& n : s.disable)
        setEnabled(n, false);
    for (const auto& a : s.assignments)
        assign(a);
}

Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

Stage* Pipeline::find(std::string_view name) {
    return const_cast<Stage*>(static_cast<const Pipeline*>(this)->find(name));
}

const Stage* Pipeline::find(std::string_view name) const {
    if (name == "bloom") {
        // The preset's bloom: the first enabled bloom stage, else the preset's natural one.
        for (const auto& s : m_stages)
            if (s->enabled() && isBloom(s->name()))
                return s.get();
        const char* def = m_preset == Preset::Pilot     ? "soft-bloom"
                          : m_preset == Preset::Lecture ? "hdr-bloom"
                                                        : "smash-bloom";
        return find(def);
    }
    name = canonicalStageName(name);
    for (const auto& s : m_stages)
        if (name == s->name())
            return s.get();
    return nullptr;
}

Stage& Pipeline::stage(std::string_view name) {
    if (Stage* s = find(name))
        return *s;
    makeStage(name); // throws the message listing every stage
    throw Error("unknown stage '" + std::string(name) + "'");
}

void Pipeline::setEnabled(std::string_view name, bool on) {
    if (name == "sanitize" && !on)
        throw Error("stage 'sanitize' cannot be disabled (it keeps NaN/Inf from spreading)");
    stage(name).setEnabled(on);
}

void Pipeline::assign(std::string_view a) {
    const auto eq = a.find('=');
    const auto dot = a.substr(0, eq).rfind('.');
    if (eq == std::string_view::npos || dot == std::string_view::npos || dot == 0 || dot + 1 == eq)
        throw Error("bad stage setting '" + std::string(a) + "' (expected stage.param=value)");
    stage(a.substr(0, dot)).setParam(a.substr(dot + 1, eq - dot - 1), a.substr(eq + 1));
}

void Pipeline::setLut(std::shared_ptr<const Lut3D> lut, Interpolation method,
                      std::shared_ptr<const Lut1D> shaper) {
    for (auto& s : m_stages)
        if (auto* l = dynamic_cast<detail::LutStage*>(s.get()))
            l->setLut(lut, method, shaper);
}

void Pipeline::setBloom(bool on) {
    if (on) {
        if (Stage* b = find("bloom"))
            b->setEnabled(true);
        return;
    }
    for (auto& s : m_stages)
        if (isBloom(s->name()))
            s->setEnabled(false);
}

std::size_t Pipeline::firstLutStage() const {
    for (std::size_t i = 0; i < m_stages.size(); ++i)
        if (dynamic_cast<const detail::LutStage*>(m_stages[i].get()))
            return i;
    return m_stages.size();
}

bool Pipeline::sameBeforeLut(const Pipeline& other) const {
    const std::size_t n = firstLutStage();
    if (n != other.firstLutStage())
        return false;
    for (std::size_t i = 0; i < n; ++i) {
        const Stage& a = *m_stages[i];
        const Stage& b = *other.m_stages[i];
        if (std::string_view(a.name()) != b.name() || a.enabled() != b.enabled())
            return false;
        if (!a.enabled())
            continue;
        const auto& pa = a.params();
        const auto& pb = b.params();
        if (pa.size() != pb.size())
            return false;
        for (std::size_t k = 0; k < pa.size(); ++k)
            if (pa[k].value != pb[k].value)
                return false;
    }
    return true;
}

std::string PipelineReport::str() const {
    std::ostringstream os;
    char buf[160];
    for (const auto& s : stages) {
        if (!s.enabled)
            continue;
        std::snprintf(buf, sizeof buf, "  %-22s %-8s %9.3f ms\n", s.name.c_str(),
                      s.fused ? "fused"
                      : s.ran ? "ran"
                              : "skipped",
                      s.milliseconds);
        os << buf;
    }
    std::snprintf(buf, sizeof buf, "  %-22s %-8s %9.3f ms\n", "total", "", totalMilliseconds);
    os << buf;
    return os.str();
}

namespace {
using Clock = std::chrono::steady_clock;

// How run() groups the stages into passes over the frame, and the one fusion (written once for
// run() and runPixels()): a stage that inspects the colour or needs the whole frame first starts
// a new pass; sanitize ends its pass (it changes alpha, which later stages may base their
// decision on); sRGB display right after smash-grade in the same pass is encoded inside the
// grading loop while the pixel is in registers (StageContext::fusedDisplay).
bool startsPass(const Stage& s) {
    return s.inspectsColor() || s.needsPrepare();
}
bool endsPass(const Stage& s) {
    return std::string_view(s.name()) == "sanitize";
}
bool fusesInto(const Stage& passBack, const Stage& s) {
    return detail::isSmashGrade(passBack) && detail::isSrgbDisplay(s);
}
double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
} // namespace

PipelineReport Pipeline::run(const ImageView& frame, const RunOptions& options) {
    const auto tStart = Clock::now();
    // The stages [first, last) of the part to run.
    const std::size_t split = firstLutStage();
    const std::size_t first = options.part == PipelinePart::FromLut ? split : 0;
    const std::size_t last = options.part == PipelinePart::BeforeLut ? split : m_stages.size();
    PipelineReport report;
    for (std::size_t i = 0; i < m_stages.size(); ++i) {
        StageReport r;
        r.name = m_stages[i]->name();
        r.enabled = m_stages[i]->enabled() && i >= first && i < last;
        report.stages.push_back(r);
    }
    if (frame.empty())
        return report;
    StageContext ctx;
    ctx.nthreads = options.nthreads;
    ctx.frameIndex = options.frameIndex;
    const int threads = std::max(1, std::min(resolveThreads(options.nthreads), frame.height));

    // Stages whose rows run in the current fused pass (index into m_stages).
    std::vector<std::size_t> pass;
    auto flush = [&] {
        if (pass.empty())
            return;
        constexpr int kBlock = 8; // rows per tile: a 1920-wide tile is 240 KB, cache-resident
        const int blocks = (frame.height + kBlock - 1) / kBlock;
        std::vector<double> ms(pass.size(), 0.0);
        std::mutex m;
        parallelForDynamic(blocks, options.nthreads, 1, [&](int b0, int b1) {
            std::vector<double> local(pass.size(), 0.0);
            for (int b = b0; b < b1; ++b) {
                const int y0 = b * kBlock, y1 = std::min(frame.height, y0 + kBlock);
                for (std::size_t k = 0; k < pass.size(); ++k) {
                    const auto t0 = Clock::now();
                    m_stages[pass[k]]->processRows(frame, y0, y1, ctx);
                    local[k] += msSince(t0);
                }
            }
            std::lock_guard<std::mutex> lock(m);
            for (std::size_t k = 0; k < pass.size(); ++k)
                ms[k] += local[k];
        });
        for (std::size_t k = 0; k < pass.size(); ++k) {
            report.stages[pass[k]].milliseconds += ms[k] / threads;
            m_stages[pass[k]]->finish();
        }
        pass.clear();
        ctx.fusedDisplay = false;
    };

    for (std::size_t i = first; i < last; ++i) {
        Stage& s = *m_stages[i];
        if (!s.enabled())
            continue;
        if (startsPass(s))
            flush(); // timed as the earlier stages' work
        const auto t0 = Clock::now();
        const bool run = options.forceAll || s.canChange(frame, options.nthreads);
        if (run) {
            report.stages[i].ran = true;
            if (s.needsPrepare())
                s.prepare(frame, ctx);
            if (!pass.empty() && fusesInto(*m_stages[pass.back()], s)) {
                ctx.fusedDisplay = true;
                report.stages[i].fused = true;
            } else {
                pass.push_back(i);
            }
        }
        report.stages[i].milliseconds += msSince(t0);
        if (endsPass(s))
            flush();
    }
    flush();
    report.totalMilliseconds = msSince(tStart);
    return report;
}

Image Pipeline::run(const Image& frame, const RunOptions& options, PipelineReport* report) {
    Image out = frame;
    PipelineReport r = run(out.view(), options);
    if (report)
        *report = std::move(r);
    return out;
}

bool Pipeline::isPointwise() const {
    for (const auto& s : m_stages)
        if (s->enabled() && !s->pointwise())
            return false;
    return true;
}

void Pipeline::runPixels(float* rgba, std::size_t count, const RunOptions& options) const {
    if (!isPointwise())
        throw Error("the pipeline has a stage that needs the whole frame (runPixels)");
    if (count == 0)
        return;
    if (count > static_cast<std::size_t>(std::numeric_limits<int>::max() / 4))
        throw Error("runPixels: too many pixels in one run");
    // run() with forceAll, on a 1-row frame: skipping a stage never changes a pixel (Stage.h), so
    // running every enabled stage gives run()'s result; the passes only decide the fusion.
    const std::size_t split = firstLutStage();
    const std::size_t first = options.part == PipelinePart::FromLut ? split : 0;
    const std::size_t last = options.part == PipelinePart::BeforeLut ? split : m_stages.size();
    const ImageView row{rgba, static_cast<int>(count), 1, static_cast<std::ptrdiff_t>(4 * count)};
    std::size_t order[32];
    bool fused[32] = {};
    std::size_t n = 0;
    const Stage* passBack = nullptr;
    for (std::size_t i = first; i < last && n < 32; ++i) {
        const Stage& s = *m_stages[i];
        if (!s.enabled())
            continue;
        if (startsPass(s))
            passBack = nullptr;
        if (passBack && n > 0 && fusesInto(*passBack, s)) {
            fused[n - 1] = true;
        } else {
            order[n++] = i;
            passBack = &s;
        }
        if (endsPass(s))
            passBack = nullptr;
    }
    StageContext ctx;
    ctx.nthreads = 1;
    ctx.frameIndex = options.frameIndex;
    for (std::size_t k = 0; k < n; ++k) {
        ctx.fusedDisplay = fused[k];
        m_stages[order[k]]->processRows(row, 0, 1, ctx);
    }
}

} // namespace lut
