// SPDX-License-Identifier: Apache-2.0
// planBatch (Batch.h): which file is written where, decided before anything is written.
#include "Batch.h"
#include "Usage.h"

#include "lut/Error.h"
#include "lut/formats/ImageFiles.h"
#include "lut/io/FrameSequence.h"
#include "lut/io/InputFile.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace lut::cli {

namespace fs = std::filesystem;

namespace {

struct Source {
    std::string path;
    std::optional<long> frame; // from a frame pattern
    std::string refused;       // a frame asked for by --frames that is missing
};

std::vector<Source> expandInputs(const std::vector<std::string>& inputs, const std::string& frames,
                                 std::vector<std::string>& notes, const FolderFiles& folderFiles) {
    std::vector<Source> out;
    bool patternSeen = false;
    for (const auto& in : inputs) {
        if (in == "-") {
            out.push_back({in, std::nullopt, {}});
            continue;
        }
        if (os::isDirectory(in)) {
            std::vector<fs::path> files;
            const std::size_t notesBefore = notes.size();
            std::error_code ec;
            for (const auto& e : fs::directory_iterator(os::toPath(in), ec)) {
                const std::string name = os::fromPath(e.path());
                if (!(folderFiles.accepts ? folderFiles.accepts(name)
                                          : formats::isImageExtension(name)))
                    continue; // not a file of the kind read here
                std::error_code kind;
                if (e.is_regular_file(kind)) {
                    files.push_back(e.path());
                    continue;
                }
                // Named as an input but not a file to read (a FIFO, a link to a device, a link
                // that loops or names nothing, a folder): said, one line each (it was skipped
                // without a word).
                try {
                    checkRegularInput(name);
                    notes.push_back(name + ": cannot be read; skipped");
                } catch (const Error& err) {
                    notes.push_back(std::string(err.what()) + "; skipped");
                }
            }
            if (files.empty())
                throw Error(in + ": folder holds no " +
                            (folderFiles.what.empty()
                                 ? std::string("image files (.png .jpg .tif .exr .dpx ...)")
                                 : folderFiles.what) +
                            (notes.size() > notesBefore ? " to read (" + notes[notesBefore] + ")"
                                                        : std::string()));
            std::sort(files.begin(), files.end());
            for (const auto& f : files)
                out.push_back({os::fromPath(f), std::nullopt, {}});
            continue;
        }
        if (const auto pattern = parseFramePattern(in)) {
            patternSeen = true;
            if (!frames.empty()) {
                std::vector<long> missing;
                for (const long f : parseFrameRange(frames)) {
                    Source s{pattern->path(f), f, {}};
                    if (!os::exists(s.path)) {
                        s.refused =
                            "frame " + std::to_string(f) + " is missing (--frames " + frames + ")";
                        missing.push_back(f);
                    }
                    out.push_back(std::move(s));
                }
                std::sort(missing.begin(), missing.end());
                if (!missing.empty())
                    notes.push_back("frames " + describeFrames(missing) + " of " + in +
                                    " are missing");
                continue;
            }
            const std::vector<long> found = findFrames(*pattern);
            if (found.empty())
                throw Error(in + ": no file matches this frame pattern");
            if (const std::string gap = missingFrames(found); !gap.empty())
                notes.push_back("frames " + gap + " of " + in + " are missing (found " +
                                describeFrames(found) + ")");
            for (const long f : found)
                out.push_back({pattern->path(f), f, {}});
            continue;
        }
        out.push_back({in, std::nullopt, {}}); // a missing file becomes this job's failure
    }
    if (!frames.empty() && !patternSeen)
        throw UsageError("--frames needs an input frame pattern (frame.%04d.exr, frame.####.exr)");
    return out;
}

} // namespace

BatchPlan planBatch(const std::vector<std::string>& inputs, const OutputOptions& output,
                    const std::vector<std::string>& protect, const std::string& frames,
                    const std::string& outExtension, const FolderFiles& folderFiles) {
    if (inputs.empty())
        throw UsageError("no input files");
    if (output.output.empty())
        throw UsageError(inputs.size() == 2
                             ? "name the output with -o (two files mean two inputs: '-o " +
                                   inputs[1] + "' writes the first to the second)"
                             : "name the output with -o (a file, a folder/ or a pattern "
                               "out.%04d.png)");
    BatchPlan plan;
    std::vector<Source> sources;
    try {
        sources = expandInputs(inputs, frames, plan.notes, folderFiles);
    } catch (const UsageError&) {
        throw;
    }
    const std::string& o = output.output;
    const bool stdinUsed =
        std::any_of(sources.begin(), sources.end(), [](const Source& s) { return s.path == "-"; });
    if (stdinUsed && sources.size() > 1)
        throw UsageError("standard input (-) can only be the one input");

    noteOutputPath(o); // data on stdout: every note on stderr
    const auto outPattern = o == "-" ? std::nullopt : parseFramePattern(o);
    const bool folder =
        !outPattern && o != "-" && (os::isPathSeparator(o.back()) || os::isDirectory(o));
    const bool singleFile = inputs.size() == 1 && sources.size() == 1 &&
                            !os::isDirectory(inputs[0]) && !parseFramePattern(inputs[0]);
    if (!outPattern && !folder && !singleFile)
        throw UsageError(std::to_string(sources.size()) + " inputs need -o DIR/ (a folder: " +
                         "existing, or ending in /) or a frame pattern (out.%04d.png), not '" + o +
                         "'");
    if (folder && stdinUsed)
        throw UsageError("standard input (-) has no name to write into a folder: -o FILE");
    if (folder && !os::isDirectory(o)) {
        std::error_code ec;
        fs::create_directories(os::toPath(o), ec); // a trailing slash says it is a folder
        if (ec)
            throw Error(o + ": cannot create the folder: " + ec.message());
    }

    std::vector<std::string> allInputs = protect;
    for (const auto& s : sources)
        allInputs.push_back(s.path);
    std::set<std::string> names;
    std::vector<std::string> existing;
    long next = 1;
    for (const auto& s : sources) {
        std::string out;
        if (outPattern) {
            out = outPattern->path(s.frame ? *s.frame : next);
            ++next;
        } else if (folder) {
            fs::path name = os::toPath(s.path).filename();
            if (!outExtension.empty())
                name.replace_extension(os::toPath(outExtension));
            out = os::fromPath(os::toPath(o) / name);
        } else {
            out = o;
        }
        BatchJob j{s.path, out, OutputTarget{}, false, s.refused};
        if (!names.insert(j.output).second) {
            j.refused = "another input has the same output " + j.output;
            plan.jobs.push_back(std::move(j));
            continue;
        }
        if (j.refused.empty()) {
            try {
                j.target = commandOutputs().claim(j.output, output.rule(), allInputs);
                j.skip = j.target.skip;
            } catch (const OutputExistsError& e) {
                existing.push_back(e.path());
            } catch (const Error& e) {
                j.refused = e.what();
            }
        }
        plan.jobs.push_back(std::move(j));
    }
    if (!existing.empty()) {
        const bool batch = plan.jobs.size() > 1;
        std::string msg = existsMessage(existing.front(), batch);
        if (existing.size() > 1)
            msg = std::to_string(existing.size()) +
                  " outputs already exist (the first: " + existing.front() +
                  "); pass -y/--overwrite to replace them or -n/--no-clobber to skip them";
        throw Error(msg);
    }
    return plan;
}

} // namespace lut::cli
