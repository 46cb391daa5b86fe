// lutkit convert DIR/ -o OUTDIR/: a folder of LUTs (a modder's edited strips) converted file by
// file through the batch runner apply uses (Batch.h: files in parallel, a progress bar, past a
// bad file, every failure listed), each under its own name as --format (default nutexb: the
// game's LUT, with what the game will show against the edit).
#include "commands/Convert.h"

#include "Batch.h"
#include "GameLut.h"
#include "StrengthOptions.h"
#include "Usage.h"

#include "lut/formats/Convert.h"
#include "lut/formats/Nutexb.h"
#include "lut/formats/Registry.h"
#include "lut/io/BuiltinLut.h"
#include "lut/io/FileNames.h"
#include "lut/io/FormatRegistry.h"
#include "lut/roundtrip/RoundtripTarget.h"

#include <filesystem>
#include <iostream>
#include <mutex>
#include <sstream>

namespace lut::cli {

namespace {

bool isDirectory(const std::string& p) {
    std::error_code ec;
    return std::filesystem::is_directory(p, ec);
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

// One LUT made for the game: read, strength, authored, written; the line that says it.
std::string convertForGame(const ConvertOptions& o, const BatchJob& j, Diagnostics& notes) {
    FormatOptions ro;
    ro.layout = o.inLayout;
    const LutFile in = formats::readLut(j.input, ro, o.inFormat);
    notes = in.diagnostics;
    const Lut3D edit = applyStrength(in.toLut3D(), o.strength);
    GameLutRequest q;
    q.stageLut = o.originalLut;
    q.screenshot = o.screenshot;
    q.refine = o.refine;
    q.interp = o.interp;
    SmashAuthoringResult authored;
    std::ostringstream unused; // the one-file report; a batch says one line per file
    LutFile out;
    out.cube = makeGameLut(edit, q, o.verbosity, unused, &authored);
    FormatOptions wo = writeOptions(o);
    wo.size = 0;
    const Diagnostics wd = formats::writeLut(j.output, out, wo, "nutexb");
    notes.insert(notes.end(), wd.begin(), wd.end());
    return j.input + " -> " + j.output + ": in game " +
           (o.refine ? authored.refinedError : authored.exactError).str() + " against the edit" +
           (o.refine ? " (refined)" : "") + "\n";
}

// One LUT written as it is, in another format: the resampling and storage errors.
std::string convertAsItIs(const ConvertOptions& o, const std::string& format, const BatchJob& j,
                          Diagnostics& notes) {
    formats::ConvertOptions co;
    co.inFormat = o.inFormat;
    co.outFormat = format;
    co.read.layout = o.inLayout;
    co.write = writeOptions(o);
    co.interp = o.interp;
    co.strength = o.strength;
    const formats::ConvertReport r = formats::convertLut(j.input, j.output, co);
    notes = r.input.diagnostics;
    notes.insert(notes.end(), r.writeDiagnostics.begin(), r.writeDiagnostics.end());
    std::string line = j.input + " -> " + j.output + ": ";
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
    formats::registerBuiltinFormats();
    const auto& registry = FormatRegistry::instance();
    const std::string format = o.format.empty() ? "nutexb" : o.format;
    const Format* writer = registry.byName(format);
    if (!writer || !writer->canWrite())
        throw UsageError("--format " + format + ": no such writer");
    const std::string ext =
        writer->extensions().empty() ? std::string(".png") : writer->extensions().front();
    const bool gameOut = writer->name() == "nutexb";
    std::optional<ExtractTarget> asked;
    if (!o.target.empty())
        asked = parseTarget(o.target);
    if (asked == ExtractTarget::Smash && !gameOut)
        throw UsageError("--target smash makes the game's LUT: a .nutexb (--format nutexb)");
    if ((!o.originalLut.empty() || !o.screenshot.empty() || o.refine) &&
        (!gameOut || asked == ExtractTarget::Raw))
        throw UsageError("--original-lut, --screenshot and --refine are for --target smash");

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
    for (const auto& n : plan.notes)
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: note: " << n << "\n";
    BatchOptions bo;
    bo.quiet = o.verbosity.quiet;
    bo.unit = "LUTs";
    std::mutex noteMutex;
    return runBatch(plan, bo, [&](const BatchJob& j, JobContext&) {
        // What each file is for: the game's LUT from an edit, or the LUT as it is (a .nutexb
        // read is the game's LUT already, as for one file).
        const bool gameIn = extensionOf(j.input) == ".nutexb" || o.inFormat == "nutexb" ||
                            isBuiltinGameLut(j.input);
        const bool smash = asked ? *asked == ExtractTarget::Smash : gameOut && !gameIn;
        Diagnostics notes;
        const std::string line =
            smash ? convertForGame(o, j, notes) : convertAsItIs(o, writer->name(), j, notes);
        std::lock_guard<std::mutex> lock(noteMutex);
        printDiagnostics(std::cerr, notes, o.verbosity, "lutkit: ");
        return line;
    });
}

} // namespace lut::cli
