// SPDX-License-Identifier: Apache-2.0
// lutkit check: lut::checkLut's report for each LUT file, as text or JSON, and its picture.
#include "commands/Check.h"

#include "Json.h"
#include "PurposeText.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/LutPurpose.h"
#include "lut/Version.h"
#include "lut/check/CheckLut.h"
#include "lut/check/CheckPicture.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"
#include "lut/io/StdStreams.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"
#include "lut/smash/SmashShownEdit.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace lut::cli {

namespace {

constexpr std::size_t kMaxThresholdsBytes = 1 << 20;

std::string jvec(glm::vec3 v) {
    return "[" + json::number(v.x) + ", " + json::number(v.y) + ", " + json::number(v.z) + "]";
}

std::string findingJson(const CheckFinding& f, int number) {
    return "{\"number\": " + std::to_string(number) +
           ", \"check\": " + json::quote(toString(checkOf(f.kind))) +
           ", \"kind\": " + json::quote(toString(f.kind)) +
           ", \"severity\": " + json::quote(toString(f.severity)) + ", \"channel\": " +
           (f.channel >= 0 ? json::quote(std::string(1, "RGB"[f.channel])) : "null") +
           ", \"where\": " + json::quote(f.where) + ", \"input\": " + jvec(f.input) +
           ", \"output\": " + jvec(f.output) + ", \"cell\": " +
           (f.cell.x >= 0 ? "[" + std::to_string(f.cell.x) + ", " + std::to_string(f.cell.y) +
                                ", " + std::to_string(f.cell.z) + "]"
                          : std::string("null")) +
           ", \"size\": " + json::number(f.size) + ", \"unit\": " + json::quote(toString(f.unit)) +
           ", \"share\": " + json::number(f.share) + ", \"detail\": " + json::quote(f.detail) + "}";
}

std::string figuresJson(const CheckFigures& f) {
    return "{\"worst_fold_over\": " + json::number(f.worstFold) +
           ", \"fold_over_share\": " + json::number(f.foldShare) +
           ", \"grey_worst_fold_over\": " + json::number(f.greyWorstFold) +
           ", \"worst_flat\": " + json::number(f.worstFlat) +
           ", \"worst_step\": " + json::number(f.worstStep) +
           ", \"steepest\": " + json::number(f.steepest) +
           ", \"banding_share\": " + json::number(f.bandingShare) +
           ", \"worst_hue_shift\": " + json::number(f.worstHueShift) +
           ", \"worst_hue\": " + json::number(f.worstHue) +
           ", \"mean_hue_shift\": " + json::number(f.meanHueShift) +
           ", \"skin_drift\": " + json::number(f.skinDrift) +
           ", \"non_finite\": " + std::to_string(f.nonFinite) +
           ", \"out_of_range_share\": " + json::number(f.outOfRangeShare) +
           ", \"output_min\": " + jvec(f.outputMin) + ", \"output_max\": " + jvec(f.outputMax) +
           ", \"clipped_share\": " +
           jvec(glm::vec3(f.clippedShare[0], f.clippedShare[1], f.clippedShare[2])) +
           ", \"gamut_coverage\": " + json::number(f.gamutCoverage) +
           ", \"image_outside_domain\": " + json::number(f.imageOutsideDomain) +
           ", \"worst_second_difference\": " + json::number(f.worstRough) +
           ", \"total_variation_ratio\": " + json::number(f.totalVariationRatio) +
           ", \"folded_share\": " + json::number(f.foldedShare) +
           ", \"worst_folded_at\": " + jvec(f.worstFolded) +
           ", \"flat_share\": " + json::number(f.flatShare) + ", \"neutral\": " +
           (f.neutralMeasured ? "{\"max_delta_e2000\": " + json::number(f.neutralMaxDeltaE) +
                                    ", \"mean_delta_e2000\": " + json::number(f.neutralMeanDeltaE) +
                                    ", \"max_8bit_steps\": " + json::number(f.neutralMaxSteps) + "}"
                              : std::string("null")) +
           "}";
}

std::string reportJson(const std::string& path, const CheckReport& r, CheckStatus verdict,
                       const std::string& picture) {
    std::string s =
        "{\"file\": " + json::quote(path) + ", \"status\": " + json::quote(toString(verdict)) +
        ", \"description\": " + json::quote(r.description) +
        ", \"over\": " + json::quote(r.image ? "picture" : "cube") + ",\n  \"checks\": [";
    for (std::size_t i = 0; i < r.checks.size(); ++i)
        s += std::string(i ? ", " : "") + "{\"check\": " + json::quote(toString(r.checks[i].kind)) +
             ", \"status\": " + json::quote(toString(r.checks[i].status)) +
             ", \"text\": " + json::quote(r.checks[i].text) + "}";
    s += "],\n  \"figures\": " + figuresJson(r.figures) + ",\n  \"findings\": [";
    for (std::size_t i = 0; i < r.findings.size(); ++i)
        s += std::string(i ? ",\n    " : "\n    ") +
             findingJson(r.findings[i], static_cast<int>(i) + 1);
    s += "], \"findings_left_out\": " + std::to_string(r.findingsLeftOut) +
         ", \"report\": " + (picture.empty() ? std::string("null") : json::quote(picture)) +
         ", \"seconds\": " + json::number(r.seconds) + "}";
    return s;
}

void printText(const std::string& path, const CheckReport& r, CheckStatus verdict,
               const Verbosity& v) {
    char head[160];
    std::snprintf(head, sizeof head, " (%s, %zu finding%s, %.2f s)", r.description.c_str(),
                  r.findings.size() + r.findingsLeftOut,
                  r.findings.size() + r.findingsLeftOut == 1 ? "" : "s", r.seconds);
    if (v.quiet) { // nothing but warnings and errors (Notes.h): a verdict other than pass
        if (verdict != CheckStatus::Pass)
            std::cerr << "lutkit: " << (verdict == CheckStatus::Fail ? "error: " : "warning: ")
                      << printable(path) << ": " << toString(verdict) << head << "\n";
        return;
    }
    std::cout << path << ": " << toString(verdict) << head << "\n";
    for (const CheckSummary& c : r.checks) {
        const std::string name = toString(c.kind);
        std::cout << "  " << name << std::string(15 - name.size(), ' ')
                  << (c.kind == CheckKind::Neutral ? "info" : toString(c.status)) << "  " << c.text
                  << "\n";
    }
    for (std::size_t i = 0; i < r.findings.size(); ++i)
        std::cout << "  " << (i + 1) << " " << toString(r.findings[i].severity) << " "
                  << r.findings[i].text(r.image) << "\n";
    if (r.findingsLeftOut)
        std::cout << "  ... and " << r.findingsLeftOut << " more (-v lists every one)\n";
}

// Where each LUT's picture goes: the path itself for one LUT, DIR/<name>.check.png for several,
// <name> its file name without the extension, with it where two LUTs share a base name (x.cube,
// x.3dl), and numbered where two share a file name (a/x.cube, b/x.cube: x.cube-2): never one
// picture for two LUTs (the second failed "already exists").
std::vector<std::string> picturePaths(const CheckCommandOptions& o) {
    std::vector<std::string> paths(o.inputs.size());
    if (o.report.empty())
        return paths;
    if (o.inputs.size() == 1) {
        paths[0] = o.report;
        return paths;
    }
    namespace fs = std::filesystem;
    std::map<std::string, int> stems, names;
    for (const auto& in : o.inputs) {
        ++stems[os::fromPath(os::toPath(in).stem())];
        ++names[os::fromPath(os::toPath(in).filename())];
    }
    std::map<std::string, int> used;
    for (std::size_t i = 0; i < o.inputs.size(); ++i) {
        const fs::path in = os::toPath(o.inputs[i]);
        std::string name = stems[os::fromPath(in.stem())] > 1 ? os::fromPath(in.filename())
                                                              : os::fromPath(in.stem());
        if (const int n = ++used[name]; n > 1 || names[os::fromPath(in.filename())] > 1)
            name += "-" + std::to_string(n);
        paths[i] = os::fromPath(os::toPath(o.report) / os::toPath(name + ".check.png"));
    }
    return paths;
}

} // namespace

