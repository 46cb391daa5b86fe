// SPDX-License-Identifier: Apache-2.0
#pragma once
// What lutkit says about what a LUT is for (lut/LutPurpose.h) and about turning it into the LUT
// for another purpose (lut/smash/PurposeConversion.h): one wording for convert, extract,
// apply, preview, compose and mix, and the options that choose it.
#include "Notes.h"

#include "lut/LutFile.h"
#include "lut/LutPurpose.h"
#include "lut/formats/Convert.h"
#include "lut/formats/LutDestination.h"
#include "lut/interp/Interpolation.h"
#include "lut/smash/PurposeConversion.h"
#include "lut/smash/PurposeOps.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <ostream>
#include <string>

namespace lut::cli {

// --target (what OUT is for), --in-target (what the input LUTs are for), --lut-target (the LUT
// apply and preview read): values raw | smash, checked against the library's names.
CLI::Option* addPurpose(CLI::App& sub, const std::string& name, std::string& target,
                        const std::string& help);
// "" = not given.
std::optional<LutPurpose> purposeOption(const std::string& value);

// The words around a purpose conversion.
struct ConversionWords {
    std::string stage = "neutral";                     // the stage LUT the edit was made on
    Interpolation interp = Interpolation::Tetrahedral; // how the edit is evaluated
};

// The report of a conversion, one line per fact:
//   raw -> smash  "game     the LUT that makes Smash Ultimate show this edit ...",
//                 "in game  ... exact composition ... refinement ...", "refine   ..."
//                 (with --refine: what it was fitted on and which LUT is written), "clamped ..."
//   smash -> raw  "edit     the edit this game LUT makes of the neutral game's picture ..."
void printConversion(std::ostream& os, const PurposeConversion& c, const ConversionWords& words);
// The same as a JSON object ("null" for no conversion).
std::string conversionJson(const std::optional<PurposeConversion>& c);

// When the file's content decided what it is for (PurposeSource::Content: it says nothing, and
// its table looks like the game's LUT), a warning on stderr: the evidence and `flag` raw.
void warnPurposeFromContent(const std::string& path, const PurposeDecision& decision,
                            const std::string& flag, const Verbosity& verbosity);

// The LUT a command reads, turned into `wanted`. A note on stderr says what the file was taken
// for when that changed the table (and what the conversion cost), or when the file does not say
// and has the game's size (16^3: it may be the game's LUT) with the flag that chooses. `given` is
// the flag's value, `flag` its name.
struct PurposedLut {
    Lut3D lut;
    PurposeDecision decision;
    std::optional<PurposeConversion> conversion;
};
PurposedLut lutFor(const LutFile& file, const std::string& path, LutPurpose wanted,
                   std::optional<LutPurpose> given, const std::string& flag,
                   const PurposeOptions& options, const Verbosity& verbosity);

// What the result of compose or mix is for: what its destination fixes (--target, else smash
// for the game's format: lut/formats/LutDestination.h), else what A is for. `known` says whether
// the output may say so (not when A's purpose was only assumed and nothing was converted); `why` is
// the reason printed.
struct ResultPurpose {
    LutPurpose to = LutPurpose::Raw;
    bool known = false;
    std::string why;
};
ResultPurpose resultPurpose(const PurposeDecision& a, const PurposeDecision& b,
                            const formats::LutDestination& out);
// What compose and mix share: A and B read with what they are for (--in-target), what OUT is for
// (--target), and after the operation its report and the purpose the output says.
struct PurposedPair {
    std::string aPath, bPath;
    Lut3D a, b;
    PurposeDecision pa, pb;
    ResultPurpose out;
};
PurposedPair readPurposedPair(const std::string& a, const std::string& b,
                              const std::string& inTarget, const std::string& target,
                              const std::string& output, const std::string& format,
                              const Verbosity& verbosity);
// "purpose  A: ...  B: ...  OUT: ..." (when any is not an assumed edit) and each conversion made
// on the way; returns what the output says it is for.
std::optional<LutPurpose> printPurposeOp(std::ostream& os, const PurposedPair& pair,
                                         const PurposeOpResult& result, Interpolation interp);

// --original-lut: the stage's LUT, the game's by the option's meaning (a file that does not say
// is taken as the game's; one that says raw is turned into the game's LUT that shows it, with a
// note).
Lut3D readStageLut(const std::string& path, const Verbosity& verbosity);

} // namespace lut::cli
