// lutkit preview: an image through the post-processing chain (preset smash = the game's), with a
// LUT, written display-encoded. Float inputs (EXR) are the linear scene; 8/16-bit inputs are
// screenshots, decoded with the piecewise sRGB curve; --from-screenshot also undoes the game's
// grading with --original-lut before grading with --lut (bloom cannot be undone).
#include "cmd_preview.h"

#include "Commands.h"
#include "cmd_apply.h"

#include "lut/Error.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/pipeline/Pipeline.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>

namespace lut::cli {

namespace {

std::string listStages(const Pipeline& p) {
    std::ostringstream os;
    os << "stages of preset " << toString(p.preset()) << " (in order; * = enabled):\n";
    for (const auto& s : p.stages()) {
        os << (s->enabled() ? "  * " : "    ") << s->name() << ": " << s->description() << "\n";
        for (const auto& prm : s->params()) {
            os << "        " << s->name() << "." << prm.name << "=" << prm.valueString();
            if (!prm.choices.empty()) {
                os << "  (";
                for (std::size_t i = 0; i < prm.choices.size(); ++i)
                    os << (i ? "|" : "") << prm.choices[i];
                os << ")";
            } else {
                os << "  [" << prm.min << ".." << prm.max << "]";
            }
            os << "  " << prm.help << "\n";
        }
    }
    os << "  not available: depth of field, SSAO, SSR (they need depth and normals an image "
          "lacks)\n";
    return os.str();
}

} // namespace

int runPreview(const PreviewOptions& o) {
    PipelineSettings settings;
    settings.preset = parsePreset(o.preset);
    settings.interpolation = parseInterpolation(o.interp);
    settings.bloom = !o.noBloom;
    settings.enable = o.enable;
    settings.disable = o.disable;
    settings.assignments = o.stageSettings;
    if (!o.lut.empty())
        settings.lut = std::make_shared<const Lut3D>(formats::readLut(o.lut).toLut3D());
    std::unique_ptr<Pipeline> configuredPtr;
    try {
        configuredPtr = std::make_unique<Pipeline>(settings); // validates every setting first
    } catch (const Error& e) {
        std::cerr << "lutkit preview: " << e.what() << "\n";
        return kExitUsage;
    }
    const Pipeline& configured = *configuredPtr;

    if (o.listStages) {
        std::cout << listStages(configured);
        return kExitOk;
    }
    std::vector<BatchJob> jobs;
    std::string error;
    if (!planBatch(o.inputs, o.outputDir, "", jobs, error)) {
        std::cerr << "lutkit preview: " << error << "\n";
        return kExitUsage;
    }
    std::shared_ptr<const Lut3D> original;
    if (!o.originalLut.empty())
        original = std::make_shared<const Lut3D>(formats::readLut(o.originalLut).toLut3D());
    bool noted = false;
    std::mutex noteMutex;

    return runBatch(jobs, o.threads, o.quiet, [&](const BatchJob& j, int inner) {
        formats::LoadedImage img = formats::readImage(j.input);
        // A screenshot holds display-encoded values whatever its bit depth.
        const bool linear = img.info.isFloat && !o.fromScreenshot;
        const Diagnostics notes = prepareSceneFrame(img.image.view(), linear, o.fromScreenshot,
                                                    original.get(), settings.interpolation, inner);
        Pipeline pipeline(settings); // one per job: stages keep per-run buffers
        RunOptions run;
        run.nthreads = inner;
        run.frameIndex = o.frame;
        const PipelineReport report = pipeline.run(img.image.view(), run);
        formats::writeImage(j.output, img.image,
                            formats::renderedImageWriteOptions(img.info, j.output, o.bitDepth));
        std::ostringstream text;
        {
            std::lock_guard<std::mutex> lock(noteMutex);
            for (const auto& d : notes) {
                // The bloom note is the same for every file: say it once.
                const bool bloomNote = d.message.rfind("bloom cannot be undone", 0) == 0;
                if (bloomNote && noted)
                    continue;
                noted = noted || bloomNote;
                std::cerr << "lutkit: "
                          << (d.severity == Diagnostic::Severity::Info ? "note" : "warning") << ": "
                          << j.input << ": " << d.message << "\n";
            }
        }
        if (o.verbose)
            text << j.input << " -> " << j.output << " (" << toString(settings.preset) << ")\n"
                 << report.str();
        return text.str();
    });
}

} // namespace lut::cli
