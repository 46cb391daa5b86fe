// lutkit apply: a LUT on the stored pixel values of images (like Photoshop's Color Lookup).
#include "commands/Apply.h"

#include "Batch.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <mutex>

namespace lut::cli {

int runApply(const ApplyOptions& o) {
    const std::vector<BatchJob> jobs = planBatch(o.inputs, o.outputDir);
    FormatOptions lutOptions;
    lutOptions.layout = o.lutLayout;
    const LutFile file = formats::readLut(o.lut, lutOptions);
    printDiagnostics(std::cerr, file.diagnostics, o.verbosity, "lutkit: ");
    if (o.verbosity.verbose)
        if (const std::string d = layoutDetail(file, o.lutLayout.has_value(), "--lut-layout");
            !d.empty())
            std::cerr << "lutkit: " << o.lut << ": " << d << "\n";
    const Lut3D lut = file.toLut3D();
    const formats::ColorPlan plan = formats::planColor(o.color);
    printDiagnostics(std::cerr, plan.diagnostics, o.verbosity, "lutkit: ");
    if (o.verbosity.verbose && o.color.any())
        std::cerr << "lutkit: " << plan.describe() << "\n";
    std::mutex noteMutex;
    return runBatch(jobs, o.threads, o.verbosity.quiet, [&](const BatchJob& j, int inner) {
        formats::LoadedImage img = formats::readImage(j.input);
        std::shared_ptr<const DomainProbe> probe;
        formats::lutPixelChain(plan, lut, o.interp, &probe).apply(img.image.view(), inner);
        if (const DomainExcess e = probe->result(); e.any()) {
            std::lock_guard lock(noteMutex);
            std::cerr << "lutkit: warning: " << j.input << ": " << e.str()
                      << ": the LUT clamps them to its edge"
                      << (o.color.any() ? ""
                                        : " (--from/--lut-space put the image in the "
                                          "space the LUT was made for)")
                      << "\n";
        }
        formats::ImageWriteOptions w;
        w.bitDepth = img.info.isFloat || img.info.bitDepth == 0 ? 32 : img.info.bitDepth;
        w.alpha =
            (img.info.channels == 2 || img.info.channels >= 4) && formats::canHoldAlpha(j.output);
        formats::writeImage(j.output, img.image, w);
        return o.verbosity.verbose ? j.input + " -> " + j.output + "\n" : std::string();
    });
}

CLI::App* setupApply(CLI::App& app, std::function<void(const ApplyOptions&)> onParsed) {
    auto o = std::make_shared<ApplyOptions>();
    auto* sub = app.add_subcommand(
        "apply", "Apply a LUT to the stored pixel values of images (alpha and bit depth kept), or "
                 "in its own colour space (--from)");
    sub->add_option("--lut", o->lut, "LUT file (any supported format)")
        ->required()
        ->type_name("FILE");
    addLayout(*sub, "--lut-layout", o->lutLayout,
              "the LUT's layout when it is an image (default: detected)");
    sub->add_option("FILES", o->inputs, "IN OUT, or input files/folders with -o DIR")
        ->type_name("FILE");
    sub->add_option("-o,--output-dir", o->outputDir,
                    "batch: write DIR/<input name> for every input")
        ->type_name("DIR");
    addInterp(*sub, o->interp, "interpolation (default tetrahedral)");
    addThreads(*sub, o->threads);
    addColorOptions(*sub, o->color, ColorOptionSet::All);
    addVerbosity(*sub, o->verbosity, "print IN -> OUT for every file written");
    sub->footer("Examples:\n"
                "  lutkit apply --lut grade.cube shot.png graded.png\n"
                "  lutkit apply --lut grade.cube frames/ -o graded/     # every image in frames/\n"
                "  lutkit apply --lut edited_strip.png --lut-layout unity in.tif out.tif\n"
                "  lutkit apply --lut log_look.cube --from ACEScg --lut-space ACEScct --to sRGB "
                "render.exr out.png");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