int runCheck(const CheckCommandOptions& o) {
    formats::registerBuiltinFormats();
    CheckOptions options;
    if (!o.thresholds.empty())
        options.thresholds = parseCheckThresholds(
            readFile(o.thresholds, kMaxThresholdsBytes, "a thresholds file"), o.thresholds);
    if (o.verbosity.verbose)
        options.maxFindings = static_cast<std::size_t>(-1);
    if (!o.report.empty() && o.inputs.size() > 1) {
        const bool folder = os::isPathSeparator(o.report.back()) || os::isDirectory(o.report);
        if (!folder)
            throw UsageError("--report " + o.report +
                             ": with several LUTs, name a folder (ending "
                             "in /) for their pictures");
        std::filesystem::create_directories(os::toPath(o.report));
    }
    std::vector<std::string> inputs = o.inputs;
    if (!o.image.empty())
        inputs.push_back(o.image);
    if (!o.thresholds.empty())
        inputs.push_back(o.thresholds);
    std::optional<formats::LoadedImage> image;
    ImageView view;
    if (!o.image.empty()) {
        // A picture whose float frame would pass 256 MiB (16 megapixels) is weighed as it is
        // read, again for each LUT, and never held whole (the weights are counts of pixels: the
        // same figures either way). Standard input is read once, whole.
        constexpr std::uint64_t kWholeFrameBytes = std::uint64_t(256) << 20;
        const bool stream = !isStdinName(o.image) && [&] {
            const formats::ImageInfo info = formats::readImageInfo(o.image);
            return static_cast<std::uint64_t>(info.width) *
                       static_cast<std::uint64_t>(info.height) * 16u >
                   kWholeFrameBytes;
        }();
        if (stream) {
            // Bands of about 4 megapixels (64 MiB) are weighed at a time: the weighing's
            // per-thread tables cost as much as a few rows of pixels.
            options.imageRows = [path =
                                     o.image](const std::function<void(const ImageView&)>& feed) {
                Image band;
                int filled = 0;
                (void)formats::readImageRows(path, [&](const ImageView& rows, int) {
                    if (band.width() != rows.width)
                        band = Image(rows.width, std::max(1, (4 << 20) / rows.width));
                    for (int y = 0; y < rows.height; ++y) {
                        std::copy_n(rows.row(y), 4 * static_cast<std::size_t>(rows.width),
                                    band.pixel(0, filled));
                        if (++filled == band.height()) {
                            feed(band.view());
                            filled = 0;
                        }
                    }
                });
                if (filled > 0) {
                    ImageView rest = band.view();
                    rest.height = filled;
                    feed(rest);
                }
            };
        } else {
            image = formats::readImage(o.image);
            view = image->image.view();
            options.image = &view;
        }
    }
    bool failed = false;
    std::vector<std::string> jsonReports;
    const std::vector<std::string> pictures = picturePaths(o);
    for (std::size_t i = 0; i < o.inputs.size(); ++i) {
        const std::string& path = o.inputs[i];
        try {
            FormatOptions read;
            read.layout = o.inLayout;
            LutFile file = formats::readLut(path, read, o.inFormat);
            printDiagnostics(std::cerr, file.diagnostics, o.verbosity, "lutkit: ");
            // A game LUT (--target smash, else what the file says: a .nutexb, its
            // LUTKIT_PURPOSE tag) is judged by the look the game shows with it.
            const bool game =
                decidePurpose(file, purposeOption(o.target)).purpose == LutPurpose::Smash;
            std::string description;
            if (game) {
                description = "Smash Ultimate game LUT " + std::to_string(file.toLut3D().size()) +
                              "^3, checked as the edit the game shows";
                LutFile shown;
                shown.cube = smashShownEdit(file.toLut3D());
                file = std::move(shown);
            }
            CheckReport report = checkLut(file, options);
            if (game)
                report.description = description + " (" + report.description + ")";
            CheckStatus verdict = report.status();
            const bool fails =
                verdict == CheckStatus::Fail || (o.strict && verdict == CheckStatus::Warn);
            failed = failed || fails;
            const std::string& picture = pictures[i];
            bool wrote = false;
            if (!picture.empty() && beginOutput(picture, o.overwrite, inputs, o.verbosity.quiet)) {
                const CheckPicture p =
                    drawCheckReport(file, report, os::fromPath(os::toPath(path).filename()));
                formats::ImageWriteOptions w;
                w.bitDepth = 8;
                w.alpha = false;
                formats::writeImage(picture, p.image, w);
                wrote = true;
            }
            if (o.json) {
                jsonReports.push_back(reportJson(path, report, verdict, wrote ? picture : ""));
                continue;
            }
            printText(path, report, verdict, o.verbosity);
            if (wrote && !o.verbosity.quiet)
                std::cout << "  wrote " << picture << ": the report picture ("
                          << "charts before and after, findings circled)\n";
        } catch (const UsageError&) {
            throw;
        } catch (const Error& e) {
            std::cerr << "lutkit: error: " << printable(e.what()) << "\n";
            failed = true;
        }
    }
    if (o.json) {
        std::cout << "{\"status\": " << json::quote(failed ? "fail" : "pass")
                  << ", \"files\": [\n  ";
        for (std::size_t i = 0; i < jsonReports.size(); ++i)
            std::cout << (i ? ",\n  " : "") << jsonReports[i];
        std::cout << "]}\n";
    }
    return failed ? kExitFailure : kExitOk;
}

