// SPDX-License-Identifier: Apache-2.0
// runBatch (Batch.h): files in parallel within a memory budget, a progress bar, a summary.
#include "Batch.h"

#include "Interrupts.h"
#include "OutOfMemory.h"
#include "Usage.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/io/FileNames.h"
#include "lut/io/MemoryLimit.h"
#include "lut/io/TempFiles.h"
#include "lut/os/Console.h"
#include "lut/os/Memory.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <thread>

namespace lut::cli {

namespace {

using Clock = std::chrono::steady_clock;

// A size in the unit that shows it: "800 bytes", "12.5 KiB", "83 MiB", "4.2 GiB" (a limit of
// 1e3 bytes was "0 MiB").
std::string mib(std::uint64_t bytes) {
    char b[48];
    const double v = static_cast<double>(bytes);
    if (bytes < 1024)
        std::snprintf(b, sizeof b, "%llu bytes", static_cast<unsigned long long>(bytes));
    else if (v < 1024.0 * 1024.0)
        std::snprintf(b, sizeof b, "%.1f KiB", v / 1024.0);
    else if (v < 1024.0 * 1024.0 * 1024.0)
        std::snprintf(b, sizeof b, "%.0f MiB", v / (1024.0 * 1024.0));
    else
        std::snprintf(b, sizeof b, "%.1f GiB", v / (1024.0 * 1024.0 * 1024.0));
    return b;
}

std::string clockText(double seconds) {
    const long s = static_cast<long>(seconds + 0.5);
    char b[32];
    if (s >= 3600)
        std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(b, sizeof b, "%ld:%02ld", s / 60, s % 60);
    return b;
}

// The batch's memory budget: jobs wait until what they reserve is free.
class Budget {
public:
    explicit Budget(std::uint64_t total) : m_total(total) {}
    void take(std::uint64_t bytes) {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_cv.wait(lock, [&] { return m_used == 0 || m_used + bytes <= m_total; });
        m_used += bytes;
    }
    void give(std::uint64_t bytes) {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_used -= bytes;
        }
        m_cv.notify_all();
    }
    std::uint64_t total() const { return m_total; }

private:
    std::uint64_t m_total;
    std::uint64_t m_used = 0;
    std::mutex m_mutex;
    std::condition_variable m_cv;
};

class Context : public JobContext {
public:
    Context(Budget& budget, int inner, const std::string& input,
            const std::function<void(const std::string&)>& warn)
        : m_budget(budget), m_inner(inner), m_input(input), m_warn(warn) {}
    ~Context() override {
        if (m_held)
            m_budget.give(m_held);
    }
    void reserveMemory(std::uint64_t bytes, const std::string& what) override {
        if (m_held + bytes > m_budget.total())
            throw Error(m_input + ": " + what + " needs " + mib(m_held + bytes) +
                        ", over the memory limit of " + mib(m_budget.total()) + " (--max-memory)");
        m_budget.take(bytes);
        m_held += bytes;
    }
    int innerThreads() const override { return m_inner; }
    void warn(const std::string& text) override { m_warn(text); }

private:
    Budget& m_budget;
    int m_inner;
    const std::string& m_input;
    const std::function<void(const std::string&)>& m_warn;
    std::uint64_t m_held = 0;
};

} // namespace

std::uint64_t defaultMaxMemory() {
    return defaultMemoryLimit();
}

std::uint64_t parseMemorySize(const std::string& text) {
    const std::string expected =
        "bad memory size '" + text + "' (expected a number with K, M, G or T: 4G; B for bytes)";
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        throw UsageError(expected);
    }
    std::string unit = text.substr(used);
    for (auto& c : unit)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (!unit.empty() && unit.back() == 'B')
        unit.pop_back();
    if (!unit.empty() && unit.back() == 'I')
        unit.pop_back();
    double scale = 1.0;
    if (unit == "K")
        scale = 1024.0;
    else if (unit == "M")
        scale = 1024.0 * 1024.0;
    else if (unit == "G")
        scale = 1024.0 * 1024.0 * 1024.0;
    else if (unit == "T")
        scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
    else if (!unit.empty())
        throw UsageError(expected);
    if (!(v > 0.0) || !std::isfinite(v))
        throw UsageError(expected);
    const double bytes = v * scale;
    // Bad usage, not a failed run: a limit no picture fits in (--max-memory 1e3 was 1000 bytes,
    // then "needs 0 MiB, over the limit of 0 MiB"), and one past any machine's (exit 1 before).
    if (bytes < 1024.0 * 1024.0)
        throw UsageError(text + " is " + mib(static_cast<std::uint64_t>(bytes)) +
                         ", less than any picture needs" +
                         (unit.empty() && text.back() != 'B' && text.back() != 'b'
                              ? ": give a unit (" + text + "M, " + text + "G)"
                              : std::string(" (at least 1M)")));
    if (bytes > 1e18)
        throw UsageError(text + " is more than any machine has (at most 1e18 bytes; the default "
                                "is half the RAM)");
    return static_cast<std::uint64_t>(bytes);
}

