// SPDX-License-Identifier: Apache-2.0
#include "Vocabulary.h"

#include "Batch.h"
#include "Suggest.h"

#include "lut/Error.h"
#include "lut/Version.h"
#include "lut/formats/Registry.h"
#include "lut/io/FrameSequence.h"
#include "lut/io/MemoryLimit.h"
#include "lut/match/MatchOptions.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchLattice.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace lut::cli {

namespace {

template <class Enum> std::vector<std::string> namesOf(const std::vector<Enum>& values) {
    std::vector<std::string> names;
    for (const Enum v : values)
        names.emplace_back(toString(v));
    return names;
}

// "a, b or c"
std::string listText(const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return s;
}

std::string joined(const std::vector<std::string>& names, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i ? sep : "") + names[i];
    return s;
}

Choices formatChoices(const std::string& kind, bool writers) {
    formats::registerBuiltinFormats();
    Choices c{kind, writers ? "output format" : "input format", {}, {}, {}};
    for (const Format* f : FormatRegistry::instance().all())
        if (writers ? f->canWrite() : f->canRead()) {
            c.names.push_back(f->name());
            // OpenColorIO's names (resolve_cube, cinespace, 3dl ...), for ociobakelut users.
            for (const auto& a : f->aliases())
                c.aliases.push_back(a.name);
        }
    std::vector<std::string> names = c.names;
    names.insert(names.end(), c.aliases.begin(), c.aliases.end());
    c.accept = [names](const std::string& s) {
        if (std::find(names.begin(), names.end(), s) == names.end())
            throw Error("unknown format '" + s + "'");
    };
    return c;
}

} // namespace

Choices layoutChoices() {
    Choices c{"layout", "layout", namesOf(allLayouts()), {}, {}};
    for (const LutLayout l : allLayouts())
        for (const auto& a : layoutAliases(l))
            c.aliases.push_back(a);
    c.accept = [](const std::string& s) { (void)parseLayout(s); };
    return c;
}

Choices interpChoices() {
    Choices c{"interp",
              "interpolation",
              namesOf(std::vector<Interpolation>{Interpolation::Nearest, Interpolation::Trilinear,
                                                 Interpolation::Tetrahedral}),
              {},
              {}};
    c.accept = [](const std::string& s) { (void)parseInterpolation(s); };
    return c;
}

Choices presetChoices() {
    Choices c{"preset", "preset", namesOf(allPresets()), {}, {}};
    for (const Preset p : allPresets())
        for (const auto& a : presetAliases(p))
            c.aliases.push_back(a);
    c.accept = [](const std::string& s) { (void)parsePreset(s); };
    return c;
}

Choices stageChoices() {
    Choices c{"stage", "stage", stageNames(), {}, {}};
    for (const auto& alias : stageAliases())
        c.aliases.push_back(alias.first);
    c.accept = [](const std::string& s) {
        if (s != "bloom")
            (void)makeStage(s);
    };
    return c;
}

Choices readFormatChoices() {
    return formatChoices("in-format", false);
}

Choices writeFormatChoices() {
    return formatChoices("format", true);
}

Choices latticeChoices() {
    Choices c{"lattice",
              "lattice",
              namesOf(std::vector<PatchLattice>{PatchLattice::Uniform, PatchLattice::Smash}),
              {},
              {}};
    c.accept = [](const std::string& s) { (void)parseLattice(s); };
    return c;
}

Choices targetChoices() {
    Choices c{"target",
              "target",
              namesOf(std::vector<LutPurpose>{LutPurpose::Raw, LutPurpose::Smash}),
              {},
              {}};
    c.accept = [](const std::string& s) { (void)parseLutPurpose(s); };
    return c;
}

Choices matchMethodChoices() {
    Choices c{"match-method", "match method", namesOf(allMatchMethods()), {}, {}};
    for (const MatchMethod m : allMatchMethods())
        for (const auto& a : matchMethodAliases(m))
            c.aliases.push_back(a);
    c.accept = [](const std::string& s) { (void)parseMatchMethod(s); };
    return c;
}

Choices preserveChoices() {
    Choices c{"preserve", "preserve", namesOf(allMatchPreserves()), {}, {}};
    c.accept = [](const std::string& s) { (void)parseMatchPreserve(s); };
    return c;
}

Choices atlasActionChoices() {
    Choices c{"atlas-action", "atlas action", {"build", "split", "info"}, {}, {}};
    c.accept = [](const std::string& s) {
        if (s != "build" && s != "split" && s != "info")
            throw Error("unknown atlas action '" + s + "'");
    };
    return c;
}

