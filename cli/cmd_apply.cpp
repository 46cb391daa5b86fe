// lutkit apply: a LUT on the stored pixel values of images (like Photoshop's Color Lookup), and
// the batch runner shared with lutkit preview.
#include "cmd_apply.h"

#include "Commands.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Interpolation.h"
#include "lut/interp/Sampler.h"
#include "lut/io/AtomicFile.h"

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

bool planBatch(const std::vector<std::string>& positionals, const std::string& outputDir,
               const std::string& outExtension, std::vector<BatchJob>& jobs, std::string& error) {
    jobs.clear();
    if (outputDir.empty()) {
        if (positionals.size() != 2) {
            error = positionals.size() < 2 ? "expected IN OUT (or inputs with -o DIR)"
                                           : "several inputs need -o DIR";
            return false;
        }
        jobs.push_back({positionals[0], positionals[1]});
        return true;
    }
    if (positionals.empty()) {
        error = "no input files";
        return false;
    }
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
    return true;
}

int runBatch(const std::vector<BatchJob>& jobs, int threads, bool quiet,
             const std::function<std::string(const BatchJob&, int)>& fn) {
    const int total = static_cast<int>(jobs.size());
    const int workers = std::max(1, std::min(resolveThreads(threads), total));
    const int inner = workers == 1 ? threads : 1;
    const bool bar = !quiet && total > 1 && isatty(STDERR_FILENO);
    std::mutex m;
    std::vector<std::string> failures(jobs.size());
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
        for (int i; (i = next++) < total;) {
            const BatchJob& j = jobs[i];
            std::string text, fail;
            try {
                if (j.output.empty())
                    throw Error(
                        "another input has the same file name (its output would be overwritten)");
                checkNotSameFile(j.input, j.output); // never overwrite an input (issue 7)
                text = fn(j, inner);
            } catch (const std::exception& e) {
                fail = e.what();
            }
            std::lock_guard<std::mutex> lock(m);
            if (!fail.empty())
                failures[i] = fail;
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
            // Library messages usually start with the path already.
            const std::string& msg = failures[i];
            if (msg.rfind(jobs[i].input, 0) == 0)
                std::cerr << "lutkit: error: " << msg << "\n";
            else
                std::cerr << "lutkit: error: " << jobs[i].input << ": " << msg << "\n";
        }
    if (failed > 0 && total > 1)
        std::cerr << "lutkit: " << failed << " of " << total << " file(s) failed\n";
    return failed > 0 ? kExitFailure : kExitOk;
}

int runApply(const ApplyOptions& o) {
    std::vector<BatchJob> jobs;
    std::string error;
    if (!planBatch(o.inputs, o.outputDir, "", jobs, error)) {
        std::cerr << "lutkit apply: " << error << "\n";
        return kExitUsage;
    }
    const Interpolation method = parseInterpolation(o.interp);
    const LutFile file = formats::readLut(o.lut);
    const auto sampler = makeSampler(file.toLut3D(), method);
    return runBatch(jobs, o.threads, o.quiet, [&](const BatchJob& j, int inner) {
        formats::LoadedImage img = formats::readImage(j.input);
        sampler->apply(img.image.view(), inner);
        formats::ImageWriteOptions w;
        w.bitDepth = img.info.isFloat || img.info.bitDepth == 0 ? 32 : img.info.bitDepth;
        w.alpha =
            (img.info.channels == 2 || img.info.channels >= 4) && formats::canHoldAlpha(j.output);
        formats::writeImage(j.output, img.image, w);
        return std::string();
    });
}

} // namespace lut::cli
