// SPDX-License-Identifier: Apache-2.0
// lutkit bake: prints what lut::formats::bake did and what it cost.
#include "commands/Bake.h"

#include "Json.h"
#include "Numbers.h"
#include "Usage.h"
#include "Vocabulary.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

namespace lut::cli {

namespace {

void printJson(const std::string& output, const formats::BakeReport& r) {
    std::cout << "{\"output\": " << json::quote(output)
              << ", \"format\": " << json::quote(r.outputFormat)
              << ",\n \"baked\": " << json::quote(r.what)
              << ", \"config\": " << json::quote(r.configUsed)
              << ",\n \"cube_size\": " << r.cubeSize << ", \"shaper_size\": " << r.shaperSize
              << ", \"shaper\": " << json::quote(r.shaper)
              << ", \"domain_min\": " << json::vec3(r.domainMin)
              << ", \"domain_max\": " << json::vec3(r.domainMax)
              << ",\n \"error\": " << json::stats(r.error)
              << ", \"measured_file\": " << (r.measuredFile ? "true" : "false")
              << ", \"read_back_error\": "
              << (r.readBackError.empty() ? "null" : json::quote(r.readBackError))
              << ",\n \"diagnostics\": " << json::diagnostics(r.diagnostics)
              << ",\n \"sample_seconds\": " << json::number(r.sampleSeconds)
              << ", \"write_seconds\": " << json::number(r.writeSeconds)
              << ", \"seconds\": " << json::number(r.totalSeconds) << "}\n";
}

void printText(const std::string& output, const formats::BakeReport& r,
               const Verbosity& verbosity) {
    std::cout << "baked    " << r.what << "\n";
    if (!r.configUsed.empty())
        std::cout << "config   " << r.configUsed << "\n";
    if (r.cubeSize == 0) {
        std::cout << "table    " << r.shaper << ", " << r.shaperSize << " entries over "
                  << significant(r.domainMin.x, 6) << ".." << significant(r.domainMax.x, 6) << ", "
                  << milliseconds(r.sampleSeconds) << "\n";
    } else {
        if (r.shaperSize)
            std::cout << "shaper   " << r.shaper << ", " << r.shaperSize << " entries\n";
        else
            std::cout << "shaper   " << r.shaper << "\n";
        std::cout << "table    " << r.cubeSize << "^3 over " << significant(r.domainMin.x, 6)
                  << ".." << significant(r.domainMax.x, 6)
                  << (r.shaperSize ? " (through the shaper)" : "") << ", "
                  << milliseconds(r.sampleSeconds) << "\n";
    }
    std::cout << "wrote    " << output << ": " << r.outputFormat << ", "
              << milliseconds(r.writeSeconds) << "\n";
    printDiagnostics(std::cout, r.diagnostics, verbosity);
    std::cout << "error    "
              << (r.measuredFile ? "the file read back"
                                 : "the table (the file cannot be read "
                                   "back: " +
                                       r.readBackError + ")")
              << " against "
              // a config's conversion baked, else the files OpenColorIO read
              << (r.configUsed.empty() ? "OpenColorIO's processor" : "the conversion") << ": "
              << r.error.str() << "\n";
    if (r.error.bounded)
        std::cout << "         max: " << r.error.coverage() << "\n";
    std::cout << "total    " << milliseconds(r.totalSeconds) << "\n";
}

} // namespace

void printBakeReport(const std::string& output, const formats::BakeReport& report, bool json,
                     const Verbosity& verbosity) {
    if (json)
        printJson(output, report);
    else
        printText(output, report, verbosity);
}

int runBake(const BakeCommandOptions& o) {
    // --cccid picks a correction of the --lut/--invlut files after it: with none, it would be
    // ignored without a word.
    const bool cccidUsed =
        std::any_of(o.bake.files.begin(), o.bake.files.end(),
                    [](const formats::BakeFileStep& f) { return !f.cccid.empty(); });
    if (!o.cccid.empty() && !cccidUsed)
        throw UsageError("--cccid " + o.cccid +
                         ": no --lut or --invlut follows it (it picks a correction of a .ccc or "
                         ".cdl file named after it)");
    std::vector<std::string> inputs = {o.bake.lut, o.bake.config};
    for (const auto& f : o.bake.files)
        inputs.push_back(f.path);
    if (!beginOutput(o.output, o.overwrite, inputs, o.verbosity.quiet))
        return kExitOk;
    printBakeReport(o.output, formats::bake(o.output, o.bake), o.json, o.verbosity);
    return kExitOk;
}

CLI::App* setupBake(CLI::App& app, std::function<void(const BakeCommandOptions&)> onParsed) {
    auto o = std::make_shared<BakeCommandOptions>();
    auto* sub = app.add_subcommand(
        "bake", "Bake an OpenColorIO conversion or LUT files into a LUT (like ociobakelut), "
                "reporting its error");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension or --format)")
        ->required()
        ->type_name("FILE");
    const std::string cfg = "Using a config";
    addConfig(*sub, o->bake.config)->group(cfg);
    sub->add_option("--iconfig", o->bake.config, "the same as --config (ociobakelut's name)")
        ->type_name("FILE")
        ->group(cfg);
    sub->add_option("--inputspace", o->bake.inputSpace, "input colour space (or role)")
        ->type_name("SPACE")
        ->group(cfg);
    sub->add_option("--outputspace", o->bake.outputSpace, "output colour space (or role)")
        ->type_name("SPACE")
        ->group(cfg);
    sub->add_option("--look", o->bake.looks, "OpenColorIO looks to apply (\"a, +b, -c\")")
        ->type_name("LOOKS")
        ->group(cfg);
    sub->add_option("--looks", o->bake.looks, "the same as --look (ociobakelut's name)")
        ->type_name("LOOKS")
        ->group(cfg);
    sub->add_option("--display", o->bake.display, "bake to this display (instead of --outputspace)")
        ->type_name("DISPLAY")
        ->group(cfg);
    sub->add_option("--view", o->bake.view, "the display's view (default: its first)")
        ->type_name("VIEW")
        ->group(cfg);

