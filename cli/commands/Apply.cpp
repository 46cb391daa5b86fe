// SPDX-License-Identifier: Apache-2.0
// lutkit apply: a LUT on the stored pixel values of images (like Photoshop's Color Lookup).
#include "commands/Apply.h"

#include "Batch.h"
#include "LutFiles.h"
#include "PurposeText.h"
#include "StrengthOptions.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/ApplyImage.h"
#include "lut/formats/ColorConfig.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <mutex>

namespace lut::cli {

namespace {

// What the LUT saw outside its domain, and what the integer outputs clamped, over a batch: said
// once after it (a sequence of 240 frames said it 240 times, 230 characters each), with the
// colour spaces of the config whose images hold such values.
class OutsideTally {
public:
    void add(const std::string& input, const formats::ApplyImageReport& r) {
        ++m_files;
        m_domain.merge(r.domain);
        if (r.domain.outside) {
            ++m_filesOutside;
            m_firstOutside = m_firstOutside.empty() ? input : std::min(m_firstOutside, input);
        }
        m_clamped.merge(r.clamped);
        if (r.clamped.outside) {
            ++m_filesClamped;
            m_firstClamped = m_firstClamped.empty() ? input : std::min(m_firstClamped, input);
            m_eightBit = m_eightBit || r.output.type == formats::PixelType::UInt8;
        }
    }

    // The warnings, whole lines; "" when nothing was outside.
    std::string text(glm::vec3 domainMin, glm::vec3 domainMax,
                     const formats::ColorSpec& color) const {
        std::string out;
        if (m_domain.outside) {
            out += "lutkit: warning: " + printable(which(m_filesOutside, m_firstOutside)) +
                   m_domain.str(domainMin, domainMax) + "; they take the LUT's edge values" +
                   (color.any() ? "" : spacesHint(m_domain.worst, color.config)) + "\n";
        }
        if (m_clamped.outside) {
            // "12 of 4096 pixels (0.29%) have values outside [0, 1] after the LUT (worst 1.25)"
            std::string s = m_clamped.str(glm::vec3(0.0f), glm::vec3(1.0f));
            const std::string from = "outside the LUT's domain [0, 1]"; // str()'s wording
            if (const auto at = s.find(from); at != std::string::npos)
                s.replace(at, from.size(), "have values outside [0, 1] after the LUT");
            out += "lutkit: warning: " + printable(which(m_filesClamped, m_firstClamped)) + s +
                   ", clamped by the " + (m_eightBit ? "8" : "16") +
                   "-bit output (--bit-depth 32 or a float format such as EXR keeps them)\n";
        }
        return out;
    }

private:
    // "a.exr: " for one file, "3 of 24 files (f.0001.exr ...): " for a batch (the first name in
    // order, whichever thread finished first).
    std::string which(int files, const std::string& first) const {
        if (m_files == 1)
            return first + ": ";
        return std::to_string(files) + " of " + std::to_string(m_files) + " files (" + first +
               (files > 1 ? " ..." : "") + "): ";
    }

    // " (scene-linear values: --from one of 'ACEScg', ... (lutkit's own config), with
    // --lut-space the LUT's space)": the config's spaces whose images hold the worst value.
    static std::string spacesHint(float worst, const std::string& config) {
        const std::string generic =
            " (--from/--lut-space put the image in the space the LUT was made for)";
        std::vector<std::string> spaces;
        std::string where;
        try {
            spaces = formats::spacesHolding(worst, config);
            const formats::ConfigLocation at = formats::locateConfig(config);
            where =
                at.source == formats::ConfigSource::Shipped ? "lutkit's own config" : at.describe();
        } catch (const std::exception&) { // no config (or the portable edition): no names
            return generic;
        }
        if (spaces.empty())
            return generic;
        std::string list;
        for (std::size_t i = 0; i < spaces.size(); ++i)
            list += (i ? ", " : "") + ("'" + spaces[i] + "'");
        return std::string(" (scene-linear values: --from ") +
               (spaces.size() > 1 ? "one of " : "") + list + " (" + where +
               "), with --lut-space the LUT's space)";
    }

