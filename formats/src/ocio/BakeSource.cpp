// SPDX-License-Identifier: Apache-2.0
#include "ocio/BakeSource.h"

#include "ocio/ColorConfigImpl.h"
#include "ocio/OcioFacts.h"
#include "ocio/OcioStructure.h"

#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/InputFile.h"

#include <filesystem>

namespace lut::formats {

namespace {

BakeSource fromConfig(const BakeOptions& o) {
    if (o.inputSpace.empty())
        throw ColorOptionError("name the input colour space (--inputspace)");
    const bool toDisplay = !o.display.empty() || !o.view.empty();
    if (o.outputSpace.empty() && !toDisplay)
        throw ColorOptionError("name the output colour space (--outputspace) or a display and "
                               "view (--display, --view)");
    if (!o.outputSpace.empty() && toDisplay)
        throw ColorOptionError("--outputspace and --display/--view both name the output: give one");
    BakeSource s;
    s.config = ColorConfig::load(o.config);
    const ColorConfig& cfg = *s.config;
    s.configUsed = cfg.location().describe();
    s.diagnostics = cfg.diagnostics();
    s.inputSpace = cfg.colorSpace(o.inputSpace);
    s.inputInfo = cfg.info(s.inputSpace);
    std::shared_ptr<const ColorTransform> t;
    if (toDisplay) {
        const std::string display = o.display.empty() ? cfg.defaultDisplay() : o.display;
        const std::string view = o.view.empty() ? cfg.defaultView(display) : o.view;
        t = ColorTransform::toDisplay(cfg, s.inputSpace, display, view, o.looks);
    } else {
        t = ColorTransform::convert(cfg, s.inputSpace, o.outputSpace, o.looks);
    }
    s.what = t->description();
    s.truth = [t](float* rgb, std::size_t n) { t->processRgb(rgb, n); };
    s.crosstalk = t->hasChannelCrosstalk();
    return s;
}

BakeSource fromFiles(const BakeOptions& o, const std::string& output) {
    BakeSource s;
    const std::string sessionPath = o.files.front().path;
    OcioSession session(sessionPath);
    std::string doing = "loading the file";
    std::string current = sessionPath;
    try {
        OCIO::ClearAllCaches();
        auto config = OCIO::Config::CreateRaw();
        auto group = OCIO::GroupTransform::Create();
        for (const auto& f : o.files) {
            current = f.path;
            checkRegularInput(f.path);
            checkNotSameFile(f.path, output);
            auto ft = OCIO::FileTransform::Create();
            ft->setSrc(std::filesystem::absolute(f.path).string().c_str());
            ft->setInterpolation(OCIO::INTERP_BEST);
            if (!f.cccid.empty())
                ft->setCCCId(f.cccid.c_str());
            ft->setDirection(f.inverse ? OCIO::TRANSFORM_DIR_INVERSE : OCIO::TRANSFORM_DIR_FORWARD);
            group->appendTransform(ft);
            s.what += (s.what.empty() ? "" : ", ") + std::string(f.inverse ? "inverse of " : "") +
                      f.path + (f.cccid.empty() ? "" : " (cccid " + f.cccid + ")");
        }
        const auto processor = config->getProcessor(group);
        doing = "building the CPU processor";
        // Unoptimised, as convert reads the same file (faithfulCpu, OcioFacts.h): even OCIO's
        // lossless optimisation changes some chains (opposite Gamma styles, CDL in a CTF).
        const auto cpu = faithfulCpu(processor);
        s.truth = [cpu](float* rgb, std::size_t n) {
            OCIO::PackedImageDesc desc(rgb, static_cast<long>(n), 1, 3);
            cpu->apply(desc);
        };
        s.crosstalk = cpu->hasChannelCrosstalk();
        if (o.files.size() == 1 && !o.files.front().inverse) {
            doing = "inspecting the processor";
            const OcioStructure st = analyseProcessor(config, processor);
            if (st.kind != OcioStructure::Kind::Chain &&
                (st.domainMin != glm::vec3(0.0f) || st.domainMax != glm::vec3(1.0f))) {
                s.ownRange = std::make_pair(st.domainMin, st.domainMax);
                s.shaped = st.kind == OcioStructure::Kind::ShaperCube;
            }
        }
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        std::string msg = ocioFailure(current, doing, e.what());
        if ((msg.find("CCC") != std::string::npos || msg.find("cccid") != std::string::npos))
            msg += " (name the correction with --cccid)";
        throw Error(msg);
    }
    session.appendDiagnostics(s.diagnostics);
    return s;
}

BakeSource fromLut(const BakeOptions& o, const std::string& output) {
    checkNotSameFile(o.lut, output);
    BakeSource s;
    const LutFile file = readLut(o.lut, o.lutRead, o.lutFormat);
    s.diagnostics = file.diagnostics;
    ColorSpec spec = o.around;
    spec.config = o.config;
    const ColorPlan plan = planColor(spec);
    s.diagnostics.insert(s.diagnostics.end(), plan.diagnostics.begin(), plan.diagnostics.end());
    const auto lut = std::make_shared<const LutFileFunction>(file);
    const auto before = plan.before, after = plan.after;
    s.truth = [lut, before, after](float* rgb, std::size_t n) {
        if (before)
            before->processRgb(rgb, n);
        (*lut)(rgb, n);
        if (after)
            after->processRgb(rgb, n);
    };
    s.what = o.lut;
    if (!plan.before)
        s.kinksOf = file;
    s.crosstalk = file.cube.has_value() || (before && before->hasChannelCrosstalk()) ||
                  (after && after->hasChannelCrosstalk());
    if (spec.any()) {
        s.config = ColorConfig::load(plan.config);
        s.configUsed = plan.config.describe();
        s.what = (plan.before ? plan.before->description() + ", " : std::string()) + o.lut +
                 (plan.after ? ", " + plan.after->description() : std::string());
        if (!o.around.from.empty()) {
            s.inputSpace = s.config->colorSpace(o.around.from);
            s.inputInfo = s.config->info(s.inputSpace);
        }
    }
    if (!plan.before) {
        const glm::vec3 lo = file.shaper ? file.shaper->domainMin() : file.cube->domainMin();
        const glm::vec3 hi = file.shaper ? file.shaper->domainMax() : file.cube->domainMax();
        if (lo != glm::vec3(0.0f) || hi != glm::vec3(1.0f)) {
            s.ownRange = std::make_pair(lo, hi);
            s.shaped = file.shaper && file.cube;
        }
    }
    return s;
}

} // namespace

BakeSource makeBakeSource(const BakeOptions& o, const std::string& output) {
    const int sources =
        (!o.inputSpace.empty() || !o.outputSpace.empty() || !o.display.empty() || !o.view.empty()) +
        !o.files.empty() + !o.lut.empty();
    if (sources == 0)
        throw ColorOptionError("nothing to bake: name colour spaces (--inputspace, --outputspace) "
                               "or LUT files (--lut)");
    if (sources > 1)
        throw ColorOptionError("bake one thing: colour spaces of a config, or LUT files");
    if (!o.files.empty()) {
        BakeSource s = fromFiles(o, output);
        // One file applied forward: where it kinks, as lutkit reads it (unreadable: unknown).
        // Read after fromFiles' OpenColorIO session has ended (readLut may open its own).
        if (o.files.size() == 1 && !o.files.front().inverse && o.files.front().cccid.empty()) {
            try {
                s.kinksOf = readLut(o.files.front().path);
            } catch (const Error&) {
            }
        }
        return s;
    }
    if (!o.lut.empty())
        return fromLut(o, output);
    return fromConfig(o);
}

} // namespace lut::formats
