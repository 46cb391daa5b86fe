// SPDX-License-Identifier: Apache-2.0
#include "PurposeText.h"

#include "Json.h"
#include "LutFiles.h"
#include "Vocabulary.h"

#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/smash/SmashConstants.h"
#include "lut/smash/StageLut.h"

#include <iostream>
#include <sstream>

namespace lut::cli {

CLI::Option* addPurpose(CLI::App& sub, const std::string& name, std::string& target,
                        const std::string& help) {
    return sub.add_option(name, target, help)
        ->type_name("NAME")
        ->check(choicesValidator(targetChoices()));
}

std::optional<LutPurpose> purposeOption(const std::string& value) {
    if (value.empty())
        return std::nullopt;
    return parseLutPurpose(value);
}

void printConversion(std::ostream& os, const PurposeConversion& c, const ConversionWords& w) {
    if (!c.converted())
        return;
    if (c.to == LutPurpose::Raw) {
        os << "edit     the edit this game LUT makes of the neutral game's picture, "
           << c.lut.size() << "^3 (" << toString(Interpolation::Tetrahedral)
           << " between its points) against that edit: " << c.sampling.str() << " over "
           << c.measuredOver << "\n";
        return;
    }
    const SmashAuthoringResult& r = c.authoring;
    os << "game     the LUT that makes Smash Ultimate show this edit of its own picture (stage "
          "LUT: "
       << w.stage << "; the edit evaluated " << toString(w.interp)
       << ", entries rounded to nearest)\n";
    if (r.exactError.count > 0) {
        os << "in game  what the game shows with the 8-bit LUT vs the edited colours, over "
           << r.measuredOver << ":\n";
        os << "         exact composition:        " << r.exactError.str()
           << (r.refined ? "" : "  (written)") << "\n";
        if (r.refinementComputed) {
            os << "         least-squares refinement: " << r.refinedError.str()
               << (r.refined ? "  (written)" : "") << "\n";
            os << "refine   fitted on " << r.fittedOn << "; written: " << r.decision << "\n";
        } else {
            os << "         least-squares refinement: not computed (--refine fits it on part of "
                  "the colours and writes it if it beats the exact composition on the rest)\n";
        }
    }
    if (r.clampedEntries > 0)
        os << "clamped  " << r.clampedEntries << " values the game cannot reach (up to "
           << r.clampedMax * 255.0 << " 8-bit steps outside [0,1])\n";
}

std::string conversionJson(const std::optional<PurposeConversion>& c) {
    if (!c || !c->converted())
        return "null";
    auto err = [](const GameError& e) {
        return "{\"max\": " + json::number(e.maxSteps) +
               ", \"mean\": " + json::number(e.meanSteps) +
               ", \"p99\": " + json::number(e.p99Steps) + "}";
    };
    std::ostringstream js;
    js << "{\"from\": " << json::quote(toString(c->from))
       << ", \"to\": " << json::quote(toString(c->to))
       << ", \"measured_over\": " << json::quote(c->measuredOver);
    if (c->to == LutPurpose::Raw) {
        js << ", \"size\": " << c->lut.size() << ", \"sampling\": " << err(c->sampling) << "}";
        return js.str();
    }
    const SmashAuthoringResult& r = c->authoring;
    js << ", \"exact\": " << err(r.exactError) << ", \"refined\": ";
    if (r.refinementComputed) {
        const std::string e = err(r.refinedError);
        js << e.substr(0, e.size() - 1)
           << ", \"held_out_mean\": " << json::number(r.heldOutRefined.meanSteps)
           << ", \"exact_held_out_mean\": " << json::number(r.heldOutExact.meanSteps)
           << ", \"fitted_on\": " << json::quote(r.fittedOn)
           << ", \"decision\": " << json::quote(r.decision) << "}";
    } else {
        js << "null";
    }
    js << ", \"written\": " << json::quote(r.refined ? "refined" : "exact")
       << ", \"clamped\": " << r.clampedEntries << "}";
    return js.str();
}

void warnPurposeFromContent(const std::string& path, const PurposeDecision& d,
                            const std::string& flag, const Verbosity& verbosity) {
    (void)verbosity; // a warning: -q keeps it (Notes.h)
    if (d.source != PurposeSource::Content)
        return;
    std::cerr << "lutkit: warning: " << path
              << ": taken as the game's LUT although it does not say so: " << d.evidence << "; "
              << flag << " raw if it is an edit\n";
}

PurposedLut lutFor(const LutFile& file, const std::string& path, LutPurpose wanted,
                   std::optional<LutPurpose> given, const std::string& flag,
                   const PurposeOptions& options, const Verbosity& verbosity) {
    PurposedLut out;
    out.decision = decidePurpose(file, given);
    warnPurposeFromContent(path, out.decision, flag, verbosity);
    if (out.decision.purpose == wanted) {
        out.lut = file.toLut3D();
    } else { // a shaper evaluated exactly (lut/smash/PurposeConversion.h)
        out.conversion = convertPurpose(file, out.decision.purpose, wanted, options);
        out.lut = out.conversion->lut;
    }
    const int tableSize = file.cube ? file.cube->size() : 0;
    // Said when it changes the table, or when the file does not say and could be either: the
    // game's LUTs are all 16^3, so an unsaid 16^3 table may be one (a 33^3 grade is no game's).
    const bool ambiguous =
        out.decision.source == PurposeSource::Assumed && tableSize == kSmashLutSize;
    if ((ambiguous || out.conversion) && !verbosity.quiet &&
        out.decision.source != PurposeSource::Content) {
        std::cerr << "lutkit: note: " << printable(path) << " is " << out.decision.text(flag);
        if (out.conversion)
            std::cerr << ": used as " << describe(wanted);
        std::cerr << "\n";
        if (out.conversion) {
            std::ostringstream os;
            ConversionWords w;
            w.interp = options.editInterpolation;
            printConversion(os, *out.conversion, w);
            std::istringstream lines(os.str());
            for (std::string line; std::getline(lines, line);)
                std::cerr << "lutkit: note: " << printable(path) << ": " << line << "\n";
        }
    }
    return out;
}

ResultPurpose resultPurpose(const PurposeDecision& a, const PurposeDecision& b,
                            const formats::LutDestination& out) {
    ResultPurpose r;
    if (out.purpose) {
        r.to = *out.purpose;
        r.known = true;
        r.why = out.purposeFrom == formats::DestinationPurpose::Said
                    ? "--target"
                    : "the output is a .nutexb, the game's LUT";
    } else {
        r.to = a.purpose;
        r.known = a.source != PurposeSource::Assumed || b.purpose != a.purpose;
        r.why = "as A; --target chooses";
    }
    return r;
}

PurposedPair readPurposedPair(const std::string& a, const std::string& b,
                              const std::string& inTarget, const std::string& target,
                              const std::string& output, const std::string& format,
                              const Verbosity& verbosity) {
    const std::optional<LutPurpose> given = purposeOption(inTarget);
    PurposedPair p;
    p.aPath = a;
    p.bPath = b;
    p.a = readLutTable(a, verbosity, &p.pa, given);
    p.b = readLutTable(b, verbosity, &p.pb, given);
    p.out = resultPurpose(p.pa, p.pb,
                          formats::resolveLutDestination(
                              {output, format, purposeOption(target), 0, std::nullopt, 0}));
    return p;
}

std::optional<LutPurpose> printPurposeOp(std::ostream& os, const PurposedPair& p,
                                         const PurposeOpResult& result, Interpolation interp) {
    const bool plain = p.pa.purpose == LutPurpose::Raw && p.pb.purpose == LutPurpose::Raw &&
                       p.out.to == LutPurpose::Raw && p.pa.source == PurposeSource::Assumed &&
                       p.pb.source == PurposeSource::Assumed;
    if (!plain)
        os << "purpose  A:   " << p.pa.text("--in-target") << "\n"
           << "         B:   " << p.pb.text("--in-target") << "\n"
           << "         OUT: " << toString(p.out.to) << " (" << p.out.why << ")\n";
    for (const auto& [what, conversion] : result.conversions) {
        os << "convert  " << what << ": " << toString(conversion.from) << " -> "
           << toString(conversion.to) << "\n";
        // B made into the game's LUT on A's picture: A is the stage
        const bool staged = conversion.onStage;
        printConversion(os, conversion,
                        ConversionWords{staged ? p.aPath : std::string("neutral"), interp});
    }
    if (p.out.known || !result.conversions.empty())
        return p.out.to;
    return std::nullopt;
}

Lut3D readStageLut(const std::string& path, const Verbosity& verbosity) {
    const LutFile file = formats::readLut(path);
    printDiagnostics(std::cerr, file.diagnostics, verbosity, "lutkit: ");
    const PurposeDecision d = decidePurpose(file, std::nullopt, LutPurpose::Smash);
    if (d.purpose == LutPurpose::Smash) {
        // A file with a shaper: sampled at the game's 16^3 lattice, the error said.
        StageLutFile stage = stageLutFromFile(file, path);
        printDiagnostics(std::cerr, stage.diagnostics, verbosity, "lutkit: ");
        return std::move(stage.lut);
    }
    const PurposeConversion c = convertPurpose(file, LutPurpose::Raw, LutPurpose::Smash);
    if (!verbosity.quiet)
        std::cerr << "lutkit: note: " << printable(path) << " (--original-lut) is " << d.text("")
                  << ": the stage runs the game's LUT that shows it\n";
    return c.lut;
}

} // namespace lut::cli