Choices strengthBlendChoices() {
    Choices c{"strength-blend", "strength blend", {"oklab", "reshade"}, {}, {}};
    c.accept = [](const std::string& s) {
        if (s != "oklab" && s != "reshade")
            throw Error("unknown strength blend '" + s + "'");
    };
    return c;
}

Choices cornerChoices() {
    Choices c{"corner",
              "corner",
              namesOf(std::vector<PatchCorner>{PatchCorner::TopLeft, PatchCorner::TopRight,
                                               PatchCorner::BottomLeft, PatchCorner::BottomRight}),
              {},
              {}};
    c.accept = [](const std::string& s) { (void)parseCorner(s); };
    return c;
}

Choices bitDepthChoices() {
    Choices c{"bit-depth", "bit depth", {"8", "16", "32"}, {}, {}};
    c.accept = [](const std::string& s) {
        if (s != "8" && s != "16" && s != "32")
            throw Error("bit depth must be 8, 16 or 32 (float)");
    };
    return c;
}

Choices imageFormatChoices() {
    Choices c{"image-format",
              "image format",
              {"png", "exr", "tif", "jpg", "dpx", "ppm", "pgm", "bmp", "tga", "hdr", "webp", "gif"},
              {"tiff", "jpeg", "pnm", "openexr"},
              {}};
    std::vector<std::string> all = c.names;
    all.insert(all.end(), c.aliases.begin(), c.aliases.end());
    c.accept = [all](const std::string& s) {
        if (std::find(all.begin(), all.end(), s) == all.end())
            throw Error("unknown image format '" + s + "'");
    };
    return c;
}

Choices compressionChoices() {
    Choices c{"compression",
              "compression",
              {"none", "zip", "zips", "rle", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab", "lzw",
               "packbits", "jpeg"},
              {},
              {}};
    const std::vector<std::string> names = c.names;
    c.accept = [names](const std::string& s) {
        // "jpeg:90", "dwaa:45": a name with a quality OpenImageIO understands.
        const std::string base = s.substr(0, s.find(':'));
        if (std::find(names.begin(), names.end(), base) == names.end())
            throw Error("unknown compression '" + s + "'");
    };
    return c;
}

Choices shaperChoices() {
    Choices c{"shaper", "shaper", {"auto", "none", "log2"}, {}, {}};
    c.accept = [](const std::string& s) {
        if (s != "auto" && s != "none" && s != "log2")
            throw Error("unknown shaper '" + s + "'");
    };
    return c;
}

Choices matchShaperChoices() {
    Choices c{"lut-form", "LUT form", {"auto", "shaper", "table"}, {}, {}};
    c.accept = [](const std::string& s) {
        if (s != "auto" && s != "shaper" && s != "table")
            throw Error("unknown LUT form '" + s + "' (expected auto, shaper or table)");
    };
    return c;
}

std::optional<Choices> choicesForValidator(const std::string& name) {
    const std::string prefix = kChoicesValidatorPrefix;
    if (name.compare(0, prefix.size(), prefix) != 0)
        return std::nullopt;
    const std::string kind = name.substr(prefix.size());
    for (Choices (*make)() :
         {layoutChoices, interpChoices, presetChoices, stageChoices, readFormatChoices,
          writeFormatChoices, latticeChoices, targetChoices, cornerChoices, bitDepthChoices,
          imageFormatChoices, compressionChoices, shaperChoices, matchMethodChoices,
          preserveChoices, matchShaperChoices, atlasActionChoices, strengthBlendChoices}) {
        Choices c = make();
        if (c.kind == kind)
            return c;
    }
    return std::nullopt;
}

std::string unknownNameMessage(const Choices& c, const std::string& value) {
    std::vector<std::string> all = c.names;
    all.insert(all.end(), c.aliases.begin(), c.aliases.end());
    std::string s = "unknown " + c.what + " '" + value + "'";
    if (const auto guess = closestWord(value, all))
        s += "; did you mean '" + *guess + "'?";
    s += " (expected " + listText(c.names);
    if (!c.aliases.empty())
        s += "; also " + joined(c.aliases, ", ");
    return s + ")";
}

CLI::Validator choicesValidator(const Choices& c) {
    return CLI::Validator(
        [c](std::string& value) -> std::string {
            try {
                c.accept(value);
                return {};
            } catch (const Error&) {
                return unknownNameMessage(c, value);
            }
        },
        "{" + joined(c.names, ",") + "}", kChoicesValidatorPrefix + c.kind);
}

