// SPDX-License-Identifier: Apache-2.0
// lutkit match: a LUT that gives a picture the look of reference pictures (lut/match/Match.h).
#include "commands/Match.h"

#include "Json.h"
#include "PurposeText.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/LutPurpose.h"
#include "lut/Version.h"
#include "lut/formats/Cube.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/StdStreams.h"
#include "lut/match/Match.h"
#include "lut/match/MatchReportImage.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/SceneKind.h"
#include "lut/smash/PurposeConversion.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <sstream>

namespace lut::cli {

namespace {

struct ReadPicture {
    formats::LoadedImage image; // every step-th pixel of a large file (info: the whole file's)
    SceneDecision scene;
    int step = 1;
};

// The grid the fit samples (lut::matchSampleStep) is all that is read of a large picture: a
// 16384^2 PNG is a 2048^2 frame, not a 4 GiB one. Standard input is read whole.
int pictureStep(const std::string& path, bool source, std::size_t references) {
    if (isStdinName(path))
        return 1;
    const formats::ImageInfo info = formats::readImageInfo(path);
    return matchSampleStep(info.width, info.height, source, references);
}

ReadPicture readPicture(const std::string& path, int step) {
    ReadPicture p;
    p.step = step;
    p.image = formats::readImageSampled(path, step);
    const auto& i = p.image.info;
    p.scene = decideSceneKind(SceneEvidence{i.isFloat, i.bitDepth, i.colorSpace, i.format});
    return p;
}

MatchPicture matchPicture(const ReadPicture& p, const std::string& name,
                          const formats::LoadedImage* mask) {
    MatchPicture m;
    m.pixels = p.image.image.view();
    m.linear = p.scene.storedIsLinear;
    m.bitDepth = p.image.info.isFloat ? 0 : p.image.info.bitDepth;
    m.name = name;
    m.step = p.step;
    m.fullWidth = p.image.info.width;
    m.fullHeight = p.image.info.height;
    if (mask) {
        m.mask = mask->image.view();
        m.maskFullWidth = mask->info.width;
        m.maskFullHeight = mask->info.height;
    }
    return m;
}

std::string distanceJson(const DistributionDistance& d) {
    return "{\"sliced_wasserstein\": " + json::number(d.slicedWasserstein) +
           ", \"quantile_delta_e2000\": " + json::number(d.quantileDeltaE) + "}";
}

std::string gameErrorJson(const GameError& e) {
    return "{\"max\": " + json::number(e.maxSteps) + ", \"mean\": " + json::number(e.meanSteps) +
           ", \"p99\": " + json::number(e.p99Steps) + "}";
}

void printJson(const MatchCommandOptions& o, const MatchReport& r, const Diagnostics& diags,
               bool smash, const SmashAuthoringResult* game) {
    std::ostringstream s;
    s << "{\"source\": " << json::quote(o.source) << ", \"references\": [";
    for (std::size_t i = 0; i < o.references.size(); ++i)
        s << (i ? ", " : "") << json::quote(o.references[i]);
    s << "], \"output\": " << json::quote(o.output)
      << ", \"target\": " << json::quote(smash ? "smash" : "raw")
      << ",\n \"method\": " << json::quote(toString(r.method))
      << ", \"asked\": " << json::quote(toString(r.asked))
      << ", \"choice\": " << json::quote(r.choice)
      << ",\n \"look\": {\"kind\": " << json::quote(r.look)
      << ", \"curve_rms_steps\": " << json::number(r.lookRmsSteps)
      << "},\n \"form\": {\"shaper\": " << (r.shaper ? "true" : "false");
    if (r.bothForms)
        s << ", \"table_alone_steps\": " << gameErrorJson(r.tableAloneError)
          << ", \"shaper_steps\": " << gameErrorJson(r.shaperError);
    s << "},\n \"candidates\": [";
    for (std::size_t i = 0; i < r.candidates.size(); ++i)
        s << (i ? ", " : "") << "{\"method\": " << json::quote(toString(r.candidates[i].method))
          << ", \"after\": " << distanceJson(r.candidates[i].after)
          << ", \"seconds\": " << json::number(r.candidates[i].seconds)
          << ", \"eligible\": " << (r.candidates[i].eligible ? "true" : "false")
          << ", \"shape_problem\": " << json::quote(r.candidates[i].shapeProblem) << "}";
    s << "],\n \"before\": " << distanceJson(r.before) << ", \"after\": " << distanceJson(r.after)
      << ",\n \"interpolation_steps\": " << gameErrorJson(r.interpolation)
      << ", \"interpolation_colours\": " << r.interpolationColours
      << ",\n \"quality\": {\"monotone_own_axes\": "
      << (r.quality.decreasingSteps == 0 ? "true" : "false")
      << ", \"decreasing_steps\": " << r.quality.decreasingSteps
      << ", \"smallest_slope\": " << json::number(r.quality.smallestSlope)
      << ", \"largest_slope\": " << json::number(r.quality.largestSlope)
      << ", \"monotone_grey\": " << (r.quality.monotoneAlongGrey ? "true" : "false")
      << ", \"folded_cells\": " << r.quality.foldedCells
      << ", \"flat_cells\": " << r.quality.flatCells << ", \"cells\": " << r.quality.cells
      << ", \"largest_second_difference_steps\": "
      << json::number(r.quality.largestSecondDifference)
      << "},\n \"sharp_second_match\": " << (r.sharpSecondMatch ? "true" : "false")
      << ",\n \"repaired\": {\"grey_drop_steps\": " << json::number(r.greyDipRepaired)
      << ", \"grey_nodes_moved\": " << r.greyNodesMoved
      << ", \"largest_move_steps\": " << json::number(r.greyLargestMove)
      << "},\n \"clipped\": {\"values\": " << r.clippedValues << ", \"of\": " << r.values
      << ", \"max_steps\": " << json::number(r.clippedMaxSteps)
      << ", \"table_values\": " << r.tableValuesOutside << ", \"table_of\": " << r.tableValues
      << "},\n \"pixels\": {\"source\": " << r.sourcePixels
      << ", \"source_counted\": " << r.sourceUsed << ", \"reference\": " << r.referencePixels
      << ", \"reference_counted\": " << r.referenceUsed
      << "},\n \"seconds\": {\"fit\": " << json::number(r.secondsFit)
      << ", \"lut\": " << json::number(r.secondsBake)
      << ", \"measure\": " << json::number(r.secondsMeasure)
      << ", \"total\": " << json::number(r.secondsTotal()) << "}";
    if (game)
        s << ",\n \"in_game\": {\"measured_over\": " << json::quote(game->measuredOver)
          << ", \"error\": " << gameErrorJson(game->exactError)
          << ", \"clamped\": " << game->clampedEntries << "}";
    s << ",\n \"diagnostics\": " << json::diagnostics(diags) << "}\n";
    std::cout << s.str();
}

} // namespace

int runMatch(const MatchCommandOptions& o) {
    std::vector<std::string> inputs{o.source};
    inputs.insert(inputs.end(), o.references.begin(), o.references.end());
    if (!o.maskSource.empty())
        inputs.push_back(o.maskSource);
    inputs.insert(inputs.end(), o.maskReferences.begin(), o.maskReferences.end());
    if (!o.originalLut.empty())
        inputs.push_back(o.originalLut);
    if (o.maskReferences.size() > o.references.size())
        throw UsageError("--mask-reference is given " + std::to_string(o.maskReferences.size()) +
                         " times for " + std::to_string(o.references.size()) +
                         " reference(s): the n-th masks the n-th REFERENCE");
    // Where OUT goes and what it is for (lut/formats/LutDestination.h): the game's LUT when
    // --target says so or OUT is the game's format.
    const bool smash = formats::resolveLutDestination(
                           {o.output, o.format, purposeOption(o.target), o.size, o.layout, 0})
                           .forGame();
    if (!smash && !o.originalLut.empty())
        throw UsageError("--original-lut is for --target smash");
    if (!beginOutput(o.output, o.overwrite, inputs, o.verbosity.quiet))
        return kExitOk;
    const bool writeReport =
        !o.reportImage.empty() && resolveOutput(o.reportImage, o.overwrite, inputs).skip == false;

    const std::size_t nrefs = o.references.size();
    ReadPicture source = readPicture(o.source, pictureStep(o.source, true, nrefs));
    std::vector<ReadPicture> refs;
    for (const auto& r : o.references)
        refs.push_back(readPicture(r, pictureStep(r, false, nrefs)));
    // A mask is read on its picture's grid.
    formats::LoadedImage maskSource;
    std::vector<formats::LoadedImage> maskRefs;
    if (!o.maskSource.empty())
        maskSource = formats::readImageSampled(o.maskSource, source.step);
    for (std::size_t i = 0; i < o.maskReferences.size(); ++i)
        maskRefs.push_back(formats::readImageSampled(o.maskReferences[i], refs[i].step));

    std::ostringstream text;
    Lut3D stage;
    if (smash) {
        if (!o.originalLut.empty())
            stage = readStageLut(o.originalLut, o.verbosity);
        if (source.scene.kind == SceneKind::Scene) {
            // A scene: what the game shows of it, through its own post-processing.
            PipelineSettings ps;
            ps.preset = Preset::Smash;
            if (!o.originalLut.empty())
                ps.lut = std::make_shared<const Lut3D>(stage);
            Pipeline p(ps);
            const Image shown = p.run(source.image.image);
            source.image.image = shown;
            source.scene.storedIsLinear = false;
            text << "source   " << o.source << ": " << source.scene.reason
                 << "; matched as the game shows it (smash preset)\n";
        } else {
            text << "source   " << o.source << ": " << source.scene.reason << "\n";
        }
    }

    MatchPicture src = matchPicture(source, o.source, o.maskSource.empty() ? nullptr : &maskSource);
    std::vector<MatchPicture> references;
    for (std::size_t i = 0; i < refs.size(); ++i)
        references.push_back(
            matchPicture(refs[i], o.references[i], i < maskRefs.size() ? &maskRefs[i] : nullptr));
    MatchOptions mo;
    mo.method = o.method;
    mo.form = o.form;
    mo.size = o.size;
    mo.strength = o.strength.strength;
    mo.lumaStrength = o.strength.luma;
    mo.chromaStrength = o.strength.chroma;
    mo.preserve = o.preserve;
    MatchResult res = matchLook(src, references, mo);
    Diagnostics diags = res.diagnostics;

    LutFile out;
    SmashAuthoringResult game;
    if (smash) {
        // The match made into the game's LUT as lutkit convert makes one
        // (lut/smash/PurposeConversion.h), measured over the screenshot's colours.
        PurposeOptions po;
        po.stageLut = o.originalLut.empty() ? nullptr : &stage;
        // The screenshot as read (what the fit sampled: every step-th pixel of a large one).
        ImageView shotView;
        if (source.scene.kind == SceneKind::Screenshot) {
            shotView = source.image.image.view();
            po.screenshot = &shotView;
        }
        po.measure = true;
        Lut3D edit = res.lut.toLut3D(33);
        edit.setTitle(res.lut.cube->title());
        PurposeConversion c = convertPurpose(edit, LutPurpose::Raw, LutPurpose::Smash, po);
        ConversionWords w;
        w.stage = o.originalLut.empty() ? "neutral" : o.originalLut;
        printConversion(text, c, w);
        out.cube = std::move(c.lut);
        out.purpose = LutPurpose::Smash;
        game = std::move(c.authoring);
    } else {
        out = res.lut;
        out.purpose = LutPurpose::Raw; // a match is an edit
    }
    FormatOptions wo;
    wo.layout = o.layout;
    const Diagnostics wd = formats::writeLut(o.output, out, wo, o.format);
    diags.insert(diags.end(), wd.begin(), wd.end());
    // A .cube with a shaper is Resolve's form, which ffmpeg's lut3d ("Invalid data found"),
    // Photoshop's Color Lookup and most engines refuse: said, with the form they read.
    if (!smash && out.shaper && o.format.empty() && o.form == MatchLutForm::Auto &&
        extensionOf(o.output) == ".cube") {
        diags.push_back(formats::resolveCubeReadersWarning(
            o.output, "the look needs it",
            res.report.bothForms
                ? "the table alone would be " + res.report.tableAloneError.str() + " from the match"
                : std::string(),
            "the shaper baked in"));
    }
    if (writeReport) {
        MatchReportPicture a{src.pixels, src.linear};
        MatchReportPicture b{references.front().pixels, references.front().linear};
        formats::ImageWriteOptions w;
        w.bitDepth = 8;
        w.alpha = false;
        formats::writeImage(o.reportImage, matchReportImage(a, res.lut, b), w);
    }
    if (o.json) {
        printJson(o, res.report, diags, smash, smash ? &game : nullptr);
        return kExitOk;
    }
    std::cout << res.report.str() << text.str();
    printDiagnostics(std::cout, diags, o.verbosity, "");
    std::cout << "wrote    " << o.output << ": "
              << (smash ? "the game's 16^3 LUT"
                        : std::to_string(o.size) + "^3 table" +
                              (res.lut.shaper ? " after a 1D shaper" : std::string()))
              << "\n";
    if (writeReport)
        std::cout << "wrote    " << o.reportImage
                  << ": source, result and reference with their histograms\n";
    return kExitOk;
}

CLI::App* setupMatch(CLI::App& app, std::function<void(const MatchCommandOptions&)> onParsed) {
    auto o = std::make_shared<MatchCommandOptions>();
    auto* sub = app.add_subcommand(
        "match", "Make a LUT that gives a picture the look of one or more reference pictures");
    sub->add_option("SOURCE", o->source, "the picture to change (screenshot, frame, photo)")
        ->required()
        ->type_name("FILE");
    sub->add_option("REFERENCE", o->references,
                    "the picture(s) whose look to take; several are pooled")
        ->required()
        ->expected(1, -1)
        ->type_name("FILE");
    // CLI11 gives every file after SOURCE to REFERENCE: OUT is the last of them (see callback).
    sub->add_option("OUT", o->output,
                    "output LUT, the last file named (any format; .nutexb: the game's LUT)")
        ->type_name("FILE");
    sub->add_option("--size", o->size, "LUT size (default 33)")->check(CLI::Range(2, 129));
    sub->add_option_function<std::string>(
           "--method", [o](const std::string& v) { o->method = parseMatchMethod(v); },
           "auto (default: hm-mkl-hm, or regularised or gradient-map when its LUT is clean and "
           "10% closer to the reference), hm (per-channel histograms), mkl (Monge-Kantorovich 3x3 "
           "+ offset), "
           "hm-mkl-hm, regularised (smooth monotone lattice for looks the others miss), "
           "gradient-map (a colour per luma: palettes, gradient maps, duotones, sepia)")
        ->check(choicesValidator(matchMethodChoices()))
        ->type_name("NAME");
    sub->add_option_function<std::string>(
           "--lut-form",
           [o](const std::string& v) {
               o->form = v == "shaper"  ? MatchLutForm::ShaperTable
                         : v == "table" ? MatchLutForm::Table
                                        : MatchLutForm::Auto;
           },
           "auto (default: a 3D table alone, which every program reads, unless the look needs a "
           "1D shaper before it; the report gives both errors), shaper (a 1D shaper and the table: "
           "DaVinci Resolve's .cube), table (the table alone)")
        ->check(choicesValidator(matchShaperChoices()))
        ->type_name("NAME");
    addStrengthOptions(*sub, o->strength); // as convert, apply, preview and extract
    sub->add_option_function<std::vector<std::string>>(
           "--preserve",
           [o](const std::vector<std::string>& v) {
               for (const auto& s : v)
                   o->preserve.push_back(parseMatchPreserve(s));
           },
           "keep the source's luma (take only colour), neutrals (greys stay grey) or skin (skin "
           "tones keep their hue and chroma); may be repeated")
        ->check(choicesValidator(preserveChoices()))
        ->type_name("NAME")
        ->delimiter(',');
    sub->add_option("--mask-source", o->maskSource,
                    "SOURCE's pixels to use: white = use, black = ignore (HUD, sky...)")
        ->type_name("FILE");
    sub->add_option("--mask-reference", o->maskReferences,
                    "the same for a REFERENCE (the n-th mask for the n-th reference)")
        ->type_name("FILE");
    sub->add_option("--target", o->target,
                    "raw (the LUT itself; default) or smash (the LUT that makes Smash Ultimate "
                    "show the match of its screenshot; default for a .nutexb)")
        ->check(choicesValidator(targetChoices()))
        ->type_name("NAME");
    sub->add_option("--original-lut", o->originalLut,
                    "smash: the stage's LUT SOURCE was taken with (default neutral)")
        ->type_name("FILE");
    sub->add_option("--report-image", o->reportImage,
                    "write a PNG: source, result and reference side by side with histograms")
        ->type_name("FILE");
    sub->add_flag("--json", o->json, "print the report as JSON");
    addOutputFormat(*sub, o->format);
    addLayout(*sub, "--layout", o->layout, "output LUT image layout (default unreal)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer(
        "Pictures are read as `apply` reads them: integer files are display-encoded (sRGB), "
        "float files scene-linear; a reference of the other kind is converted. The report gives "
        "the distance to the reference's colours before and after (sliced Wasserstein in "
        "CIELAB, mean ΔE2000 of matched quantiles), how the LUT interpolates, what it clips and "
        "the time taken (" LUTKIT_DOC_DIR "/docs/match.md).\n\n"
        "Examples:\n"
        "  lutkit match stage.png look.png look.cube\n"
        "  lutkit match shot.png ref1.jpg ref2.jpg look.cube --method hm-mkl-hm --strength 0.7\n"
        "  lutkit match shot.png film.png color_grading_lut.nutexb --preserve skin\n"
        "  lutkit match shot.png ref.png look.cube --mask-source hud.png --report-image cmp.png "
        "--json");
    sub->callback([o, onParsed] {
        MatchCommandOptions parsed = *o;
        if (parsed.output.empty()) {
            if (parsed.references.size() < 2)
                throw UsageError("name SOURCE, at least one REFERENCE and OUT");
            parsed.output = parsed.references.back();
            parsed.references.pop_back();
        }
        onParsed(parsed);
    });
    return sub;
}

} // namespace lut::cli
