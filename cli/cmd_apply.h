#pragma once
#include <functional>
#include <string>
#include <vector>

namespace lut::cli {

struct ApplyOptions {
    std::string lut;                 // LUT file (any readable format)
    std::vector<std::string> inputs; // IN OUT, or with outputDir: files and/or folders
    std::string outputDir;           // -o DIR: batch mode
    std::string interp = "tetrahedral";
    int threads = 0; // 0 = all cores
    bool quiet = false;
};

// Applies the LUT to the stored pixel values (no colour conversion), alpha kept, output bit depth
// = the input's, rounded to nearest -- what Photoshop's Color Lookup does. Batch as below.
int runApply(const ApplyOptions& options);

// ---- Batch helpers shared by apply and preview ----

struct BatchJob {
    std::string input;
    std::string output;
};

// Without outputDir, positionals must be exactly {IN, OUT}. With it, every positional is an input
// file or a folder (its image files, sorted, not recursive) and outputs are DIR/<input name>
// (optionally with the extension replaced by outExtension, e.g. ".png"). Returns false with
// *error set on bad usage.
bool planBatch(const std::vector<std::string>& positionals, const std::string& outputDir,
               const std::string& outExtension, std::vector<BatchJob>& jobs, std::string& error);

// Runs fn for every job on up to `threads` workers (files in parallel; a single file gets all
// threads as innerThreads). fn throws on failure; the batch keeps going, shows a progress bar on a
// terminal (stderr, quiet otherwise), then lists every failure. Returns the exit code (1 if any
// job failed). fn's returned text (may be empty) is printed to stdout after the job, in order of
// completion.
int runBatch(const std::vector<BatchJob>& jobs, int threads, bool quiet,
             const std::function<std::string(const BatchJob&, int innerThreads)>& fn);

} // namespace lut::cli
