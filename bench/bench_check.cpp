// SPDX-License-Identifier: Apache-2.0
// Google Benchmark: lut::checkLut on 17, 33 and 65 point LUTs (a smooth grade: a per-channel
// S-curve with lifted blacks, 10% less saturation and a warm tint, as tests/ops' filmic grade),
// on all cores and on one, with and without the distance from neutral (ΔE2000 over the lattice,
// the slowest part); and the report picture. The goal (issue 24): a 65^3 check under 1 s.
// Run: build/bin/lutkit_bench --benchmark_filter=Check
#include "lut/check/CheckLut.h"
#include "lut/check/CheckPicture.h"

#include <benchmark/benchmark.h>
#include <glm/common.hpp>

#include <algorithm>
#include <map>

using namespace lut;

namespace {

const Lut3D& grade(int n) {
    static std::map<int, Lut3D> cache;
    if (auto it = cache.find(n); it != cache.end())
        return it->second;
    Lut3D l(n);
    auto curve = [](float x) { return 0.02f + 0.95f * (x + 0.35f * x * (1 - x) * (2 * x - 1)); };
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 x = l.latticeInput(r, g, b);
                const glm::vec3 c(curve(x.r), curve(x.g), curve(x.b));
                const float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
                const glm::vec3 tint(1.01f, 1.0f, 0.98f);
                l.at(r, g, b) =
                    glm::clamp((glm::vec3(luma) + 0.9f * (c - luma)) * tint, 0.0f, 1.0f);
            }
    return cache.emplace(n, std::move(l)).first->second;
}

// Args: size, threads (0 = all cores), measure the distance from neutral (0/1).
void BM_CheckLut(benchmark::State& state) {
    const Lut3D& lut = grade(static_cast<int>(state.range(0)));
    CheckOptions o;
    o.nthreads = static_cast<int>(state.range(1));
    o.measureNeutral = state.range(2) != 0;
    for (auto _ : state) {
        CheckReport r = checkLut(lut, o);
        benchmark::DoNotOptimize(r);
    }
    state.counters["entries"] = static_cast<double>(lut.entryCount());
}
BENCHMARK(BM_CheckLut)
    ->ArgsProduct({{17, 33, 65}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_CheckPicture(benchmark::State& state) {
    LutFile file;
    file.cube = grade(static_cast<int>(state.range(0)));
    const CheckReport report = checkLut(*file.cube);
    for (auto _ : state) {
        CheckPicture p = drawCheckReport(file, report, "bench");
        benchmark::DoNotOptimize(p);
    }
}
BENCHMARK(BM_CheckPicture)->Arg(33)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
