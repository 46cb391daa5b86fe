// SPDX-License-Identifier: Apache-2.0
// Google Benchmark: the LUT kernels on a 4K float RGBA frame, for every interpolation and LUT
// size 16, 17, 33, 65, next to OpenColorIO's CPU processor on the same LUT and pixels and a
// plain copy of the same bytes. Counters: ns_per_pixel, and for our kernels max_err / mean_err
// against the analytic grade the LUT was sampled from (lut/bench/KernelBench.h in bench/support,
// shared with `lutkit bench`). Frame size: LUTKIT_BENCH_WIDTH / LUTKIT_BENCH_HEIGHT (default
// 3840x2160).
#include "lut/bench/KernelBench.h"
#include "lut/bench/OcioLutProcessor.h"
#include "lut/interp/Sampler.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <memory>

using namespace lut;

namespace {

int envInt(const char* name, int fallback) {
    const char* v = std::getenv(name);
    return v && std::atoi(v) > 0 ? std::atoi(v) : fallback;
}

struct Frames {
    Image frame, reference, work;
    Frames() {
        const int w = envInt("LUTKIT_BENCH_WIDTH", 3840), h = envInt("LUTKIT_BENCH_HEIGHT", 2160);
        frame = makeBenchFrame(w, h);
        reference = analyticReference(frame);
        work = Image(w, h);
    }
    double pixels() const { return static_cast<double>(frame.width()) * frame.height(); }
};

Frames& frames() {
    static Frames f; // built on first use: listing benchmarks stays instant
    return f;
}

const Lut3D& gradeLut(int size) {
    static std::map<int, Lut3D> cache;
    auto it = cache.find(size);
    if (it == cache.end())
        it = cache.emplace(size, sampleAnalyticGrade(size)).first;
    return it->second;
}

Interpolation methodArg(std::int64_t v) {
    return static_cast<Interpolation>(v);
}

// Times apply() on a fresh copy of the frame each iteration (the copy is not timed).
void runSampler(benchmark::State& state, bool scalar) {
    Frames& f = frames();
    const Interpolation method = methodArg(state.range(0));
    const int size = static_cast<int>(state.range(1));
    if (scalar)
        ::setenv("LUTKIT_SIMD", "scalar", 1);
    const auto sampler = makeSampler(gradeLut(size), method);
    if (scalar)
        ::unsetenv("LUTKIT_SIMD");
    for (auto _ : state) {
        state.PauseTiming();
        parallelCopy(f.frame, f.work);
        state.ResumeTiming();
        sampler->apply(f.work.view());
        benchmark::ClobberMemory();
    }
    const ErrorStats e = frameError(f.work, f.reference);
    state.counters["ns_per_pixel"] =
        benchmark::Counter(f.pixels() * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                  benchmark::Counter::kInvert);
    state.counters["max_err"] = e.maxAbs;
    state.counters["mean_err"] = e.meanAbs;
    state.SetLabel(std::string(toString(method)) + " " + std::to_string(size) + "^3 " +
                   (scalar ? "scalar" : samplerIsa()));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(f.pixels()) * 16);
}

void BM_Lut(benchmark::State& state) {
    runSampler(state, false);
}
void BM_LutScalar(benchmark::State& state) {
    runSampler(state, true);
}

// OpenColorIO's CPU processor, called as ocioconvert calls it: one apply() over the frame.
void BM_Ocio(benchmark::State& state) {
    Frames& f = frames();
    const Interpolation method = methodArg(state.range(0));
    const int size = static_cast<int>(state.range(1));
    const Lut3D& lut = gradeLut(size);
    const OcioLutProcessor ocio(lut, method);
    for (auto _ : state) {
        state.PauseTiming();
        parallelCopy(f.frame, f.work);
        state.ResumeTiming();
        ocio.apply(f.work);
        benchmark::ClobberMemory();
    }
    const ErrorStats e = frameError(f.work, f.reference);
    state.counters["ns_per_pixel"] =
        benchmark::Counter(f.pixels() * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                  benchmark::Counter::kInvert);
    state.counters["max_err"] = e.maxAbs;
    state.counters["mean_err"] = e.meanAbs;
    state.SetLabel(std::string("OCIO ") + toString(method) + " " + std::to_string(size) + "^3");
}

// The memory-bandwidth yardstick: a copy of the same bytes on all threads.
void BM_Memcpy(benchmark::State& state) {
    Frames& f = frames();
    for (auto _ : state) {
        parallelCopy(f.frame, f.work);
        benchmark::ClobberMemory();
    }
    state.counters["ns_per_pixel"] =
        benchmark::Counter(f.pixels() * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                  benchmark::Counter::kInvert);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(f.pixels()) * 16);
}

void lutArgs(benchmark::internal::Benchmark* b, bool withNearest) {
    for (int m = withNearest ? 0 : 1; m < 3; ++m)
        for (int size : {16, 17, 33, 65})
            b->Args({m, size});
    b->ArgNames({"interp", "size"})->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace

BENCHMARK(BM_Memcpy)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Lut)->Apply([](benchmark::internal::Benchmark* b) { lutArgs(b, true); });
BENCHMARK(BM_Ocio)->Apply([](benchmark::internal::Benchmark* b) { lutArgs(b, false); });
BENCHMARK(BM_LutScalar)
    ->Args({2, 33})
    ->ArgNames({"interp", "size"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
