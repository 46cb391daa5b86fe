// SPDX-License-Identifier: Apache-2.0
// Google Benchmark: .cube parsing and writing for 17, 33, 65 (and, with LUTKIT_BENCH_CUBE_MAX=256,
// 129 and 256) point cubes, next to OpenColorIO reading the same file (FileTransform +
// getProcessor, its caches cleared each time) in the same run. Counters: MB_per_s and
// ns_per_row. Run: build/bin/lutkit_bench --benchmark_filter=Cube
#include "lut/formats/Cube.h"

#include <OpenColorIO/OpenColorIO.h>
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;

namespace {

struct CubeFixture {
    LutFile lut;
    std::string text;
    std::string path;
};

// A random LUT (values a little outside 0..1, as graded LUTs have) written once per size to a
// temporary file; the same bytes feed every reader.
const CubeFixture& fixture(int size) {
    static std::map<int, CubeFixture> cache;
    auto it = cache.find(size);
    if (it != cache.end())
        return it->second;
    CubeFixture f;
    Lut3D l(size);
    std::mt19937 rng(static_cast<unsigned>(size));
    std::uniform_real_distribution<float> u(-0.05f, 1.05f);
    for (auto& v : l.entries())
        v = glm::vec3(u(rng), u(rng), u(rng));
    l.setTitle("bench");
    f.lut.cube = std::move(l);
    f.text = formats::writeCubeString(f.lut);
    f.path = (std::filesystem::temp_directory_path() /
              ("lutkit_bench_" + std::to_string(size) + ".cube"))
                 .string();
    formats::writeCube(f.path, f.lut);
    return cache.emplace(size, std::move(f)).first->second;
}

void counters(benchmark::State& state, const CubeFixture& f) {
    const double rows = static_cast<double>(f.lut.cube->entryCount());
    state.counters["MB_per_s"] = benchmark::Counter(static_cast<double>(f.text.size()) / 1e6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
    state.counters["ns_per_row"] = benchmark::Counter(
        rows * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_CubeParseMemory(benchmark::State& state) {
    const CubeFixture& f = fixture(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        LutFile r = formats::parseCube(f.text, f.path);
        benchmark::DoNotOptimize(r.cube->data());
    }
    counters(state, f);
}

void BM_CubeReadFile(benchmark::State& state) {
    const CubeFixture& f = fixture(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        LutFile r = formats::readCube(f.path);
        benchmark::DoNotOptimize(r.cube->data());
    }
    counters(state, f);
}

void BM_CubeWriteString(benchmark::State& state) {
    const CubeFixture& f = fixture(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        std::string s = formats::writeCubeString(f.lut);
        benchmark::DoNotOptimize(s.data());
    }
    counters(state, f);
}

void BM_CubeWriteFile(benchmark::State& state) {
    const CubeFixture& f = fixture(static_cast<int>(state.range(0)));
    const std::string out = f.path + ".out.cube";
    for (auto _ : state)
        formats::writeCube(out, f.lut);
    std::filesystem::remove(out);
    counters(state, f);
}

// OpenColorIO's reader on the same file: what a user of OCIO pays to load it.
void BM_OcioCubeRead(benchmark::State& state) {
    const CubeFixture& f = fixture(static_cast<int>(state.range(0)));
    // Without the file and processor caches, every iteration really reads and parses the file.
    OCIO::ConfigRcPtr config = OCIO::Config::CreateRaw()->createEditableCopy();
    config->setProcessorCacheFlags(OCIO::PROCESSOR_CACHE_OFF);
    for (auto _ : state) {
        OCIO::ClearAllCaches();
        OCIO::FileTransformRcPtr ft = OCIO::FileTransform::Create();
        ft->setSrc(f.path.c_str());
        ft->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
        OCIO::ConstProcessorRcPtr proc = config->getProcessor(ft);
        benchmark::DoNotOptimize(proc.get());
    }
    counters(state, f);
}

void sizes(benchmark::internal::Benchmark* b, bool ocio) {
    const char* env = std::getenv("LUTKIT_BENCH_CUBE_MAX");
    const int max = env ? std::atoi(env) : 65;
    for (int n : {17, 33, 65, 129, 256})
        if (n <= max && !(ocio && n > 129))
            b->Arg(n); // OCIO refuses 3D sizes above 129
    // Wall time: the writer formats on all cores, and wall time is what a user waits for.
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(BM_CubeParseMemory)->Apply([](auto* b) { sizes(b, false); });
BENCHMARK(BM_CubeReadFile)->Apply([](auto* b) { sizes(b, false); });
BENCHMARK(BM_OcioCubeRead)->Apply([](auto* b) { sizes(b, true); });
BENCHMARK(BM_CubeWriteString)->Apply([](auto* b) { sizes(b, false); });
BENCHMARK(BM_CubeWriteFile)->Apply([](auto* b) { sizes(b, false); });

} // namespace
