// SPDX-License-Identifier: Apache-2.0
#include "LutFiles.h"

#include "PurposeText.h"

#include "lut/Error.h"
#include "lut/formats/DisplayRange.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/io/FormatRegistry.h"
#include "lut/ops/Lattice.h"

#include <iostream>

namespace lut::cli {

LutFile readCommandLut(const std::string& path, const std::optional<LutLayout>& layout,
                       const Verbosity& verbosity) {
    FormatOptions options;
    options.layout = layout;
    LutFile file = formats::readLut(path, options);
    printDiagnostics(std::cerr, file.diagnostics, verbosity, "lutkit: ");
    if (verbosity.verbose)
        if (const std::string d = layoutDetail(file, layout.has_value(), "--lut-layout");
            !d.empty())
            std::cerr << "lutkit: " << printable(path) << ": " << printable(d) << "\n";
    return file;
}

Lut3D readLutTable(const std::string& path, const Verbosity& verbosity, PurposeDecision* purpose,
                   std::optional<LutPurpose> given) {
    const LutFile file = formats::readLut(path, {});
    printDiagnostics(std::cerr, file.diagnostics, verbosity, "lutkit: ");
    if (purpose) {
        *purpose = decidePurpose(file, given);
        warnPurposeFromContent(path, *purpose, "--in-target", verbosity);
    }
    if (!file.shaper)
        return file.toLut3D();
    // One lattice, never silently: what it costs between its points. Over 0..1 where the shaper's
    // domain holds it (the one rule, lut/formats/DisplayRange.h), else over that domain.
    const bool display = formats::samplesDisplayRange(file.inputDomainMin(), file.inputDomainMax());
    LatticeRequest q;
    if (display) {
        q.domainMin = glm::vec3(0.0f);
        q.domainMax = glm::vec3(1.0f);
    }
    LatticeResult r = sampleOnLattice(file, q);
    r.error.seconds = 0.0;
    Diagnostic d;
    d.severity =
        r.error.maxSteps8() > 1.0 ? Diagnostic::Severity::Warning : Diagnostic::Severity::Info;
    d.path = path;
    d.message = "its 1D shaper and table taken as one " + std::to_string(r.lut.size()) +
                "^3 table " +
                (display ? std::string(formats::kDisplayRangeWords) +
                               (file.inputDomainMin() != glm::vec3(0.0f) ||
                                        file.inputDomainMax() != glm::vec3(1.0f)
                                    ? " (inputs outside it take the edge value)"
                                    : std::string())
                         : std::string("over the shaper's range")) +
                " (this command works on one lattice): " + r.error.str() + " on " +
                std::to_string(r.heldOut) + " inputs between lattice points";
    printDiagnostics(std::cerr, {d}, verbosity, "lutkit: ");
    return std::move(r.lut);
}

std::optional<LutPurpose> knownPurpose(const PurposeDecision& d) {
    if (d.source == PurposeSource::Assumed)
        return std::nullopt;
    return d.purpose;
}

WrittenLut writeLutFile(const std::string& path, const LutFile& file, const std::string& format,
                        const std::vector<std::string>& inputs) {
    for (const auto& in : inputs)
        checkNotSameFile(in, path);
    formats::registerBuiltinFormats();
    const auto& registry = FormatRegistry::instance();
    const Format* writer = format.empty() ? registry.writerForPath(path) : registry.byName(format);
    if (!writer || !writer->canWrite())
        throw Error(path + ": no format writes '" + extensionOf(path) +
                    "' files (name the output format: --format)");
    WrittenLut w;
    w.format = writer->name();
    w.diagnostics = formats::writeLut(path, file, {}, format);
    return w;
}

void writeLutTable(std::ostream& os, const std::string& path, const Lut3D& lut,
                   const std::string& format, const std::vector<std::string>& inputs,
                   const Verbosity& verbosity, std::optional<LutPurpose> purpose) {
    LutFile file;
    file.cube = lut;
    file.purpose = purpose;
    const WrittenLut w = writeLutFile(path, file, format, inputs);
    os << "wrote    " << path << ": " << w.format << ", " << lut.size() << "^3\n";
    printDiagnostics(os, w.diagnostics, verbosity);
}

std::string costText(const ErrorStats& error, std::size_t sanitizedEntries) {
    std::string s = error.str();
    if (sanitizedEntries)
        s += " (" + std::to_string(sanitizedEntries) +
             " NaN/Inf entries of the input counted as 0 or +-65504)";
    if (error.bounded)
        s += "\n         max: " + error.coverage();
    return s;
}

} // namespace lut::cli