CLI::Validator stageSettingValidator() {
    return CLI::Validator(
        [](std::string& value) -> std::string {
            const auto eq = value.find('=');
            const auto dot = value.substr(0, eq).rfind('.');
            if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 == eq)
                return "bad stage setting '" + value + "' (expected STAGE.PARAM=VALUE)";
            const std::string stage = value.substr(0, dot);
            const Choices stages = stageChoices();
            try {
                stages.accept(stage);
            } catch (const Error&) {
                return unknownNameMessage(stages, stage);
            }
            if (stage == "bloom")
                return {}; // the preset's bloom: checked when the pipeline is built
            const auto s = makeStage(stage);
            const std::string param = value.substr(dot + 1, eq - dot - 1);
            std::vector<std::string> params;
            for (const auto& p : s->params())
                params.push_back(p.name);
            if (std::find(params.begin(), params.end(), param) == params.end()) {
                std::string msg = "stage '" + stage + "' has no parameter '" + param + "'";
                if (const auto guess = closestWord(param, params))
                    msg += "; did you mean '" + *guess + "'?";
                return msg + " (parameters: " + joined(params, ", ") + ")";
            }
            try {
                s->setParam(param, value.substr(eq + 1));
            } catch (const Error& e) {
                return e.what();
            }
            return {};
        },
        "STAGE.PARAM=VALUE", "stage-setting");
}

CLI::Option* addOutputFormat(CLI::App& sub, std::string& target) {
    return sub
        .add_option("--format", target,
                    "output format (default: from OUT's extension); for .cube also resolve_cube "
                    "(a 1D shaper and a 3D table where the LUT has a shaper) or iridas_cube (one "
                    "3D table, the form ffmpeg, Photoshop and game engines read)")
        ->type_name("NAME")
        ->check(choicesValidator(writeFormatChoices()));
}

CLI::Option* addInputFormat(CLI::App& sub, std::string& target) {
    return sub.add_option("--in-format", target, "input format (default: from the extension)")
        ->type_name("NAME")
        ->check(choicesValidator(readFormatChoices()));
}

CLI::Option* addLayout(CLI::App& sub, const std::string& name, std::optional<LutLayout>& target,
                       const std::string& help) {
    const Choices c = layoutChoices();
    return sub
        .add_option_function<std::string>(
            name, [&target](const std::string& v) { target = parseLayout(v); },
            help + " (also " + joined(c.aliases, ", ") + ")")
        ->type_name("NAME")
        ->check(choicesValidator(c));
}

CLI::Option* addInterp(CLI::App& sub, Interpolation& target, const std::string& help) {
    return sub
        .add_option_function<std::string>(
            "--interp,--interpolation",
            [&target](const std::string& v) { target = parseInterpolation(v); }, help)
        ->type_name("NAME")
        ->check(choicesValidator(interpChoices()));
}

CLI::Option* addBitDepth(CLI::App& sub, int& target, const std::string& help) {
    return sub.add_option("--bit-depth", target, help)
        ->type_name("BITS")
        ->check(choicesValidator(bitDepthChoices()));
}

CLI::Option* addThreads(CLI::App& sub, int& target) {
    return sub.add_option("--threads", target, "worker threads (default 0 = all cores)")
        ->check(CLI::Range(0, 1024));
}

CLI::Option* addFrames(CLI::App& sub, std::string& target) {
    return sub
        .add_option("--frames", target,
                    "frames of an input pattern: 1-100, 1-100x2, 1,5,7-9 (default: every frame "
                    "found)")
        ->type_name("RANGE")
        ->check(CLI::Validator(
            [](std::string& v) -> std::string {
                try {
                    (void)parseFrameRange(v);
                    return {};
                } catch (const Error& e) {
                    return e.what();
                }
            },
            "RANGE", "frame-range"));
}

void addImageFormats(CLI::App& sub, std::string& inFormat, std::string& outFormat) {
    const Choices c = imageFormatChoices();
    sub.add_option("--in-format", inFormat,
                   "image format of standard input (default: told from its first bytes)")
        ->type_name("NAME")
        ->check(choicesValidator(c));
    sub.add_option("--format", outFormat,
                   "image format written to standard output (default: the input's)")
        ->type_name("NAME")
        ->check(choicesValidator(c));
}

