// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a LUT is for: the one vocabulary of the library, both programs and the files they write
// (docs/architecture.md, "Why one purpose"; docs/roundtrip.md):
//   Raw    "raw": the look itself, a function of display colours: what a colourist's .cube, an
//          engine's strip (Unreal, Unity, Pilot apply it to the displayed picture) or a modder's
//          graded neutral.png holds;
//   Smash  "smash": Smash Ultimate's LUT (color_grading_lut.nutexb): what the game applies in its
//          grading pass, compensated for its brighten step so that the game shows a look.
// A file says which it is with the tag "LUTKIT_PURPOSE raw|smash": a comment line in a .cube, a
// .3dl and an .itx ("# LUTKIT_PURPOSE smash" on top), a description in .clf, .ctf and .csp, a
// text field in a LUT image (a PNG tEXt chunk, a TIFF ImageDescription, an OpenEXR comments
// attribute); a .nutexb is the game's LUT by its format. Other readers ignore the tag
// (OpenColorIO, ffmpeg, Resolve: a comment). .cub, .spi3d and Houdini's .lut have no place for it:
// writing a game LUT there warns with the flag that reads it back (Format::keepsPurpose,
// lut::writeLutFile). A file that says nothing may still be told by its content
// (lut/LutFile.h's gameLutEvidence: Smush-LUT's untagged output).
#include "lut/Error.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

enum class LutPurpose {
    Raw,   // "raw": the look itself, applied to the displayed picture
    Smash, // "smash": the game's LUT, compensated for its grading and brighten step (the nutexb)
};
const char* toString(LutPurpose purpose);          // "raw", "smash"
LutPurpose parseLutPurpose(std::string_view name); // "raw", "smash"; throws lut::Error
const char* describe(LutPurpose purpose);          // "an edit (the look itself)", ...
std::vector<std::string> lutPurposeNames();        // {"raw", "smash"}

// The tag a file carries: "LUTKIT_PURPOSE smash".
constexpr const char* kPurposeKeyword = "LUTKIT_PURPOSE";
std::string purposeTag(LutPurpose purpose);

// What a text (a comment line without its '#', an image's description) declares: nullopt when
// it holds no tag. A line of a multi-line text may carry it. A tag with another word is an error
// naming the word (`where` names the file and the place for the message).
std::optional<LutPurpose> purposeInText(std::string_view text, const std::string& where = {});

// Takes the tag out of a file's comment lines (so a writer does not write it twice): returns the
// purpose they declare, nullopt when none does. Two tags that disagree are an error.
std::optional<LutPurpose> takePurposeTag(std::vector<std::string>& comments,
                                         const std::string& where = {});

// Which purpose a command takes for a LUT it reads, and why: what the user gave (a flag, an
// answer) first, then what the file says (its tag, or its format: a .nutexb is the game's LUT),
// then what its content says (Content: lut/LutFile.h's gameLutEvidence, for a file that says
// nothing), else `assumed` (lutkit's default: raw). The programs say the text when the file did
// not say, and warn when the content decided.
enum class PurposeSource { Given, File, Format, Builtin, Content, Assumed };
struct PurposeDecision {
    LutPurpose purpose = LutPurpose::Raw;
    PurposeSource source = PurposeSource::Assumed;
    std::optional<LutPurpose> said; // what the file says (kept when given overrides it)
    std::string evidence;           // Content: what in the table says so
    // "smash (the file says so: LUTKIT_PURPOSE smash)", "smash (a .nutexb is the game's LUT)",
    // "smash (a built-in game LUT)",
    // "raw (--in-target)", "raw (the file does not say; --in-target smash if it is the game's
    // LUT)", "smash (the file does not say; its content does: EVIDENCE; --in-target raw if it is
    // an edit)": `how` names what chooses (a flag, the editor's question).
    std::string text(const std::string& how) const;
};
PurposeDecision decidePurpose(std::optional<LutPurpose> said, bool byFormat,
                              std::optional<LutPurpose> given,
                              LutPurpose assumed = LutPurpose::Raw);

} // namespace lut
