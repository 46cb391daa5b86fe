#include "Batch.h"

#include "Interrupts.h"
#include "OutOfMemory.h"
#include "Usage.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/formats/ImageFiles.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/TempFiles.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <set>
#include <thread>
#include <unistd.h>

namespace lut::cli {

namespace fs = std::filesystem;

std::vector<BatchJob> planBatch(const std::vector<std::string>& positionals,
                                const std::string& outputDir, const std::string& outExtension) {
    std::vector<BatchJob> jobs;
    if (outputDir.empty()) {
        if (positionals.size() != 2)
            throw UsageError(positionals.size() < 2 ? "expected IN OUT (or inputs with -o DIR)"
                                                    : "several inputs need -o DIR");
        jobs.push_back({positionals[0], positionals[1]});
        return jobs;
    }
    if (positionals.empty())
        throw UsageError("no input files");
    std::set<std::string> names;
    for (const auto& in : positionals) {
        std::vector<fs::path> files;
        std::error_code ec;
        if (fs::is_directory(in, ec)) {
            for (const auto& e : fs::directory_iterator(in, ec))
                if (e.is_regular_file(ec) && formats::isImageExtension(e.path().string()))
                    files.push_back(e.path());
            std::sort(files.begin(), files.end());
        } else {
            files.push_back(in); // a missing file becomes a failed job, reported at the end
        }
        for (const auto& f : files) {
            fs::path name = f.filename();
            if (!outExtension.empty())
                name.replace_extension(outExtension);
            BatchJob j{f.string(), (fs::path(outputDir) / name).string()};
            if (!names.insert(j.output).second)
                j.output.clear(); // collision: reported as a failure
            jobs.push_back(std::move(j));
        }
    }
    return jobs;
}

int runBatch(const std::vector<BatchJob>& jobs, int threads, bool quiet,
             const std::function<std::string(const BatchJob&, int)>& fn) {
    const int total = static_cast<int>(jobs.size());
    const int workers = std::max(1, std::min(resolveThreads(threads), total));
    const int inner = workers == 1 ? threads : 1;
    const bool bar = !quiet && total > 1 && isatty(STDERR_FILENO);
    // Ctrl-C: temporary files go at once, jobs in flight stop at their next write, no new job
    // starts, and what was finished is listed below (Interrupts.h).
    const CooperativeInterrupts cooperative;
    std::mutex m;
    std::vector<std::string> failures(jobs.size());
    std::vector<char> finished(jobs.size(), 0);
    std::atomic<int> next{0}, done{0};
    for (const auto& j : jobs)
        if (!j.output.empty()) {
            std::error_code ec;
            const fs::path dir = fs::path(j.output).parent_path();
            if (!dir.empty())
                fs::create_directories(dir, ec);
        }
    auto drawBar = [&](int d) {
        const int width = 30, filled = total ? d * width / total : width;
        std::fprintf(stderr, "\r[%s%s] %d/%d", std::string(filled, '#').c_str(),
                     std::string(width - filled, '.').c_str(), d, total);
        std::fflush(stderr);
    };
    auto work = [&] {
        for (int i; !lut::interrupted() && (i = next++) < total;) {
            const BatchJob& j = jobs[i];
            std::string text, fail;
            bool stopped = false;
            try {
                if (j.output.empty())
                    throw Error(
                        "another input has the same file name (its output would be overwritten)");
                checkNotSameFile(j.input, j.output); // never overwrite an input (issue 7)
                text = fn(j, inner);
            } catch (const InterruptedError&) {
                stopped = true;
            } catch (const std::bad_alloc&) {
                fail = outOfMemoryText();
            } catch (const std::exception& e) {
                fail = e.what();
            }
            // A job that failed once the program was interrupted most likely failed because of
            // it (its temporary file was removed under it): it is among the unfinished.
            stopped = stopped || (!fail.empty() && lut::interrupted());
            std::lock_guard<std::mutex> lock(m);
            if (!fail.empty() && !stopped)
                failures[i] = fail;
            else if (!stopped)
                finished[static_cast<std::size_t>(i)] = 1;
            if (!text.empty()) {
                if (bar)
                    std::fprintf(stderr, "\r\033[K");
                std::cout << text << std::flush;
            }
            const int d = ++done;
            if (bar)
                drawBar(d);
        }
    };
    std::vector<std::thread> pool;
    for (int w = 1; w < workers; ++w)
        pool.emplace_back(work);
    work();
    for (auto& t : pool)
        t.join();
    if (bar)
        std::fprintf(stderr, "\r\033[K");
    int failed = 0;
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (!failures[i].empty()) {
            ++failed;
            // Library messages usually start with the path already (the input's or the
            // output's).
            const std::string& msg = failures[i];
            if (msg.rfind(jobs[i].input, 0) == 0 ||
                (!jobs[i].output.empty() && msg.rfind(jobs[i].output, 0) == 0))
                std::cerr << "lutkit: error: " << msg << "\n";
            else
                std::cerr << "lutkit: error: " << jobs[i].input << ": " << msg << "\n";
        }
    if (lut::interrupted()) {
        // One line: what is complete on the disk; everything else was not written (or removed).
        std::string list;
        int count = 0;
        for (std::size_t i = 0; i < jobs.size(); ++i)
            if (finished[i]) {
                ++count;
                list += (list.empty() ? "" : ", ") + jobs[i].output;
            }
        std::cerr << "lutkit: interrupted (" << signalName(lut::interruptSignal()) << "): " << count
                  << " of " << total << " file(s) finished" << (count ? " (" + list + ")" : "")
                  << "; nothing else was written\n";
        return kExitInterrupted;
    }
    if (failed > 0 && total > 1)
        std::cerr << "lutkit: " << failed << " of " << total << " file(s) failed\n";
    return failed > 0 ? kExitFailure : kExitOk;
}

} // namespace lut::cli
