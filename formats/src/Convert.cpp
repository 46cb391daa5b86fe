// SPDX-License-Identifier: Apache-2.0
// convertLut: read, resample when the output stores another size, write, read back, measure.
#include "lut/formats/Convert.h"

#include "LutPrep.h"
#include "StorageError.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/Hald.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/io/LutWriter.h"
#include "lut/ops/CompareLuts.h"
#include "lut/ops/Lattice.h"
#include "lut/ops/Resample.h"
#include "lut/ops/Strength.h"
#include "lut/smash/SmashConstants.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace lut::formats {

namespace {

// The lattice a shaper-only file gets in a format without a shaper when none is asked for.
constexpr int kDefaultUnitSize = 33;

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

const Format* formatNamed(const std::string& name) {
    const Format* f = FormatRegistry::instance().byName(name);
    if (!f) {
        std::string known;
        for (const Format* g : FormatRegistry::instance().all())
            known += (known.empty() ? "" : ", ") + g->name();
        throw Error("unknown format '" + name + "' (known: " + known + ")");
    }
    return f;
}

} // namespace

ConvertReport convertLut(const std::string& input, const std::string& output,
                         const ConvertOptions& options) {
    const auto tStart = Clock::now();
    const int wantSize = options.write.size;
    if (wantSize != 0 && (wantSize < limits::kMin3DSize || wantSize > limits::kMax3DSize))
        throw Error("output size " + std::to_string(wantSize) + " is outside " +
                    std::to_string(limits::kMin3DSize) + ".." + std::to_string(limits::kMax3DSize));
    if (output != "-")
        checkNotOverwritingInputs(output, {input});

    registerBuiltinFormats();
    if (!options.inFormat.empty())
        (void)formatNamed(options.inFormat);
    if (!options.outFormat.empty())
        (void)formatNamed(options.outFormat);
    // Where the output goes and what it is for (lut/formats/LutDestination.h).
    const LutDestination dest = resolveLutDestination(
        {output, options.outFormat, options.outPurpose, wantSize, options.write.layout, 0});
    const Format* writer = &dest.requireWriter();

    ConvertReport report;
    report.outputFormat = writer->name();

    // Readers that sample (OpenColorIO's chains) sample at the size the output stores, through
    // the whole processor, instead of being resampled afterwards.
    // (Not when the table is to change purpose: the edit is then evaluated at the game's
    // colours, from the file's own lattice.)
    const bool mayConvert = dest.purpose || options.inPurpose;
    FormatOptions readOptions = options.read;
    if (readOptions.size == 0 && !mayConvert)
        readOptions.size = wantSize ? wantSize : writer->fixedSizeFor(options.write);
    auto t0 = Clock::now();
    report.input = readLut(input, readOptions, options.inFormat);
    report.readSeconds = since(t0);
    if (!report.input.cube && !report.input.shaper)
        throw Error(input + ": holds no table");
    Diagnostics sizeNotes;

    // What the input is for and what the output is for.
    PurposeStep& step = report.purpose;
    step.input = decidePurpose(report.input, options.inPurpose);
    step.output = dest.purposeFor(step.input.purpose);
    step.outputFrom = dest.purposeFrom;

    // The strength blends the edit (lut/ops/Strength.h): a raw input before it is made into the
    // game's LUT (the game shows the blend), the edit a game LUT makes after it is made; a LUT
    // written for the purpose it has is blended as it is.
    // A shaper + table is blended over 0..1, where display pictures live (never over the
    // shaper's whole range, 0..64 for a log shaper: its 0..1 would get a few lattice planes):
    // behind the shaper, kept, when the output holds one and the shaper rises; else sampled at a
    // lattice over 0..1. What that costs is bounded there and said.
    auto blend = [&](LutFile& f) {
        if (f.shaper && f.cube) {
            const StrengthAmounts amounts = strengthAmounts(options.strength);
            LatticeRequest q;
            q.domainMin = glm::vec3(0.0f);
            q.domainMax = glm::vec3(1.0f);
            q.finish = [amounts](const glm::dvec3& x, const glm::dvec3& y) {
                return blendStrength(x, y, amounts);
            };
            FormatOptions wo = options.write;
            if (!options.outFormat.empty())
                FormatRegistry::instance().applyAlias(options.outFormat, wo);
            std::optional<ShaperLatticeResult> kept;
            if (writer->holdsShaperFor(wo))
                kept = finishKeepingShaper(f, q);
            ErrorStats error;
            std::string how;
            if (kept) {
                f = std::move(kept->file);
                error = kept->error;
                how = "blended with neutral behind the 1D shaper (kept)";
            } else {
                const int fixed = writer->fixedSizeFor(wo);
                q.size = wantSize ? wantSize
                         : fixed  ? fixed
                                  : std::max(f.cube->size(), kDefaultUnitSize);
                LatticeResult r = sampleOnLattice(f, q);
                f.cube = std::move(r.lut);
                f.shaper.reset();
                error = r.error;
                how = "the 1D shaper and table blended with neutral at a " +
                      std::to_string(q.size) + "^3 lattice over 0..1, where display pictures live";
            }
            error.seconds = 0.0;
            sizeNotes.push_back({error.maxSteps8() > 1.0 ? Diagnostic::Severity::Warning
                                                         : Diagnostic::Severity::Info,
                                 output, 0, 0,
                                 how + " (--strength): " + error.str() + " over 0..1"});
            report.strength = amounts;
            return;
        }
        if (f.shaper) { // 1D alone: as a table
            f.cube = f.toLut3D(0);
            sizeNotes.push_back({Diagnostic::Severity::Info, output, 0, 0,
                                 "the 1D curves were made into a " +
                                     std::to_string(f.cube->size()) +
                                     "^3 table to blend them with neutral (--strength)"});
            f.shaper.reset();
        }
        f.cube = applyStrength(*f.cube, options.strength);
        report.strength = strengthAmounts(options.strength);
    };
    const bool blendAfter =
        step.input.purpose == LutPurpose::Smash && step.output == LutPurpose::Raw;
    LutFile converted = report.input;
    if (!isFullStrength(options.strength) && !blendAfter)
        blend(converted);

    // The table for the output's purpose.
    if (step.output != step.input.purpose) {
        if (step.output == LutPurpose::Smash && wantSize != 0 && wantSize != kSmashLutSize)
            throw RequestError("the game's LUT is " + std::to_string(kSmashLutSize) +
                               "^3: another size does not apply to it");
        PurposeOptions po = options.purpose;
        const int fixed = writer->fixedSizeFor(options.write);
        if (step.output == LutPurpose::Raw)
            po.rawSize = wantSize            ? wantSize
                         : fixed             ? fixed
                         : report.input.cube ? std::max(report.input.cube->size(), 33)
                                             : 33;
        step.conversion = convertPurpose(converted, step.input.purpose, step.output, po);
        converted.shaper.reset();
        converted.cube = step.conversion->lut;
        if (!isFullStrength(options.strength) && blendAfter)
            blend(converted);
    }
    // The output says what it is for when that is known: the file or the user said it, or the
    // table was made for it (an assumption is not turned into a statement).
    const bool known = step.input.source != PurposeSource::Assumed || step.conversion ||
                       step.outputFrom == DestinationPurpose::Said ||
                       step.output == LutPurpose::Smash;
    converted.purpose = known ? std::optional<LutPurpose>(step.output) : std::nullopt;
    const LutFile& in = converted;

    // Resample when the output stores another lattice size.
    const int sourceSize = in.cube ? in.cube->size() : 0;
    int targetSize = wantSize ? wantSize : writer->fixedSizeFor(options.write);
    if (targetSize == 0)
        targetSize = sourceSize; // 0 stays 0 for a pure 1D file: the writer decides
    // A Hald image holds N = L^2 only: resample once, to the size it will hold.
    if (dest.hald && targetSize != 0 && haldSizeFor(targetSize) != targetSize) {
        const int held = haldSizeFor(targetSize);
        sizeNotes.push_back({Diagnostic::Severity::Info, output, 0, 0,
                             std::to_string(targetSize) +
                                 "^3 is not a square: a Hald image stores N = L^2, so " +
                                 haldSizeText(held) + " (--level L asks for N = L^2)"});
        targetSize = held;
    }
    FormatOptions writeOptions = options.write;
    if (!options.outFormat.empty()) // iridas_cube: the Adobe dialect, as OpenColorIO's baker
        FormatRegistry::instance().applyAlias(options.outFormat, writeOptions);
    LutFile toWrite = in;
    if (in.shaper && !writer->holdsShaperFor(writeOptions)) {
        // Every format without a shaper implies inputs 0..1 (an Adobe .cube could name the
        // shaper's range, 0..64, but then spends its lattice where display pictures are not:
        // inputs in 0..1 were off OpenColorIO's reading of the source by mean 85 steps): the
        // shaper, then the table, evaluated exactly at the output's lattice over 0..1, the error
        // bounded between lattice points (never the two merged over the shaper's range first).
        const int size = targetSize ? targetSize : kDefaultUnitSize;
        ErrorStats error;
        toWrite.cube = prepareUnitLut(in, size, output, sizeNotes, &error);
        toWrite.shaper.reset();
        report.resample = ResampleStep{sourceSize, size, options.interp, error, true};
        targetSize = size;
    } else if (targetSize != 0 && targetSize != sourceSize) {
        if (in.shaper && in.cube && writer->holdsShaper()) {
            // The output keeps the shaper: only the cube changes size.
            ResampleResult r = resampleWithError(*in.cube, targetSize, options.interp);
            r.lut.setDomain(in.cube->domainMin(), in.cube->domainMax());
            report.resample = ResampleStep{sourceSize, targetSize, options.interp, r.error};
            toWrite.cube = std::move(r.lut);
        } else {
            ResampleResult r = resampleWithError(in.toLut3D(0), targetSize, options.interp);
            report.resample = ResampleStep{sourceSize, targetSize, options.interp, r.error};
            toWrite.shaper.reset();
            toWrite.cube = std::move(r.lut);
        }
    }
    toWrite.diagnostics.clear();

    writeOptions.size = targetSize;
    t0 = Clock::now();
    std::string inPlaceBytes; // what went to standard output or a device, to read back
    report.writeDiagnostics = writeLutFile(*writer, output, toWrite, writeOptions, &inPlaceBytes);
    report.writeDiagnostics.insert(report.writeDiagnostics.begin(), sizeNotes.begin(),
                                   sizeNotes.end());
    report.writeSeconds = since(t0);

    // Read back what was written, in the layout it was written in.
    t0 = Clock::now();
    try {
        FormatOptions backOptions;
        backOptions.layout = options.write.layout;
        report.readBack = inPlaceBytes.empty()
                              ? readLut(output, backOptions)
                              : writer->readMemory(inPlaceBytes, output, backOptions);
        report.storage = storageError(toWrite, *report.readBack);
        report.storage->seconds = since(t0);
    } catch (const Error& e) {
        report.readBack.reset();
        report.readBackError = e.what();
    }
    report.totalSeconds = since(tStart);
    return report;
}

} // namespace lut::formats