    const std::string files = "Config-free: LUT files, applied in order through OpenColorIO";
    sub->add_option_function<std::string>(
           "--cccid", [o](const std::string& v) { o->cccid = v; },
           "the CCC id (or index) of the .ccc/.cdl files named after it")
        ->type_name("ID")
        ->trigger_on_parse()
        ->group(files);
    sub->add_option_function<std::string>(
           "--lut",
           [o](const std::string& v) {
               o->bake.files.push_back({v, o->cccid, false});
           },
           "a LUT file of any format OpenColorIO reads (repeatable)")
        ->type_name("FILE")
        ->trigger_on_parse()
        ->group(files);
    sub->add_option_function<std::string>(
           "--invlut",
           [o](const std::string& v) {
               o->bake.files.push_back({v, o->cccid, true});
           },
           "a LUT file applied inverted (repeatable)")
        ->type_name("FILE")
        ->trigger_on_parse()
        ->group(files);

    const std::string baking = "Baking";
    addOutputFormat(*sub, o->bake.format)->group(baking);
    sub->add_option("--cubesize", o->bake.cubeSize,
                    "lattice size (default: ociobakelut's for the format: flame 17, lustre 33, "
                    "iridas_cube, cinespace, truelight 32, resolve_cube, iridas_itx, houdini, clf, "
                    "ctf 64; a fixed size where the format has one; else 33)")
        ->check(CLI::Range(2, 256))
        ->group(baking);
    sub->add_option("--size", o->bake.cubeSize, "the same as --cubesize")
        ->check(CLI::Range(2, 256))
        ->group(baking);
    sub->add_option("--shaperspace", o->bake.shaperSpace,
                    "colour space whose curve shapes the input before the table")
        ->type_name("SPACE")
        ->group(baking);
    sub->add_option_function<std::string>(
           "--shaper",
           [o](const std::string& v) {
               o->bake.shaper = v == "none"   ? formats::ShaperChoice::None
                                : v == "log2" ? formats::ShaperChoice::Log2
                                              : formats::ShaperChoice::Auto;
           },
           "auto (log2 for scene-linear input when the format holds a shaper), none or log2")
        ->type_name("NAME")
        ->check(choicesValidator(shaperChoices()))
        ->group(baking);
    sub->add_option("--shaper-size,--shapersize", o->bake.shaperSize,
                    "shaper entries (default 4096)")
        ->check(CLI::Range(2, 65536))
        ->group(baking);
    addLayout(*sub, "--layout", o->bake.write.layout, "LUT image output layout (default unreal)")
        ->group(baking);
    addBitDepth(*sub, o->bake.write.bitDepth, "LUT image output: 8, 16 or 32 (float)")
        ->group(baking);
    sub->add_flag("--json", o->json, "print the report as JSON");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer(
        "Format names: lutkit's (--format NAME) and ociobakelut's: flame, lustre, 3dl, "
        "cinespace, resolve_cube,\n  iridas_cube, iridas_itx, truelight, houdini, \"Academy/ASC "
        "Common LUT Format\", \"Color Transform Format\".\n"
        "Formats that hold a shaper (.cube, .clf, .ctf, .csp) get a log2 shaper for scene-linear "
        "input.\n\n"
        "Examples:\n"
        "  lutkit bake --inputspace ACEScg --outputspace sRGB acescg_to_srgb.cube\n"
        "  lutkit bake --config studio.ocio --inputspace lg10 --outputspace srgb8 --format flame "
        "lg.3dl\n"
        "  lutkit bake --lut film.3dl --lut calibration.3dl --format resolve_cube display.cube\n"
        "  lutkit bake --cccid shot042 --lut grades.ccc --cubesize 65 shot042.clf\n"
        "  lutkit bake --inputspace ACEScct --display sRGB --view Standard --cubesize 65 "
        "view.cube");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
