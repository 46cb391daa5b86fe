// SPDX-License-Identifier: Apache-2.0
// lutkit neutral: the identity LUT in any writable format.
#include "commands/Neutral.h"

#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/formats/Hald.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Nutexb.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runNeutral(const NeutralOptions& o) {
    const OutputTarget target = resolveOutput(o.output, o.overwrite, {});
    if (target.skip) {
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: " << printable(o.output) << " exists; skipped (-n)\n";
        return kExitOk;
    }
    // Where it goes, decided once (lut/formats/LutDestination.h): the writer, the Hald level's
    // rule (N = L^2, a LUT image only), the size the format fixes.
    const formats::LutDestination dest = formats::resolveLutDestination(
        {o.output, o.format, std::nullopt, o.size, o.layout, o.level});
    const Format* writer = &dest.requireWriter();
    const std::optional<LutLayout> layout = dest.layout;
    const bool hald = dest.hald;
    if (layout)
        if (const std::string problem = layoutSizeProblem(*layout, o.size); !problem.empty())
            throw UsageError(problem);
    const int asked = dest.newTableSize(kNeutralSize);
    // A Hald image holds N = L^2 only: say so rather than write another size than the one named.
    const int size = hald ? formats::haldSizeFor(asked) : asked;
    LutFile file;
    file.cube = Lut3D::identity(size);
    file.cube->setTitle(o.title.empty() ? "neutral " + std::to_string(size) : o.title);
    FormatOptions options;
    options.layout = layout;
    options.size = size;
    options.bitDepth = o.bitDepth;
    if (!o.name.empty())
        options.setAttribute(formats::nutexb::kNameAttribute, o.name);
    const Diagnostics diags = formats::writeLut(o.output, file, options, writer->name());
    std::cout << "wrote " << o.output << ": " << writer->name() << ", neutral "
              << (hald ? formats::haldSizeText(size) : std::to_string(size) + "^3");
    if (layout)
        std::cout << ", layout " << toString(*layout);
    if (o.bitDepth)
        std::cout << ", " << o.bitDepth << "-bit";
    std::cout << "\n";
    if (o.verbosity.verbose)
        std::cout << "  " << writer->name() << ": " << writer->description() << "\n";
    if (hald && size != asked && !o.verbosity.quiet)
        std::cout << "  note: --size " << asked << " is not a square; a Hald image stores N = "
                  << "L^2, so " << formats::haldSizeText(size)
                  << " was written (--level L asks for N = L^2)\n";
    printDiagnostics(std::cout, diags, o.verbosity);
    return kExitOk;
}

CLI::App* setupNeutral(CLI::App& app, std::function<void(const NeutralOptions&)> onParsed) {
    auto o = std::make_shared<NeutralOptions>();
    auto* sub = app.add_subcommand("neutral", "Write a neutral (identity) LUT in any format");
    sub->add_option("OUT", o->output, "output file (format from the extension)")
        ->required()
        ->type_name("FILE");
    auto* size =
        sub->add_option("--size", o->size,
                        "lattice size N (N^3; default: the format's fixed size; 16 for images; 33 "
                        "otherwise)")
            ->check(CLI::Range(2, 256));
    sub->add_option("--level", o->level,
                    "Hald level L as ImageMagick's hald:L (N = L^2, an L^3 x L^3 image)")
        ->check(CLI::Range(formats::kMinHaldLevel, formats::kMaxHaldLevel))
        ->excludes(size);
    addOutputFormat(*sub, o->format);
    addLayout(*sub, "--layout", o->layout,
              "LUT images: the layout (default unreal, 256x16; reshade and unity-32 are 1024x32)");
    addBitDepth(*sub, o->bitDepth, "LUT images: 8, 16 or 32 (float)");
    sub->add_option("--name", o->name, "nutexb name field (default color_grading_lut)");
    sub->add_option("--title", o->title, "title stored where the format has one");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "also describe the format written");
    sub->footer("Examples:\n"
                "  lutkit neutral neutral.png                    # 256x16 strip to grade in an "
                "image editor\n"
                "  lutkit neutral color_grading_lut.nutexb       # Smash Ultimate's 16^3 "
                "neutral\n"
                "  lutkit neutral --size 65 identity.cube\n"
                "  lutkit neutral --level 8 hald8.png                # ImageMagick's hald:8, "
                "64^3\n"
                "  lutkit neutral --layout unity --bit-depth 16 unity_neutral.png\n"
                "  lutkit neutral --layout reshade lut.png           # ReShade's LUT.fx, 1024x32");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
