// lutkit preview: an image through the post-processing chain (preset smash = the game's), with a
// LUT, written display-encoded. Float inputs (EXR) are the linear scene; 8/16-bit inputs are
// screenshots, decoded with the piecewise sRGB curve; --from-screenshot also undoes the game's
// grading with --original-lut before grading with --lut (bloom cannot be undone).
#include "commands/Preview.h"

#include "Batch.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <CLI/CLI.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>

namespace lut::cli {

namespace {

std::string oldNamesOf(const std::string& stage) {
    std::string s;
    for (const auto& [alias, name] : stageAliases())
        if (name == stage)
            s += (s.empty() ? "" : ", ") + alias;
    return s;
}

std::string paramText(const StageParam& p, bool current) {
    StageParam shown = p;
    if (!current)
        shown.value = shown.defaultValue;
    std::ostringstream os;
    os << p.name << "=" << shown.valueString();
    if (!p.choices.empty()) {
        os << " (";
        for (std::size_t i = 0; i < p.choices.size(); ++i)
            os << (i ? "|" : "") << p.choices[i];
        os << ")";
    } else {
        os << " [" << p.min << ".." << p.max << "]";
    }
    return os.str();
}

// The --help footer, generated from the stage registry and the presets.
std::string previewFooter() {
    std::ostringstream os;
    os << "Input: float images (EXR) are the linear scene; 8/16-bit images are decoded with the "
          "sRGB curve.\n"
          "--from-screenshot undoes the game's display encode and grading (with --original-lut, "
          "default\n  neutral) before applying --lut; bloom already in the screenshot cannot be "
          "undone.\n\nPresets (--preset):\n";
    for (const Preset preset : allPresets()) {
        const Pipeline p(preset);
        std::string aliases;
        for (const auto& a : presetAliases(preset))
            aliases += (aliases.empty() ? " (also " : ", ") + a;
        os << "  " << std::left << std::setw(10) << toString(preset) << describe(preset)
           << (aliases.empty() ? "" : aliases + ")") << "\n    stages:";
        for (const auto& s : p.stages())
            if (s->enabled())
                os << " " << s->name();
        os << "\n";
    }
    os << "\nStages, in order (--enable, --disable, --stage STAGE.PARAM=VALUE; \"bloom\" is the "
          "preset's\nbloom stage; --list-stages shows a preset's current values):\n";
    for (const auto& name : stageNames()) {
        const auto s = makeStage(name);
        const std::string old = oldNamesOf(name);
        os << "  " << std::left << std::setw(21) << name << s->description()
           << (old.empty() ? "" : " (also " + old + ")") << "\n";
        std::string line = "      ";
        for (const auto& p : s->params()) {
            const std::string t = paramText(p, false);
            if (line.size() + t.size() > 100) {
                os << line << "\n";
                line = "      ";
            }
            line += (line.size() > 6 ? "  " : "") + t;
        }
        if (line.size() > 6)
            os << line << "\n";
    }
    os << "  Not available: depth of field, SSAO, SSR (they need depth and normals an image "
          "lacks).\n\n"
          "Examples:\n"
          "  lutkit preview shot.png seen.png --lut grade.cube      # as Smash Ultimate shows "
          "it\n"
          "  lutkit preview shot.png seen.png --from-screenshot --lut new.nutexb --original-lut "
          "old.nutexb\n"
          "  lutkit preview render.exr out.png --preset filmic --lut grade.cube\n"
          "  lutkit preview acescg_render.exr out.png --from ACEScg --lut grade.cube\n"
          "  lutkit preview frames/ -o seen/ --enable grain --stage grain.strength=0.05\n"
          "  lutkit preview --list-stages --preset cinematic";
    return os.str();
}

} // namespace

std::string stageList(const Pipeline& p) {
    std::ostringstream os;
    os << "stages of preset " << toString(p.preset()) << " (in order; * = enabled):\n";
    for (const auto& s : p.stages()) {
        os << (s->enabled() ? "  * " : "    ") << s->name() << ": " << s->description() << "\n";
        for (const auto& prm : s->params())
            os << "        " << s->name() << "." << paramText(prm, true) << "  " << prm.help
               << "\n";
    }
    os << "  not available: depth of field, SSAO, SSR (they need depth and normals an image "
          "lacks)\n";
    return os.str();
}

int runPreview(const PreviewOptions& o) {
    PipelineSettings settings;
    settings.preset = o.preset;
    settings.interpolation = o.interp;
    settings.bloom = !o.noBloom;
    settings.enable = o.enable;
    settings.disable = o.disable;
    settings.assignments = o.stageSettings;
    std::unique_ptr<Pipeline> configured;
    try {
        configured = std::make_unique<Pipeline>(settings); // validates every setting first
    } catch (const Error& e) {
        throw UsageError(e.what()); // e.g. --disable sanitize
    }
    if (o.listStages) {
        std::cout << stageList(*configured);
        return kExitOk;
    }
    const std::vector<BatchJob> jobs = planBatch(o.inputs, o.outputDir);
    if (!o.lut.empty()) {
        FormatOptions lutOptions;
        lutOptions.layout = o.lutLayout;
        const LutFile file = formats::readLut(o.lut, lutOptions);
        printDiagnostics(std::cerr, file.diagnostics, o.verbosity, "lutkit: ");
        if (o.verbosity.verbose)
            if (const std::string d = layoutDetail(file, o.lutLayout.has_value(), "--lut-layout");
                !d.empty())
                std::cerr << "lutkit: " << o.lut << ": " << d << "\n";
        settings.lut = std::make_shared<const Lut3D>(file.toLut3D());
    }
    std::shared_ptr<const Lut3D> original;
    if (!o.originalLut.empty())
        original = std::make_shared<const Lut3D>(formats::readLut(o.originalLut).toLut3D());
    if (o.fromScreenshot && !o.color.from.empty())
        throw UsageError("--from-screenshot and --from both say what the input is: give one");
    const formats::ColorPlan color = formats::planPreviewColor(o.color);
    printDiagnostics(std::cerr, color.diagnostics, o.verbosity, "lutkit: ");
    bool noted = false;
    std::mutex noteMutex;

    return runBatch(jobs, o.threads, o.verbosity.quiet, [&](const BatchJob& j, int inner) {
        formats::LoadedImage img = formats::readImage(j.input);
        // A screenshot holds display-encoded values whatever its bit depth; --from converts any
        // input to sRGB-encoded values.
        bool linear = img.info.isFloat && !o.fromScreenshot;
        if (color.before) {
            PixelChain toSrgb;
            toSrgb.append(color.before);
            toSrgb.apply(img.image.view(), inner);
            linear = false;
        }
        const Diagnostics notes = prepareSceneFrame(img.image.view(), linear, o.fromScreenshot,
                                                    original.get(), settings.interpolation, inner);
        Pipeline pipeline(settings); // one per job: stages keep per-run buffers
        RunOptions run;
        run.nthreads = inner;
        run.frameIndex = o.frame;
        const PipelineReport report = pipeline.run(img.image.view(), run);
        if (color.after) {
            PixelChain fromSrgb;
            fromSrgb.append(color.after);
            fromSrgb.apply(img.image.view(), inner);
        }
        formats::writeImage(j.output, img.image,
                            formats::renderedImageWriteOptions(img.info, j.output, o.bitDepth));
        {
            std::lock_guard<std::mutex> lock(noteMutex);
            for (const auto& d : notes) {
                if (!isShown(d, o.verbosity))
                    continue;
                // The bloom note is the same for every file: say it once.
                const bool bloomNote = d.message.rfind("bloom cannot be undone", 0) == 0;
                if (bloomNote && noted)
                    continue;
                noted = noted || bloomNote;
                std::cerr << "lutkit: " << severityWord(d.severity) << ": " << j.input << ": "
                          << d.message << "\n";
            }
        }
        if (!o.verbosity.verbose)
            return std::string();
        return j.input + " -> " + j.output + " (" + toString(settings.preset) + ")\n" +
               report.str();
    });
}

CLI::App* setupPreview(CLI::App& app, std::function<void(const PreviewOptions&)> onParsed) {
    auto o = std::make_shared<PreviewOptions>();
    auto* sub = app.add_subcommand(
        "preview", "Show images as the game would: post-processing chain with a LUT");
    sub->footer(previewFooter());
    sub->add_option("FILES", o->inputs, "IN OUT, or input files/folders with -o DIR")
        ->type_name("FILE");
    sub->add_option("-o,--output-dir", o->outputDir,
                    "batch: write DIR/<input name> for every input")
        ->type_name("DIR");
    sub->add_option("--lut", o->lut, "grading LUT (default: neutral)")->type_name("FILE");
    addLayout(*sub, "--lut-layout", o->lutLayout,
              "the LUT's layout when it is an image (default: detected)");
    sub->add_option_function<std::string>(
           "--preset", [o](const std::string& v) { o->preset = parsePreset(v); },
           "the post-processing chain (default smash; also pilot, lecture)")
        ->type_name("NAME")
        ->check(choicesValidator(presetChoices()));
    sub->add_flag("--no-bloom", o->noBloom, "disable every bloom stage");
    addInterp(*sub, o->interp, "LUT interpolation (default trilinear, as the game's GPU)");
    auto* shot = sub->add_flag("--from-screenshot", o->fromScreenshot,
                               "the input is an in-game screenshot: undo the game's grading first");
    sub->add_option("--original-lut", o->originalLut,
                    "the LUT the screenshot was taken with (default neutral)")
        ->type_name("FILE")
        ->needs(shot);
    sub->add_option("--stage", o->stageSettings, "set a stage parameter (repeatable)")
        ->allow_extra_args(false)
        ->check(stageSettingValidator());
    sub->add_option("--enable", o->enable, "switch a stage on (repeatable)")
        ->allow_extra_args(false)
        ->type_name("STAGE")
        ->check(choicesValidator(stageChoices()));
    sub->add_option("--disable", o->disable, "switch a stage off (repeatable)")
        ->allow_extra_args(false)
        ->type_name("STAGE")
        ->check(choicesValidator(stageChoices()));
    sub->add_option("--frame", o->frame, "frame index (film grain changes per frame)");
    addBitDepth(*sub, o->bitDepth, "output bit depth 8, 16 or 32 (default: the input's)");
    addThreads(*sub, o->threads);
    addColorOptions(*sub, o->color, ColorOptionSet::Preview);
    sub->add_flag("--list-stages", o->listStages,
                  "print the stages and parameters of the preset and exit");
    addVerbosity(*sub, o->verbosity, "list the stages that ran and their time");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
