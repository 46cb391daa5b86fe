// lutkit convert --target smash: the game's LUT for an edit of its picture (Smush-LUT's whole
// job: a graded neutral strip in, a compensated color_grading_lut.nutexb out), through
// lut::authorSmashLutForEdit (GameLut.h).
#include "commands/Convert.h"

#include "GameLut.h"
#include "Json.h"
#include "StrengthOptions.h"
#include "Usage.h"
#include "WrittenCheck.h"

#include "lut/formats/Nutexb.h"
#include "lut/formats/OcioFiles.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"

#include <iostream>
#include <optional>
#include <sstream>

namespace lut::cli {

int runConvertGame(const ConvertOptions& o, const std::string& reason) {
    checkNotSameFile(o.input, o.output);
    if (o.size != 0 && o.size != 16)
        throw UsageError("the game's LUT is 16^3: --size does not apply to --target smash");
    FormatOptions ro;
    ro.layout = o.inLayout;
    if (!o.cccid.empty())
        ro.setAttribute(formats::kOcioCccIdAttribute, o.cccid);
    const LutFile in = formats::readLut(o.input, ro, o.inFormat);
    std::ostringstream text;
    text << "read     " << o.input << ": " << in.format
         << (in.dialect.empty() ? "" : " (" + in.dialect + ")") << ", "
         << (in.shaper ? "1D shaper " + std::to_string(in.shaper->size()) + (in.cube ? ", " : "")
                       : std::string())
         << (in.cube ? std::to_string(in.cube->size()) + "^3" : std::string()) << "\n";
    printDiagnostics(text, in.diagnostics, o.verbosity);
    std::optional<Lut3D> blended;
    if (!isFullStrength(o.strength)) {
        // The edit at the strength asked for, then made for the game: the game shows the blend.
        blended = applyStrength(in.toLut3D(), o.strength);
        text << "strength " << strengthText(o.strength) << ", of the edit\n";
    }
    text << "target   smash (" << reason << ")\n";
    GameLutRequest q;
    q.stageLut = o.originalLut;
    q.screenshot = o.screenshot;
    q.refine = o.refine;
    q.interp = o.interp;
    SmashAuthoringResult authored;
    const Lut3D game = blended ? makeGameLut(*blended, q, o.verbosity, text, &authored)
                               : makeGameLut(in, q, o.verbosity, text, &authored);
    LutFile out;
    out.cube = game;
    FormatOptions wo;
    wo.layout = o.layout;
    wo.bitDepth = o.bitDepth;
    wo.dither = o.dither;
    if (!o.name.empty())
        wo.setAttribute(formats::nutexb::kNameAttribute, o.name);
    const Diagnostics wd = formats::writeLut(o.output, out, wo, o.format);
    text << "wrote    " << o.output << ": 16^3 game LUT\n";
    printDiagnostics(text, wd, o.verbosity);
    if (o.json) {
        std::cout << "{\"input\": " << json::quote(o.input)
                  << ", \"output\": " << json::quote(o.output)
                  << ", \"target\": \"smash\", \"measured_over\": "
                  << json::quote(authored.measuredOver)
                  << ",\n \"exact\": {\"max\": " << json::number(authored.exactError.maxSteps)
                  << ", \"mean\": " << json::number(authored.exactError.meanSteps)
                  << ", \"p99\": " << json::number(authored.exactError.p99Steps)
                  << "},\n \"refined\": ";
        if (authored.refinementComputed)
            std::cout << "{\"max\": " << json::number(authored.refinedError.maxSteps)
                      << ", \"mean\": " << json::number(authored.refinedError.meanSteps)
                      << ", \"p99\": " << json::number(authored.refinedError.p99Steps)
                      << ", \"held_out_mean\": " << json::number(authored.heldOutRefined.meanSteps)
                      << ", \"exact_held_out_mean\": "
                      << json::number(authored.heldOutExact.meanSteps)
                      << ", \"fitted_on\": " << json::quote(authored.fittedOn)
                      << ", \"decision\": " << json::quote(authored.decision) << "}";
        else
            std::cout << "null";
        std::cout << ",\n \"written\": " << json::quote(authored.refined ? "refined" : "exact")
                  << ", \"clamped\": " << authored.clampedEntries
                  << ",\n \"diagnostics\": " << json::diagnostics(wd) << "}\n";
    } else {
        std::cout << text.str();
    }
    checkWrittenLut(o.output, out, o.verbosity, true);
    return kExitOk;
}

} // namespace lut::cli
