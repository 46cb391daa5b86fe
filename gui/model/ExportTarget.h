// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where the LUT goes: the export destinations, each a file type made for one purpose
// (lut/LutPurpose.h, the one vocabulary of what a LUT is for; the purpose and the lattice are
// the library's rule, lut/formats/LutDestination.h, as for lutkit convert):
//   Smash    Smash Ultimate: color_grading_lut.nutexb, the game's 16^3 LUT (purpose smash): an edit
//            made into the LUT that makes the game show it (lut::convertPurpose, as lutkit
//            convert does); the preview runs the game's chain with it.
//   Engine   a game engine's strip (16^3 as a 256x16 PNG in the unreal layout, 8-bit), an edit
//            (purpose raw); the preview applies it to the encoded picture (or runs the chosen
//            engine chain on a linear scene).
//   Grading  a .cube for a grading application, the edit at the document's size, float (raw).
// The preview grades with the LUT the default export writes, read back from its bytes
// (makeTargetLut), so the window shows what the file gives, quantisation and resampling included.
// Plain C++ over lutlib and the formats (no Qt).
#include "lut/Error.h"
#include "lut/Lut3D.h"
#include "lut/LutPurpose.h"
#include "lut/io/FormatOptions.h"
#include "lut/ops/Adjust.h"
#include "lut/ops/Clipping.h"
#include "lut/ops/Strength.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut::gui {

enum class ExportTarget { Smash, Engine, Grading };

struct ExportTargetInfo {
    ExportTarget id;
    std::string key;                 // "smash", "engine", "cube": settings, command line, scripts
    std::string label;               // what the toolbar shows
    std::string format;              // registry name of the default export format
    std::optional<LutLayout> layout; // for image formats
    std::string extension;           // of the default export, with the dot
    // From the library's rule for where a LUT goes (lut/formats/LutDestination.h):
    int size;           // lattice size written (0 = the document's)
    int bitDepth;       // 0 = the format's default
    LutPurpose purpose; // what the file is for (its LUTKIT_PURPOSE tag)
};

const std::vector<ExportTargetInfo>& exportTargets();
const ExportTargetInfo& exportTargetInfo(ExportTarget target);
// "smash", "engine", "cube" (also "grading", "raw"); throws lut::Error.
ExportTarget parseExportTarget(std::string_view key);
// Whether an export to `path` with no format named (`format` empty) is the target's own file
// type: the format that writes the path is the target's (then the target's settings apply).
bool isTargetFile(ExportTarget target, const std::string& path, const std::string& format);

// The document's state an export is made from. The pointers identify it: two sources are the
// same when they hold the same objects (a change makes new ones).
struct LutSource {
    // Base LUT with the adjustments applied (null = neutral 33^3).
    std::shared_ptr<const Lut3D> effective;
    // The base, when it is the game's LUT (purpose smash: a .nutexb, a file that says so, or one
    // the user said is): then the adjustments edit the picture the game shows with it; null when
    // the base is an edit (purpose raw).
    std::shared_ptr<const Lut3D> gameBase;
    std::shared_ptr<const Adjustments> adjustments; // with gameBase (null = neutral)
    LutPurpose purpose() const { return gameBase ? LutPurpose::Smash : LutPurpose::Raw; }
    bool operator==(const LutSource&) const = default;
};

// The default export for a target, made from a source.
struct TargetLut {
    Lut3D table;                        // what the export writes, before the format rounds it
    std::shared_ptr<const Lut3D> shown; // the written bytes read back: what the preview uses
    ClipCount clip;                     // entries of `table` outside [0, 1] (the file clamps)
    Diagnostics notes;                  // what the writer reported (rounding, resampling...)
};

// The table a target exports: the source made for the target's purpose by the library's one
// conversion (lut::convertPurpose, its one rule above white, as lutkit convert makes it), with
// the adjustments as an edit of the picture. Smash: the 16^3 game LUT, its exact composition
// before the file clamps it to [0, 1] (as convert's file clamps it: the same .nutexb bytes);
// others: the edit (a game LUT as the edit it makes). At a partial strength (lut/ops/Strength.h)
// the edit is blended with neutral first: for Smash before it is made for the game, so the game
// shows that share of the edit. `clip` (optional) counts the entries outside [0, 1].
Lut3D exportTable(const LutSource& source, ExportTarget target,
                  const StrengthOptions& strength = {}, ClipCount* clip = nullptr);
// The default format options of a target for writing `table`.
FormatOptions targetFormatOptions(ExportTarget target);
// Writes the target's default export to memory and reads it back; throws lut::Error.
TargetLut makeTargetLut(const LutSource& source, ExportTarget target);

} // namespace lut::gui
