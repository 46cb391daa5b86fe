#pragma once
// The batch runner shared by lutkit apply and lutkit preview: which files to write where, and
// running a job per file on all cores with a progress bar, going on past failures.
#include <functional>
#include <string>
#include <vector>

namespace lut::cli {

struct BatchJob {
    std::string input;
    std::string output; // "" = refused at planning (reported as this job's failure)
};

// Without outputDir, positionals must be exactly {IN, OUT}. With it, every positional is an input
// file or a folder (its image files, sorted, not recursive) and outputs are DIR/<input name>
// (optionally with the extension replaced by outExtension, e.g. ".png"). Throws UsageError.
std::vector<BatchJob> planBatch(const std::vector<std::string>& positionals,
                                const std::string& outputDir, const std::string& outExtension = {});

// Runs fn for every job on up to `threads` workers (files in parallel; a single file gets all
// threads as innerThreads). fn throws on failure; the batch keeps going, shows a progress bar on a
// terminal (stderr; not when quiet), then lists every failure. Returns the exit code (1 if any
// job failed). fn's returned text (may be empty) is printed to stdout after the job, in order of
// completion. No job writes over its own input.
int runBatch(const std::vector<BatchJob>& jobs, int threads, bool quiet,
             const std::function<std::string(const BatchJob&, int innerThreads)>& fn);

} // namespace lut::cli
