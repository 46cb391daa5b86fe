// SPDX-License-Identifier: Apache-2.0
// lutkit preview: an image through the post-processing chain (preset smash = the game's), with a
// LUT, written display-encoded. Which input is a screenshot and which a scene is the library's
// rule (lut/pipeline/SceneKind.h, shared with the editor): 8/16-bit inputs are in-game
// screenshots (the game's grading is undone with --original-lut before grading with --lut; bloom
// cannot be undone), float inputs (EXR) and files tagged linear are linear scenes; the choice is
// said per input and --from-screenshot / --scene override it.
#include "commands/Preview.h"

#include "Batch.h"
#include "LutFiles.h"
#include "PurposeText.h"
#include "StrengthOptions.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/formats/ApplyImage.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/PixelChain.h"
#include "lut/io/FileNames.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/pipeline/PreviewPreparation.h"
#include "lut/pipeline/SceneKind.h"

#include <CLI/CLI.hpp>

#include <algorithm>

#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
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
    os << "Input: 8/16-bit images are in-game screenshots: with preset smash the game's "
          "display encode and\n  grading (with --original-lut, default neutral) are undone "
          "before --lut; bloom already in a\n  screenshot cannot be undone, and none is added "
          "(--enable bloom adds it); with another preset\n  the LUT goes on the stored values "
          "(the screenshot has its engine's post-processing). Float\n  images (EXR) and files "
          "tagged linear are linear scenes. The choice is said for every input;\n  "
          "--from-screenshot and --scene override it.\nLUT: with preset smash the game's LUT: "
          "an edit (a file that says raw or does not say, unless\n  --lut-target smash) is made "
          "into the game's LUT first, as convert writes the .nutexb; with\n  another preset an "
          "edit: the game's LUT is turned into the edit it makes.\n\nPresets (--preset):\n";
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
          "  lutkit preview shot.png -o seen.png --lut grade.cube   # as Smash Ultimate shows "
          "it\n"
          "  lutkit preview shot.png -o seen.png --lut new.nutexb --original-lut old.nutexb\n"
          "  lutkit preview shot.png -o seen.png --lut new.nutexb --original-lut "
          "builtin:smash-default\n"
          "  lutkit preview shot.png -o seen.png --lut grade.cube --strength 0.7\n"
          "  lutkit preview photo.png -o seen.png --scene --lut grade.cube  # an 8-bit scene\n"
          "  lutkit preview render.exr -o out.png --preset filmic --lut grade.cube\n"
          "  lutkit preview acescg_render.exr -o out.png --from ACEScg --lut grade.cube\n"
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
    PreviewRequest request;
    request.preset = o.preset;
    request.interpolation = o.interp;
    request.bloom = !o.noBloom;
    request.enable = o.enable;
    request.disable = o.disable;
    request.assignments = o.stageSettings;
    {
        PipelineSettings settings;
        settings.preset = o.preset;
        settings.interpolation = o.interp;
        settings.bloom = request.bloom;
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
    }
    if (o.fromScreenshot && !o.color.from.empty())
        throw UsageError("--from-screenshot and --from both say what the input is: give one");
    const formats::ColorPlan color = formats::planPreviewColor(o.color); // names first: usage
    const BatchPlan plan =
        planBatch(o.inputs, o.output, {o.lut, o.originalLut, o.color.config}, o.frames);
    BatchOptions bo;
    bo.threads = o.threads;
    bo.quiet = o.verbosity.quiet;
    bo.maxMemory = o.maxMemory.empty() ? 0 : parseMemorySize(o.maxMemory);
    if (o.lut.empty() && !isFullStrength(o.strength))
        throw UsageError("--strength, --luma-strength and --chroma-strength blend --lut with "
                         "neutral: give --lut");
    std::shared_ptr<const Lut3D> original;
    if (!o.originalLut.empty())
        original = std::make_shared<const Lut3D>(readStageLut(o.originalLut, o.verbosity));
    // The chain's LUT, made for what the chain is (the game's LUT for the game's chain, as the
    // .nutexb convert writes holds it; an edit for the others). A LUT used as it is keeps its
    // shaper (a Resolve .cube's) and table, each run exactly by the LUT stage.
    std::shared_ptr<const Lut3D> lut;
    std::shared_ptr<const Lut1D> shaper;
    if (!o.lut.empty()) {
        LutFile file = readCommandLut(o.lut, o.lutLayout, o.verbosity);
        PurposeOptions po;
        po.stageLut = original.get();
        po.rawSize = 65; // the game's LUT as an edit for another chain, as apply makes it
        const LutPurpose wanted = previewLutPurpose(o.preset);
        const std::optional<LutPurpose> given = purposeOption(o.lutTarget);
        // --strength blends the edit (one table): before it is made into the game's LUT, after
        // a game LUT is made into its edit; a LUT used for its purpose as it is.
        const bool full = isFullStrength(o.strength);
        const bool blendAfter =
            decidePurpose(file, given).purpose == LutPurpose::Smash && wanted == LutPurpose::Raw;
        if (!full && !blendAfter) {
            file.cube = strengthLut(file.toLut3D(), o.lut, o.strength, o.verbosity);
            file.shaper.reset();
        }
        PurposedLut used = lutFor(file, o.lut, wanted, given, "--lut-target", po, o.verbosity);
        if (!full && blendAfter)
            used.lut = strengthLut(std::move(used.lut), o.lut, o.strength, o.verbosity);
        if (used.conversion || !full) {
            if (used.conversion && wanted == LutPurpose::Smash)
                (void)quantize8(used.lut);
            lut = std::make_shared<const Lut3D>(std::move(used.lut));
        } else {
            if (file.cube)
                lut = std::make_shared<const Lut3D>(*file.cube);
            if (file.shaper)
                shaper = std::make_shared<const Lut1D>(*file.shaper);
        }
    }
    printDiagnostics(std::cerr, color.diagnostics, o.verbosity, "lutkit: ");
    bool noted = false;
    std::mutex noteMutex;

    // The recipe (lut/pipeline/PreviewPlan.h) for a file: screenshot or scene by the library's
    // rule or what the user said, what is undone, which stages run.
    auto recipeFor = [&](const formats::ImageInfo& info) {
        PreviewRequest q = request;
        q.evidence = SceneEvidence{info.isFloat, info.bitDepth, info.colorSpace, info.format};
        q.forced = o.fromScreenshot          ? std::optional<SceneKind>(SceneKind::Screenshot)
                   : o.scene || color.before ? std::optional<SceneKind>(SceneKind::Scene)
                                             : std::nullopt;
        q.storedEncoded = color.before != nullptr;
        return planPreview(q, original != nullptr);
    };
    // The chain a recipe runs, with the LUT (and its shaper) made above.
    auto chainSettings = [&](const PreviewPlan& recipe) {
        PipelineSettings settings = recipe.settings;
        settings.lut = lut;
        settings.shaper = shaper;
        return settings;
    };
    // Above the progress bar (JobContext::warn).
    auto printNotes = [&](JobContext& ctx, const std::string& input, const Diagnostics& notes) {
        std::string lines;
        std::lock_guard<std::mutex> lock(noteMutex);
        for (const auto& d : notes) {
            if (!isShown(d, o.verbosity))
                continue;
            // The bloom note is the same for every file: say it once.
            const bool bloomNote = d.id == NoteId::BloomNotUndone;
            if (bloomNote && noted)
                continue;
            noted = noted || bloomNote;
            lines += std::string("lutkit: ") + severityWord(d.severity) + ": " +
                     printable(input + ": " + d.message) + "\n";
        }
        ctx.warn(lines);
    };

    return runBatch(plan, bo, [&](const BatchJob& j, JobContext& ctx) {
        const int inner = ctx.innerThreads();
        if (j.input != "-") {
            const formats::ImageInfo info = formats::readImageInfo(j.input, o.inFormat, o.subimage);
            // A picture whose chain works on each pixel alone (no bloom, vignette, grain ...),
            // written to PNG or PNM at its own depth, is streamed: read, undone, run through the
            // chain and written a few rows at a time, never held as a float frame (a 1080p
            // screenshot's frame is 33 MB to fill); the same file as the frame path below.
            const bool fileTarget =
                j.target.kind == OutputKind::NewFile || j.target.kind == OutputKind::ExistingFile;
            if (!color.before && !color.after && fileTarget && o.format.empty() &&
                formats::appliedLayoutIsRendered(info, j.output, o.bitDepth)) {
                const PreviewPlan recipe = recipeFor(info);
                const PipelineSettings settings = chainSettings(recipe);
                auto pipeline = std::make_shared<const Pipeline>(settings);
                if (pipeline->isPointwise()) {
                    auto prep = std::make_shared<const PreviewPreparation>(
                        recipe, original.get(), info.type == formats::PixelType::UInt8);
                    PixelChain chain;
                    if (prep->active())
                        chain.addBefore("undo",
                                        [prep](float* p, std::size_t n) { prep->apply(p, n); });
                    RunOptions run;
                    run.frameIndex = o.frame;
                    chain.addAfter("chain", [pipeline, run](float* p, std::size_t n) {
                        pipeline->runPixels(p, n, run);
                    });
                    formats::ApplyImageOptions ao;
                    ao.inFormat = o.inFormat;
                    ao.threads = inner;
                    ao.subimage = o.subimage;
                    // A preview is looked at, then replaced: PNGs are written with the fastest
                    // level.
                    if (extensionOf(j.output) == ".png")
                        ao.compression = "zip:1";
                    ao.reserveMemory = [&ctx](std::uint64_t bytes, const std::string& what) {
                        ctx.reserveMemory(bytes, what);
                    };
                    const formats::ApplyImageReport r =
                        formats::applyToImage(j.input, j.target, chain, ao);
                    Diagnostics notes = recipe.notes;
                    const Diagnostics undo = prep->notes();
                    notes.insert(notes.end(), undo.begin(), undo.end());
                    notes.insert(notes.end(), r.diagnostics.begin(), r.diagnostics.end());
                    printNotes(ctx, j.input, notes);
                    if (!o.verbosity.verbose)
                        return std::string();
                    std::ostringstream os;
                    os << j.input << " -> " << j.output << " (" << toString(settings.preset)
                       << ", streamed: no frame held)\n  stages:";
                    for (const auto& s : pipeline->stages())
                        if (s->enabled())
                            os << " " << s->name();
                    os << "\n  total " << std::fixed << std::setprecision(3) << r.seconds * 1e3
                       << " ms (read, undo, chain and write)\n";
                    return os.str();
                }
            }
            // Before anything is decoded (the header checked against the file first): the
            // frame, the blur pyramids of the bloom stages (about one more frame) and what the
            // format's decoder holds.
            ctx.reserveMemory(static_cast<std::uint64_t>(info.width) *
                                      static_cast<std::uint64_t>(info.height) * 16u * 2u +
                                  info.decoderBytes,
                              "the preview of a " + std::to_string(info.width) + "x" +
                                  std::to_string(info.height) + " image");
        }
        formats::LoadedImage img;
        try {
            img = formats::readImage(j.input, o.inFormat, nullptr, o.subimage);
        } catch (const formats::MultiImageError& e) {
            throw Error(j.input + ": holds " + std::to_string(e.count()) + " images (" + e.kind() +
                        "): pick one with --subimage N (0 to " + std::to_string(e.count() - 1) +
                        ")");
        }
        if (color.before) {
            // --from: OpenColorIO converts the input to sRGB-encoded values first.
            ProcessorChain toSrgb;
            toSrgb.append(color.before);
            toSrgb.apply(img.image.view(), inner);
        }
        const PreviewPlan recipe = recipeFor(img.info);
        Diagnostics notes = recipe.notes;
        const Diagnostics undo =
            preparePreviewFrame(recipe, img.image.view(), original.get(),
                                !color.before && img.info.type == formats::PixelType::UInt8, inner);
        notes.insert(notes.end(), undo.begin(), undo.end());
        const PipelineSettings settings = chainSettings(recipe);
        Pipeline pipeline(settings); // one per job: stages keep per-run buffers
        RunOptions run;
        run.nthreads = inner;
        run.frameIndex = o.frame;
        const PipelineReport report = pipeline.run(img.image.view(), run);
        if (color.after) {
            ProcessorChain fromSrgb;
            fromSrgb.append(color.after);
            fromSrgb.apply(img.image.view(), inner);
        }
        formats::ImageWriteOptions wo =
            formats::renderedImageWriteOptions(img.info, j.output, o.bitDepth);
        wo.format = o.format.empty() && j.target.inPlace() ? img.info.format : o.format;
        // Keep the screenshot's metadata (ICC profile, EXIF) where the output can hold it.
        wo.metadata = img.metadata;
        // A preview is looked at, then replaced: PNGs are written with zlib's fastest level.
        if (extensionOf(j.output) == ".png" || wo.format == "png")
            wo.compression = "zip:1";
        formats::writeImage(j.target.writePath, img.image, wo);
        printNotes(ctx, j.input, notes);
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
    sub->add_option("INPUTS", o->inputs,
                    "images, folders of images, frame patterns (f.%04d.png), or - (stdin)")
        ->type_name("FILE");
    addOutputOptions(*sub, o->output,
                     "output: a file (one input), a folder (existing, or ending in /), a frame "
                     "pattern (out.%04d.png), or - (stdout)");
    addFrames(*sub, o->frames);
    addImageFormats(*sub, o->inFormat, o->format);
    addMaxMemory(*sub, o->maxMemory);
    addSubimage(*sub, o->subimage,
                "the image of files holding several (OpenEXR part, TIFF page, GIF frame; from 0)");
    sub->add_option("--lut", o->lut,
                    "grading LUT (default: neutral; also builtin:neutral, builtin:smash-default): "
                    "with preset smash the game's LUT (an edit is made into the game's LUT first, "
                    "as convert makes the .nutexb), else an edit")
        ->type_name("FILE");
    addLayout(*sub, "--lut-layout", o->lutLayout,
              "the LUT's layout when it is an image (default: detected)");
    addPurpose(*sub, "--lut-target", o->lutTarget,
               "what --lut is for (default: what the file says, LUTKIT_PURPOSE, or a .nutexb; "
               "else raw, an edit)");
    addStrengthOptions(*sub, o->strength);
    sub->add_option_function<std::string>(
           "--preset", [o](const std::string& v) { o->preset = parsePreset(v); },
           "the post-processing chain (default smash; also pilot, lecture)")
        ->type_name("NAME")
        ->check(choicesValidator(presetChoices()));
    sub->add_flag("--no-bloom", o->noBloom, "disable every bloom stage");
    addInterp(*sub, o->interp, "LUT interpolation (default trilinear, as the game's GPU)");
    auto* shot = sub->add_flag("--from-screenshot", o->fromScreenshot,
                               "the inputs are in-game screenshots (the default for 8/16-bit "
                               "files): undo the game's grading first");
    sub->add_flag("--scene", o->scene,
                  "the inputs are linear scenes (the default for float files; 8/16-bit files are "
                  "sRGB-decoded)")
        ->excludes(shot);
    sub->add_option("--original-lut", o->originalLut,
                    "the LUT the screenshots were taken with (default neutral); a file or a "
                    "built-in: a stage without its own LUT was most likely shot with "
                    "builtin:smash-default, the game's default stage LUT as the reference "
                    "renderer (ssbh_wgpu) has it")
        ->type_name("FILE");
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
