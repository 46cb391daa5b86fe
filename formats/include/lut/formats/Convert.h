// SPDX-License-Identifier: Apache-2.0
#pragma once
// Converting a LUT file into another format and, when asked or when the output means it, to
// another purpose (lut/LutPurpose.h: a .nutexb is the game's LUT), saying what it cost: what
// `lutkit convert` does, for every target. The purpose step is lut::convertPurpose
// (lut/smash/PurposeConversion.h); the output says what it is for where its format has a
// place for it. The losses are measured apart:
//  - resampling, when the output stores another lattice size (the format's fixed size or the one
//    asked for): lut::resampleWithError on a probe grid;
//  - storage (integer quantisation, clipping, a dropped domain or shaper): the written file is
//    read back and compared with the table that was handed to the writer.
// The input is never written over (lut::checkNotOverwritingInputs); the output is written
// atomically and verified (lut/io/AtomicFile.h).
#include "lut/ErrorStats.h"
#include "lut/LutFile.h"
#include "lut/LutPurpose.h"
#include "lut/formats/LutDestination.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/FormatOptions.h"
#include "lut/ops/Strength.h"
#include "lut/smash/PurposeConversion.h"

#include <optional>
#include <string>

namespace lut::formats {

struct ConvertOptions {
    std::string inFormat;  // input format name ("" = by extension)
    std::string outFormat; // output format name ("" = by extension)
    FormatOptions read;    // how to read the input (layout of a LUT image, sampling size ...)
    // How to write the output. write.size is the output lattice size: 0 = the output format's
    // fixed size if it has one, else the input's.
    FormatOptions write;
    Interpolation interp = Interpolation::Tetrahedral; // for resampling
    // What the input is for: nullopt = what the file says (its tag, a .nutexb), else raw.
    std::optional<LutPurpose> inPurpose;
    // What the output is for: nullopt = the destination's rule (lut/formats/LutDestination.h:
    // smash for the game's format, else the input's).
    std::optional<LutPurpose> outPurpose;
    // raw <-> smash: the stage LUT, the screenshot, the refinement, the rule above white.
    PurposeOptions purpose;
    // The LUT blended with neutral before it is resampled and written (lut/ops/Strength.h); a
    // shaper is baked into the 3D table first (the neutral of the whole file).
    StrengthOptions strength;
};

// What the input and the output are for, and the conversion between them.
struct PurposeStep {
    PurposeDecision input;
    LutPurpose output = LutPurpose::Raw;
    DestinationPurpose outputFrom = DestinationPurpose::Input; // said, the game's format, as IN
    std::optional<PurposeConversion> conversion;               // when the purposes differ
};

struct ResampleStep {
    int from = 0; // input lattice size
    int to = 0;   // output lattice size
    Interpolation interp = Interpolation::Tetrahedral;
    ErrorStats error; // against the input on a probe grid (with its time)
    // The input's 1D shaper and table sampled at one lattice over 0..1 (a format without a
    // shaper): the error is against the shaper then the table, evaluated exactly.
    bool shaper = false;
};

struct ConvertReport {
    LutFile input; // as read (with its diagnostics)
    double readSeconds = 0.0;
    PurposeStep purpose;
    std::string outputFormat;                // the writer's name
    std::optional<StrengthAmounts> strength; // nullopt: full strength, the LUT as read
    std::optional<ResampleStep> resample;    // nullopt: written at the input's size
    Diagnostics writeDiagnostics;
    double writeSeconds = 0.0;
    std::optional<LutFile> readBack;   // the output read back (nullopt: it could not be read)
    std::optional<ErrorStats> storage; // written table vs read back (with the read-back time)
    std::string readBackError;         // why the output could not be read back
    double totalSeconds = 0.0;
};

// Reads `input`, blends it with neutral when options.strength asks (the edit: before it is made
// into the game's LUT, after a game LUT is made into its edit), turns it into the output's purpose
// (a game LUT is 16^3: another size asked for it throws RequestError, bad usage), resamples
// when the output stores another size, writes `output`, reads it back and measures. Throws
// lut::Error for an unknown format name, an output extension no format writes, an unreadable
// input, a size outside lut/Limits.h, or a failed write (the old output, if any, is left as it
// was).
ConvertReport convertLut(const std::string& input, const std::string& output,
                         const ConvertOptions& options = {});

} // namespace lut::formats