CLI::Option* addImageOutputFormat(CLI::App& sub, std::string& target, const std::string& help) {
    return sub.add_option("--format", target, help)
        ->type_name("NAME")
        ->check(choicesValidator(imageFormatChoices()));
}

CLI::Option* addCompression(CLI::App& sub, std::string& target) {
    return sub
        .add_option("--compression", target,
                    "compression of EXR/TIFF outputs: zip, piz, dwaa:45, lzw, none ... (default: "
                    "the input's)")
        ->type_name("NAME")
        ->check(choicesValidator(compressionChoices()));
}

CLI::Option* addMaxMemory(CLI::App& sub, std::string& target, const std::string& help) {
    return sub
        .add_option("--max-memory", target,
                    help.empty() ? "memory files in parallel may use together: 4G, 512M "
                                   "(default: half the RAM)"
                                 : help)
        ->type_name("SIZE")
        // The process's limit too (lut/io/MemoryLimit.h): what one file may take.
        ->each([](const std::string& v) { setMemoryLimit(parseMemorySize(v)); })
        ->check(CLI::Validator(
            [](std::string& v) -> std::string {
                try {
                    (void)parseMemorySize(v); // one grammar: checked here for exit 2
                } catch (const std::exception& e) {
                    return e.what();
                }
                return {};
            },
            "SIZE", "memory-size"));
}

CLI::Option* addSubimage(CLI::App& sub, int& target, const std::string& help) {
    return sub.add_option("--subimage", target, help)->check(CLI::Range(0, 1023));
}

void refuseNonFiniteNumbers(CLI::App& app) {
    const CLI::Validator finite(
        [](std::string& v) -> std::string {
            const char* s = v.c_str();
            char* end = nullptr;
            const double x = std::strtod(s, &end);
            if (end != s && !std::isfinite(x))
                return "value " + v + " is not a finite number";
            return {};
        },
        "", "finite");
    for (CLI::Option* o : app.get_options())
        if (o->get_type_name().rfind("FLOAT", 0) == 0)
            o->transform(finite); // first, before any range check (which would say "not in range")
    for (CLI::App* sub : app.get_subcommands({}))
        refuseNonFiniteNumbers(*sub);
}

CLI::Option* addConfig(CLI::App& sub, std::string& target) {
    return sub
        .add_option("--config", target,
                    "OpenColorIO config (default: $OCIO, else lutkit's own: " LUTKIT_DOC_DIR
                    "/docs/colour.md)")
        ->type_name("FILE");
}

void addColorOptions(CLI::App& sub, formats::ColorSpec& t, ColorOptionSet set) {
    const bool all = set == ColorOptionSet::All;
    const std::string group = "Colour management (OpenColorIO)";
    addConfig(sub, t.config)->group(group);
    sub.add_option("--from", t.from, "colour space of the input image (a name, alias or role)")
        ->type_name("SPACE")
        ->group(group);
    sub.add_option("--to", t.to,
                   "colour space to write the output in (default: the LUT's output space; "
                   "preview: sRGB)")
        ->type_name("SPACE")
        ->group(group);
    if (all) {
        sub.add_option("--lut-space", t.lutSpace,
                       "colour space the LUT was made for (default: --from)")
            ->type_name("SPACE")
            ->group(group);
        sub.add_option("--lut-output-space", t.lutOutputSpace,
                       "colour space of the LUT's output (default: --lut-space)")
            ->type_name("SPACE")
            ->group(group);
    }
    sub.add_option("--look", t.looks, "OpenColorIO looks to apply after --from (\"a, +b, -c\")")
        ->type_name("LOOKS")
        ->group(group);
    if (!all)
        return;
    sub.add_option("--display", t.display, "write for this display (with --view; not with --to)")
        ->type_name("DISPLAY")
        ->group(group);
    sub.add_option("--view", t.view, "the display's view (default: the display's first)")
        ->type_name("VIEW")
        ->group(group);
}

void addVerbosity(CLI::App& sub, Verbosity& target, const std::string& verboseHelp) {
    sub.add_flag("-q,--quiet", target.quiet,
                 "nothing but warnings and errors (no report, notes or progress bar)");
    if (!verboseHelp.empty())
        sub.add_flag("-v,--verbose", target.verbose, verboseHelp);
}

CLI::Option* addMovedOption(CLI::App& sub, const std::string& name, const std::string& message) {
    return sub.add_option_function<std::string>(name, [](const std::string&) {})
        ->check(
            CLI::Validator([message](std::string&) { return message; }, "", kMovedValidatorName))
        ->group("");
}

} // namespace lut::cli