CLI::App* setupCheck(CLI::App& app, std::function<void(const CheckCommandOptions&)> onParsed) {
    auto o = std::make_shared<CheckCommandOptions>();
    auto* sub = app.add_subcommand(
        "check", "Check LUTs for fold-overs, banding, hue twists, clipping and roughness: a "
                 "health report, with a picture");
    sub->add_option("LUT", o->inputs, "LUT files to check")->required()->type_name("FILE");
    sub->add_option("--image", o->image,
                    "check over this image's colours (e.g. a screenshot), weighted by how often "
                    "each occurs")
        ->type_name("FILE");
    sub->add_option("--report", o->report,
                    "draw the report: the stress charts before and after the LUT, findings "
                    "circled, the worst lines plotted (PNG; a folder for several LUTs)")
        ->type_name("PATH");
    sub->add_flag("--strict", o->strict, "a warning fails too (exit 1)");
    sub->add_option("--thresholds", o->thresholds,
                    "thresholds file: lines 'NAME = WARN FAIL' (" LUTKIT_DOC_DIR "/docs/check.md)")
        ->type_name("FILE");
    sub->add_flag("--json", o->json, "print the report as JSON");
    addPurpose(*sub, "--target", o->target,
               std::string("what the LUT is for: ") + toString(LutPurpose::Smash) +
                   " = Smash Ultimate's LUT, checked as the look the game shows with it "
                   "(default: what the file says, LUTKIT_PURPOSE, or a .nutexb); " +
                   toString(LutPurpose::Raw) + " = the table as it is");
    addInputFormat(*sub, o->inFormat);
    addLayout(*sub, "--in-layout", o->inLayout, "LUT images: the layout (default: detected)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "list every finding (default: the worst 40)");
    addMovedOption(*sub, "--format",
                   "check reads LUTs: name their format with --in-format (--format is the "
                   "output format of the commands that write)");
    std::string thresholds = "Thresholds (warn, fail):";
    const CheckThresholds defaults;
    for (const ThresholdKey& k : thresholdKeys()) {
        const Threshold& t = defaults.*(k.member);
        char buf[160];
        std::snprintf(buf, sizeof buf, "\n  %-13s %g, %g %s: %s", k.name, t.warn, t.fail, k.unit,
                      k.meaning);
        thresholds += buf;
    }
    sub->footer(thresholds +
                "\nEntries are taken as sRGB-encoded display values; hue is measured in Oklab. "
                "Exit code 0 when every check passes or warns, 1 when one fails (--strict: or "
                "warns) or a file cannot be read.\n\n"
                "Examples:\n"
                "  lutkit check grade.cube\n"
                "  lutkit check grade.cube --report grade-check.png\n"
                "  lutkit check color_grading_lut.nutexb --image screenshot.png --strict\n"
                "  lutkit check *.cube --json --report checks/");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
