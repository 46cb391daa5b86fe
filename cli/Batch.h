// SPDX-License-Identifier: Apache-2.0
#pragma once
// The batch runner shared by lutkit apply and lutkit preview: which files to write where
// (planBatch), and running a job per file, files in parallel within a memory budget, with a
// progress bar and a one-line summary, going on past failures (runBatch).
#include "Outputs.h"

#include "lut/io/OutputPolicy.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lut::cli {

struct BatchJob {
    std::string input;  // a file, or "-" (standard input)
    std::string output; // as named to the user
    OutputTarget target;
    bool skip = false;   // -n and the output exists
    std::string refused; // planned as a failure: this job's error (e.g. a missing frame)
};

// Which files of an input folder are inputs: image files unless `accepts` is set (convert takes
// every LUT file); `what` names them in the message for a folder without one ("LUT files").
struct FolderFiles {
    std::function<bool(const std::string&)> accepts;
    std::string what;
};

struct BatchPlan {
    std::vector<BatchJob> jobs;
    std::vector<std::string> notes; // e.g. "frames 4, 6-8 of f.%04d.png are missing"
};

// Inputs are files, folders (their image files, sorted, not recursive; a folder without one is
// an error), frame patterns (f.%04d.exr, f.####.exr: the frames present, or `frames` when given),
// or "-". The output (-o) is:
//   - a file: for exactly one input file (or "-" for standard output);
//   - a folder: an existing one, or any path ending in '/' (created): DIR/<input name>, the
//     extension replaced by outExtension when given (".png");
//   - a frame pattern: the input's frame numbers, or 1, 2, ... for other inputs.
// No -o, or one file for several inputs, is bad usage (UsageError, naming -o). Two inputs never
// mean "write the second". Existing outputs are refused before anything is written (lut::Error
// naming -y and -n), or skipped with -n. No output may be one of the inputs or of `protect`
// (the --lut file ...). Throws UsageError or lut::Error.
BatchPlan planBatch(const std::vector<std::string>& inputs, const OutputOptions& output,
                    const std::vector<std::string>& protect, const std::string& frames = {},
                    const std::string& outExtension = {}, const FolderFiles& folderFiles = {});

// What a job may ask of the runner.
class JobContext {
public:
    virtual ~JobContext() = default;
    // Blocks until `bytes` of the batch's memory budget are free and holds them until the job
    // ends; throws lut::Error when one file alone needs more than the whole budget.
    virtual void reserveMemory(std::uint64_t bytes, const std::string& what) = 0;
    virtual int innerThreads() const = 0; // threads this job may use
    // Prints text (whole lines) to standard error above the progress bar: the bar's line is
    // cleared first and drawn again after, so a warning never lands in the middle of it.
    virtual void warn(const std::string& text) = 0;
};

struct BatchOptions {
    int threads = 0;             // 0 = all cores
    bool quiet = false;          // no progress bar, no summary
    std::uint64_t maxMemory = 0; // 0 = defaultMaxMemory()
    std::string unit = "files";  // for the summary
    // Called once every job is done, the bar cleared, before the failures and the summary: for
    // what is said once per batch (apply's values outside the LUT's domain, over every frame).
    std::function<void()> afterJobs;
};

// Half the physical memory (what --max-memory defaults to).
std::uint64_t defaultMaxMemory();
// "4G", "512M", "1.5GB", "2000000000" (a number alone is bytes): bytes. Throws UsageError (exit
// 2) for anything else, under 1 MiB or over 1e18 bytes.
std::uint64_t parseMemorySize(const std::string& text);

// Runs fn for every job not skipped, files in parallel (a single file gets every thread), within
// the memory budget. fn throws on failure; the batch keeps going. On a terminal (stderr, not
// quiet) a progress bar shows the current file, files done/total, elapsed time and ETA, and
// leaves a one-line summary (files, frames/s, skipped, failures); every failure is listed after.
// Returns the exit code (1 if any job failed). fn's returned text is printed to stdout.
int runBatch(const BatchPlan& plan, const BatchOptions& options,
             const std::function<std::string(const BatchJob&, JobContext&)>& fn);

} // namespace lut::cli