int runBatch(const BatchPlan& plan, const BatchOptions& options,
             const std::function<std::string(const BatchJob&, JobContext&)>& fn) {
    const auto& jobs = plan.jobs;
    const int total = static_cast<int>(jobs.size());
    for (const auto& n : plan.notes)
        std::cerr << "lutkit: warning: " << printable(n) << "\n";
    const int workers = std::max(1, std::min(resolveThreads(options.threads), total));
    const int inner = workers == 1 ? options.threads : 1;
    const bool bar = !options.quiet && total > 1 && os::terminalTakesEscapes(2);
    Budget budget(options.maxMemory ? options.maxMemory : defaultMaxMemory());
    std::mutex m;
    std::vector<std::string> failures(jobs.size());
    std::vector<char> finished(jobs.size(), 0);
    // Ctrl-C: temporary files go at once, jobs in flight stop at their next write, no new job
    // starts, and what was finished is listed below (Interrupts.h).
    const CooperativeInterrupts cooperative;
    std::atomic<int> next{0};
    int done = 0, skipped = 0, written = 0;
    std::string current;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    auto drawBar = [&] {
        const int width = 24, filled = total ? done * width / total : width;
        const double t = elapsed();
        std::string eta = "--:--";
        if (done > 0 && done < total)
            eta = clockText(t / done * (total - done));
        else if (done == total)
            eta = "0:00";
        std::string name = current;
        if (name.size() > 40)
            name = "..." + name.substr(name.size() - 37);
        std::fprintf(stderr, "\r\033[K[%s%s] %d/%d %s, ETA %s  %s",
                     std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
                     done, total, clockText(t).c_str(), eta.c_str(), name.c_str());
        std::fflush(stderr);
    };
    // Lines for standard error while jobs run: on the bar's line, cleared first, the bar drawn
    // again below them.
    const std::function<void(const std::string&)> warn = [&](const std::string& text) {
        if (text.empty())
            return;
        std::lock_guard<std::mutex> lock(m);
        std::cout.flush();
        if (bar)
            std::fprintf(stderr, "\r\033[K");
        std::fputs(text.c_str(), stderr);
        if (text.back() != '\n')
            std::fputc('\n', stderr);
        if (bar)
            drawBar();
        std::fflush(stderr);
    };
    auto work = [&] {
        for (int i; !lut::interrupted() && (i = next++) < total;) {
            const BatchJob& j = jobs[static_cast<std::size_t>(i)];
            if (bar) {
                std::lock_guard<std::mutex> lock(m);
                current = j.input;
                drawBar();
            }
            std::string text, fail;
            bool skip = j.skip, stopped = false;
            if (!skip) {
                try {
                    if (!j.refused.empty())
                        throw Error(j.refused);
                    Context ctx(budget, inner, j.input, warn);
                    text = fn(j, ctx);
                } catch (const InterruptedError&) {
                    stopped = true;
                } catch (const std::bad_alloc&) {
                    fail = outOfMemoryText();
                } catch (const std::exception& e) {
                    fail = e.what();
                    if (fail.empty())
                        fail = "failed";
                }
            }
            // A job that failed once the program was interrupted most likely failed because of
            // it (its temporary file was removed under it): it is among the unfinished.
            stopped = stopped || (!fail.empty() && lut::interrupted());
            std::lock_guard<std::mutex> lock(m);
            if (stopped) {
                // not finished, not a failure: listed by the interrupt summary below
            } else if (!fail.empty())
                failures[static_cast<std::size_t>(i)] = fail;
            else if (skip)
                ++skipped;
            else {
                ++written;
                finished[static_cast<std::size_t>(i)] = 1;
            }
            if (!text.empty()) {
                if (bar)
                    std::fprintf(stderr, "\r\033[K");
                std::cout << text << std::flush;
            }
            ++done;
            if (bar)
                drawBar();
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
    if (options.afterJobs && !lut::interrupted())
        options.afterJobs();
    int failed = 0;
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (!failures[i].empty()) {
            ++failed;
            // Library messages usually start with the path already (the input's or the
            // output's).
            const std::string& msg = failures[i];
            if (msg.rfind(jobs[i].input, 0) == 0 ||
                (!jobs[i].output.empty() && msg.rfind(jobs[i].output, 0) == 0))
                std::cerr << "lutkit: error: " << printable(msg) << "\n";
            else
                std::cerr << "lutkit: error: " << printable(jobs[i].input + ": " + msg) << "\n";
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
    if (total > 1 && (!options.quiet || failed > 0)) {
        const double t = elapsed();
        char rate[64];
        std::snprintf(rate, sizeof rate, "%.3g", t > 0 ? written / t : 0.0);
        std::cerr << "lutkit: " << written << " of " << total << " " << options.unit
                  << " written in " << clockText(t) << " (" << rate << " " << options.unit << "/s)";
        if (skipped)
            std::cerr << ", " << skipped << " skipped (exist)";
        std::cerr << ", " << failed << " failed\n";
    } else if (skipped && !options.quiet) {
        std::cerr << "lutkit: " << printable(jobs.front().output) << " exists; skipped (-n)\n";
    }
    return failed > 0 ? kExitFailure : kExitOk;
}

} // namespace lut::cli