    int m_files = 0, m_filesOutside = 0, m_filesClamped = 0;
    DomainStats m_domain, m_clamped;
    std::string m_firstOutside, m_firstClamped;
    bool m_eightBit = false;
};

} // namespace

int runApply(const ApplyOptions& o) {
    // The LUT, in the colour space it was made for when --from/--to... ask (OpenColorIO's
    // conversions as steps before and after it). First: a misspelt name is bad usage (exit 2),
    // whatever the files.
    const formats::ColorPlan colour = formats::planColor(o.color);
    const BatchPlan plan = planBatch(o.inputs, o.output, {o.lut, o.color.config}, o.frames);
    BatchOptions bo;
    bo.threads = o.threads;
    bo.quiet = o.verbosity.quiet;
    bo.maxMemory = o.maxMemory.empty() ? 0 : parseMemorySize(o.maxMemory);
    const LutFile file = readCommandLut(o.lut, o.lutLayout, o.verbosity);
    printDiagnostics(std::cerr, colour.diagnostics, o.verbosity, "lutkit: ");
    if (o.verbosity.verbose && o.color.any())
        std::cerr << "lutkit: " << colour.describe() << "\n";
    // An edit goes on the pixels as it is (a shaper then its table, exactly); the game's LUT as
    // the edit it makes of the game's picture (lut/smash/PurposeConversion.h), with a note
    // saying so and what it cost. At another strength, that edit blended with neutral (one
    // table).
    // (65^3: half the 33^3 lattice's mean error for ~1 s more, measured on a warm stage LUT)
    PurposeOptions po;
    po.rawSize = 65;
    PurposedLut used = lutFor(file, o.lut, LutPurpose::Raw, purposeOption(o.lutTarget),
                              "--lut-target", po, o.verbosity);
    const PixelChain chain =
        !isFullStrength(o.strength)
            ? formats::lutPixelChain(
                  colour, strengthLut(std::move(used.lut), o.lut, o.strength, o.verbosity),
                  o.interp)
        : used.conversion ? formats::lutPixelChain(colour, std::move(used.lut), o.interp)
                          : formats::lutPixelChain(colour, file, o.interp);
    std::mutex noteMutex;
    OutsideTally tally;
    bo.afterJobs = [&] { std::cerr << tally.text(chain.domainMin(), chain.domainMax(), o.color); };
    return runBatch(plan, bo, [&](const BatchJob& j, JobContext& ctx) {
        formats::ApplyImageOptions ao;
        ao.bitDepth = o.bitDepth;
        ao.compression = o.compression;
        ao.inFormat = o.inFormat;
        ao.outFormat = o.format;
        ao.threads = ctx.innerThreads();
        ao.subimage = o.subimage;
        // Held before anything is decoded: files in parallel stay within --max-memory.
        ao.reserveMemory = [&ctx](std::uint64_t bytes, const std::string& what) {
            ctx.reserveMemory(bytes, what);
        };
        formats::ApplyImageReport r;
        try {
            r = formats::applyToImage(j.input, j.target, chain, ao);
        } catch (const formats::MultiImageError& e) {
            throw Error(j.input + ": holds " + std::to_string(e.count()) + " images (" + e.kind() +
                        ") and " + j.output +
                        "'s format holds one: write .exr or .tif to keep every one, or pick "
                        "one with --subimage N (0 to " +
                        std::to_string(e.count() - 1) + ")");
        }
        {
            // Values outside the LUT's domain and values clamped by the output: counted over the
            // batch, said once after it (afterJobs); the file's own notes now, above the bar.
            std::lock_guard<std::mutex> lock(noteMutex);
            tally.add(j.input, r);
        }
        std::string notes;
        for (const auto& d : r.diagnostics)
            if (isShown(d, o.verbosity))
                notes += std::string("lutkit: ") + severityWord(d.severity) + ": " +
                         printable(j.input + ": " + d.message) + "\n";
        ctx.warn(notes);
        if (!o.verbosity.verbose)
            return std::string();
        return j.input + " -> " + j.output + " (" + formats::toString(r.output.type) +
               (r.unchanged ? ", neutral: values copied" : "") + ")\n";
    });
}

CLI::App* setupApply(CLI::App& app, std::function<void(const ApplyOptions&)> onParsed) {
    auto o = std::make_shared<ApplyOptions>();
    auto* sub = app.add_subcommand(
        "apply", "Apply a LUT to the stored pixel values of images (data type, alpha, compression "
                 "and metadata kept), or in its own colour space (--from)");
    sub->add_option("--lut", o->lut,
                    "LUT file (any supported format), or a built-in: builtin:neutral, "
                    "builtin:smash-default")
        ->required()
        ->type_name("FILE");
    addLayout(*sub, "--lut-layout", o->lutLayout,
              "the LUT's layout when it is an image (default: detected)");
    addPurpose(*sub, "--lut-target", o->lutTarget,
               "what --lut is for (default: what the file says, LUTKIT_PURPOSE, or a .nutexb; "
               "else raw): the game's LUT (smash) is applied as the edit it makes of the game's "
               "picture");
    sub->add_option("INPUTS", o->inputs,
                    "images, folders of images, frame patterns (f.%04d.exr), or - (stdin)")
        ->type_name("FILE");
    addOutputOptions(*sub, o->output,
                     "output: a file (one input), a folder (existing, or ending in /), a frame "
                     "pattern (out.%04d.exr), or - (stdout)");
    addFrames(*sub, o->frames);
    addImageFormats(*sub, o->inFormat, o->format);
    addBitDepth(*sub, o->bitDepth,
                "output data type: 8, 16 (half for EXR) or 32 (float) (default: the input's)");
    addCompression(*sub, o->compression);
    addMaxMemory(*sub, o->maxMemory);
    addSubimage(*sub, o->subimage,
                "only this image of files holding several (OpenEXR part, TIFF page, GIF frame; "
                "from 0) (default: every one, where the output format holds them)");
    addInterp(*sub, o->interp, "interpolation (default tetrahedral)");
    addThreads(*sub, o->threads);
    addStrengthOptions(*sub, o->strength);
    addColorOptions(*sub, o->color, ColorOptionSet::All);
    addVerbosity(*sub, o->verbosity, "print IN -> OUT for every file written");
    sub->footer(
        "Examples:\n"
        "  lutkit apply --lut grade.cube shot.png -o graded.png\n"
        "  lutkit apply --lut grade.cube frames/ -o graded/       # every image in frames/\n"
        "  lutkit apply --lut grade.cube f.%04d.exr --frames 1-100 -o out.%04d.exr\n"
        "  lutkit apply --lut grade.cube - --in-format png -o - --format png < in.png > out.png\n"
        "  lutkit apply --lut edited_strip.png --lut-layout unity in.tif -o out.tif -y\n"
        "  lutkit apply --lut grade.cube --strength 0.5 shot.png -o half.png\n"
        "  lutkit apply --lut log_look.cube --from ACEScg --lut-space ACEScct --to sRGB "
        "render.exr -o out.png\n"
        "An existing output is replaced only with -y; -n skips existing outputs.");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
