// SPDX-License-Identifier: Apache-2.0
// The preview pipeline on a 1920x1080 float frame: the full smash chain (target < 30 ms per frame
// on two cores so the editor previews at 30 fps), each smash stage alone, and the other presets.
// Run: build/bin/lutkit_bench --benchmark_filter=Pipeline
#include "lut/Image.h"
#include "lut/bench/SmashChainBench.h"
#include "lut/pipeline/Pipeline.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>

namespace {

int envInt(const char* name, int def) {
    const char* v = std::getenv(name);
    return v ? std::atoi(v) : def;
}

lut::Image benchScene() {
    return lut::makeSmashBenchScene(envInt("LUTKIT_BENCH_WIDTH", 1920),
                                    envInt("LUTKIT_BENCH_HEIGHT", 1080));
}

// Every smash benchmark grades with the same non-identity 16^3 LUT as `lutkit bench`.
void runPipeline(benchmark::State& state, lut::Pipeline& p) {
    p.setLut(std::make_shared<const lut::Lut3D>(lut::makeSmashBenchLut()));
    const lut::Image scene = benchScene();
    lut::Image work = scene;
    lut::RunOptions o;
    o.nthreads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        state.PauseTiming();
        work.pixels() = scene.pixels();
        state.ResumeTiming();
        p.run(work.view(), o);
        benchmark::DoNotOptimize(work.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.width()) *
                            scene.height());
}

void BM_PipelineSmash(benchmark::State& state) {
    lut::Pipeline p(lut::Preset::Smash);
    runPipeline(state, p);
}

void BM_PipelineSmashNoBloom(benchmark::State& state) {
    lut::Pipeline p(lut::Preset::Smash);
    p.setBloom(false);
    runPipeline(state, p);
}

void BM_PipelineSmashStage(benchmark::State& state, const char* stage) {
    lut::Pipeline p(lut::Preset::None);
    p.setEnabled("display", false);
    p.setEnabled(stage, true);
    runPipeline(state, p);
}

void BM_PipelinePreset(benchmark::State& state, lut::Preset preset) {
    lut::Pipeline p(preset);
    runPipeline(state, p);
}

} // namespace

BENCHMARK(BM_PipelineSmash)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PipelineSmashNoBloom)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_PipelineSmashStage, bloom, "smash-bloom")
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PipelineSmashStage, grade, "smash-grade")
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PipelinePreset, pilot, lut::Preset::Pilot)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PipelinePreset, lecture, lut::Preset::Lecture)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
