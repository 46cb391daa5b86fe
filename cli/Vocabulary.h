// SPDX-License-Identifier: Apache-2.0
#pragma once
// One vocabulary for every lutkit subcommand: an option name means the same thing everywhere
// (--format is the output format, --in-format the input's, --layout the output layout ...). The
// options several subcommands share are added here, once; an option whose values come from a
// fixed set gets a validator built from the library's own name lists (toString, the aliases its
// parser accepts, the format registry), so a bad value is bad usage (exit 2) with a "did you
// mean", and a name the library learns is accepted here without an edit.
#include "Notes.h"

#include "lut/formats/ColorTransform.h"
#include "lut/interp/Interpolation.h"
#include "lut/io/Layout.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lut::cli {

// A fixed set of names an option takes.
struct Choices {
    std::string kind;                 // "layout", "interp" ...: the validator is "choices:<kind>"
    std::string what;                 // "layout", "interpolation": for messages
    std::vector<std::string> names;   // the names users see, in the library's order
    std::vector<std::string> aliases; // older names still accepted
    // The library's parser: throws lut::Error for a name it does not know (it may accept more
    // spellings than names + aliases, e.g. "tetra").
    std::function<void(const std::string&)> accept;
};

Choices layoutChoices();
Choices interpChoices();
Choices presetChoices();
Choices stageChoices(); // also accepts "bloom", the preset's bloom stage
Choices readFormatChoices();
Choices writeFormatChoices();
Choices latticeChoices();
Choices targetChoices();
Choices cornerChoices();
Choices bitDepthChoices();
Choices imageFormatChoices();   // image files apply and preview read and write: png, exr, tif ...
Choices compressionChoices();   // --compression: the names OpenImageIO uses (zip, piz, lzw ...)
Choices shaperChoices();        // lutkit bake --shaper: auto, none, log2
Choices matchMethodChoices();   // lutkit match --method: auto, hm, mkl, hm-mkl-hm, regularised
Choices preserveChoices();      // lutkit match --preserve: luma, neutrals, skin
Choices matchShaperChoices();   // lutkit match --lut-form: auto, shaper, table
Choices atlasActionChoices();   // lutkit atlas ACTION: build, split, info
Choices strengthBlendChoices(); // --strength-blend: oklab, reshade
// The choices a validator name "choices:<kind>" refers to (nullopt for another name).
std::optional<Choices> choicesForValidator(const std::string& validatorName);

constexpr const char* kChoicesValidatorPrefix = "choices:";
constexpr const char* kMovedValidatorName = "moved";

// "unknown layout 'unrel'; did you mean 'unreal'? (expected unreal, unity, smush, hald, reshade or
// unity-32; also pilot, godot, lattice, unreal-32)"
std::string unknownNameMessage(const Choices& choices, const std::string& value);
// Validator named "choices:<kind>": accepts what choices.accept accepts.
CLI::Validator choicesValidator(const Choices& choices);
// Validator for --stage STAGE.PARAM=VALUE: the stage by name, the parameter and its range
// checked by the stage itself (lut::makeStage, Stage::setParam).
CLI::Validator stageSettingValidator();

// ---- Options shared by several subcommands (same name, same values everywhere) ----

CLI::Option* addOutputFormat(CLI::App& sub, std::string& target); // --format NAME
CLI::Option* addInputFormat(CLI::App& sub, std::string& target);  // --in-format NAME
// --layout (output), --in-layout (input), --lut-layout (the LUT read by apply/preview).
CLI::Option* addLayout(CLI::App& sub, const std::string& name, std::optional<LutLayout>& target,
                       const std::string& help);
// --interp (old spelling --interpolation, as lutkit bench and the editor had it).
CLI::Option* addInterp(CLI::App& sub, Interpolation& target, const std::string& help);
CLI::Option* addBitDepth(CLI::App& sub, int& target, const std::string& help);
CLI::Option* addThreads(CLI::App& sub, int& target);
// --frames RANGE (oiiotool's syntax: 1-100, 1-100x2, 1,5,7-9; lut/io/FrameSequence.h).
CLI::Option* addFrames(CLI::App& sub, std::string& target);
// --in-format / --format for images read from standard input and written to standard output.
void addImageFormats(CLI::App& sub, std::string& inFormat, std::string& outFormat);
// --format NAME for a command that writes one picture: its image format (png, exr ...) when the
// output is - (standard output) or has no extension.
CLI::Option* addImageOutputFormat(CLI::App& sub, std::string& target, const std::string& help);
// --compression NAME (default: the input's).
CLI::Option* addCompression(CLI::App& sub, std::string& target);
// --max-memory SIZE (4G, 512M; default half the RAM): what files in parallel may use together,
// and what one command may hold at once (lut::setMemoryLimit: a frame, standard input). Every
// command has it (CommandLine gives it to those that do not add it themselves).
CLI::Option* addMaxMemory(CLI::App& sub, std::string& target, const std::string& help = {});
// --subimage INT: which image of a file holding several (an OpenEXR part, a TIFF page, a GIF
// frame; from 0). Unset: -1.
CLI::Option* addSubimage(CLI::App& sub, int& target, const std::string& help);
// Every FLOAT option of app and its subcommands refuses NaN and infinities as bad usage (CLI11
// reads "nan" and "inf" as numbers, and its range checks let NaN through).
void refuseNonFiniteNumbers(CLI::App& app);

// Colour management (lut/formats/ColorTransform.h), named as ocioconvert and ociobakelut name
// them: --config FILE, --from SPACE, --to SPACE, --look LOOKS and, for All, --lut-space SPACE,
// --lut-output-space SPACE, --display DISPLAY and --view VIEW. The names are checked against the
// config when the command runs (the config may come later on the command line): value names
// SPACE, LOOKS, DISPLAY and VIEW.
enum class ColorOptionSet { All, Preview };
void addColorOptions(CLI::App& sub, formats::ColorSpec& target, ColorOptionSet set);
// --config FILE alone (bake adds its own names around it).
CLI::Option* addConfig(CLI::App& sub, std::string& target);

// -q/--quiet, and -v/--verbose when verboseHelp says what it adds ("" = nothing to add: no -v).
void addVerbosity(CLI::App& sub, Verbosity& target, const std::string& verboseHelp);

// An option whose meaning moved to another name (e.g. `info --format`, now --in-format): hidden
// from --help; using it is bad usage with `message`, which names the new spelling.
CLI::Option* addMovedOption(CLI::App& sub, const std::string& name, const std::string& message);

} // namespace lut::cli
