// SPDX-License-Identifier: Apache-2.0
// lutkit convert DIR/ -o OUTDIR/: a folder of LUTs (a modder's edited strips) converted file by
// file through the batch runner apply uses (Batch.h: files in parallel, a progress bar, past a
// bad file, every failure listed), each under its own name as --format (default nutexb: the
// game's LUT, with what the game will show against the edit).
#include "commands/Convert.h"

#include "Batch.h"
#include "LutFiles.h"
#include "PurposeText.h"
#include "StrengthOptions.h"
#include "Usage.h"

#include "lut/formats/Convert.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Nutexb.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/FormatRegistry.h"
#include "lut/os/Files.h"

#include <iostream>
#include <mutex>
#include <sstream>

namespace lut::cli {

namespace {

bool isDirectory(const std::string& p) {
    return os::isDirectory(p);
}

FormatOptions writeOptions(const ConvertOptions& o) {
    FormatOptions wo;
    wo.layout = o.layout;
    wo.size = o.size;
    wo.bitDepth = o.bitDepth;
    wo.dither = o.dither;
    if (!o.name.empty())
        wo.setAttribute(formats::nutexb::kNameAttribute, o.name);
    return wo;
}

// One LUT converted by the library's convertLut (lut/formats/Convert.h): made for what OUT is
// for (the game's LUT from an edit, the edit a game LUT makes, or as it is), at the strength
// asked for; the line that says what it cost.
std::string convertOne(const std::string& format, const BatchJob& j,
                       const formats::ConvertOptions& base, Diagnostics& notes) {
    formats::ConvertOptions co = base;
    co.outFormat = format;
    const formats::ConvertReport r = formats::convertLut(j.input, j.output, co);
    notes = r.input.diagnostics;
    notes.insert(notes.end(), r.writeDiagnostics.begin(), r.writeDiagnostics.end());
    std::string line = j.input + " -> " + j.output + ": ";
    if (const std::string s = strengthText(base.strength); !s.empty())
        line += "strength " + s + "; ";
    const auto& c = r.purpose.conversion;
    if (c && c->to == LutPurpose::Smash) {
        const SmashAuthoringResult& a = c->authoring;
        return line + "in game " + (a.refined ? a.refinedError : a.exactError).str() +
               " against the edit" + (a.refined ? " (refined)" : "") + "\n";
    }
    if (c)
        line += "the edit this game LUT makes " + c->sampling.str() + "; ";
    if (r.resample)
        line += "resampled " + std::to_string(r.resample->from) + "^3 -> " +
                std::to_string(r.resample->to) + "^3 " + r.resample->error.str() + "; ";
    line += r.storage ? "storage " + r.storage->str()
                      : "storage not measured (" + r.readBackError + ")";
    return line + "\n";
}

} // namespace

bool isConvertBatch(const ConvertOptions& o) {
    if (o.input == "-" || o.output == "-")
        return false;
    // OUT ending in / is a folder; an existing folder is one for a folder IN only. A folder IN
    // with a file OUT is refused as any folder given for a LUT file is ("is a directory, not a
    // regular file"), a file IN with an existing folder OUT as any folder in a file's place
    // ("is a folder, not a file": robust_tests NothingLost).
    return (!o.output.empty() && o.output.back() == '/') ||
           (isDirectory(o.input) && isDirectory(o.output));
}

int runConvertBatch(const ConvertOptions& o) {
    if (o.json)
        throw UsageError("--json reports one file: convert a folder without it");
    if (o.color.any())
        throw UsageError("--from/--to bake one file at a time: convert a folder without them");
    if (o.level)
        throw UsageError("--level writes one Hald image: convert a folder with --size");
    if (o.layout)
        if (const std::string problem = layoutSizeProblem(*o.layout, o.size); !problem.empty())
            throw UsageError(problem);
    // Where each LUT goes (lut/formats/LutDestination.h): --format, by default the game's.
    const std::string format = o.format.empty() ? formats::kGameLutFormat : o.format;
    const std::optional<LutPurpose> asked = purposeOption(o.target);
    const formats::LutDestination dest =
        formats::resolveLutDestination({o.output, format, asked, o.size, o.layout, 0});
    const Format* writer = dest.writer;
    if (!writer)
        throw UsageError("--format " + format + ": no such writer");
    const auto& registry = FormatRegistry::instance();
    const std::string ext =
        writer->extensions().empty() ? std::string(".png") : writer->extensions().front();
    if ((!o.originalLut.empty() || !o.screenshot.empty() || o.refine) && !dest.forGame())
        throw UsageError("--original-lut, --screenshot and --refine are for --target smash");
    // What every file is converted with: what each is for (its tag, a .nutexb, --in-target),
    // what OUT is for (--target, else the game's for a .nutexb), the stage and screenshot.
    formats::ConvertOptions base;
    base.inFormat = o.inFormat;
    base.read.layout = o.inLayout;
    base.write = writeOptions(o);
    base.interp = o.interp;
    base.strength = o.strength;
    base.inPurpose = purposeOption(o.inTarget);
    base.outPurpose = asked;
    PurposeInputs held;
    preparePurposeInputs(o, held, base);

    OutputOptions out = o.overwrite;
    out.output = o.output;
    FolderFiles luts;
    luts.what = "LUT files (.cube .png strips .nutexb .3dl ...)";
    luts.accepts = [&registry](const std::string& path) {
        for (const Format* f : registry.forExtension(path))
            if (f->canRead())
                return true;
        return false;
    };
    const BatchPlan plan = planBatch({o.input}, out, {o.originalLut, o.screenshot}, {}, ext, luts);
    // plan.notes (missing frames, skipped folder entries) are printed once, by runBatch.
    BatchOptions bo;
    bo.quiet = o.verbosity.quiet;
    bo.unit = "LUTs";
    return runBatch(plan, bo, [&](const BatchJob& j, JobContext& ctx) {
        Diagnostics notes;
        const std::string line = convertOne(writer->name(), j, base, notes);
        std::string lines; // above the progress bar
        for (const auto& d : notes)
            if (isShown(d, o.verbosity))
                lines += "lutkit: " + printable(d.str()) + "\n";
        ctx.warn(lines);
        return line;
    });
}

} // namespace lut::cli
