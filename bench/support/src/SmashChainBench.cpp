// SPDX-License-Identifier: Apache-2.0
#include "lut/bench/SmashChainBench.h"

#include "lut/Error.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/smash/SmashConstants.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

namespace lut {

Image makeSmashBenchScene(int width, int height) {
    Image scene(width, height, 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = scene.pixel(x, y);
            const float u = (x + 0.5f) / width, v = (y + 0.5f) / height;
            p[0] = 0.6f * u * u;
            p[1] = 0.5f * v;
            p[2] = 0.25f + 0.2f * u * v;
            if (((x / 64) + (y / 64)) % 7 == 0)
                p[0] = p[1] = p[2] = 3.0f + 10.0f * u;
            p[3] = y < height / 10 ? 0.0f : 1.0f;
        }
    return scene;
}

Lut3D makeSmashBenchLut() {
    Lut3D lut = Lut3D::identity(kSmashLutSize);
    const int n = lut.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 v = lut.at(r, g, b);
                const float luma = 0.2126f * v.x + 0.7152f * v.y + 0.0722f * v.z;
                glm::vec3 o = v * 0.8f + glm::vec3(luma) * 0.2f; // desaturate a little
                o = o * o * (3.0f - 2.0f * o);                   // S-curve
                o *= glm::vec3(1.05f, 1.0f, 0.9f);               // warm
                lut.at(r, g, b) = glm::clamp(o, glm::vec3(0.0f), glm::vec3(1.0f));
            }
    return lut;
}

SmashChainTiming benchmarkSmashChain(int width, int height, int iterations, int nthreads) {
    using Clock = std::chrono::steady_clock;
    if (width <= 0 || height <= 0)
        throw Error("benchmark frame size must be positive");
    iterations = std::max(1, iterations);
    const Image scene = makeSmashBenchScene(width, height);
    Pipeline pipeline(Preset::Smash);
    pipeline.setLut(std::make_shared<const Lut3D>(makeSmashBenchLut()));
    RunOptions opt;
    opt.nthreads = nthreads;
    Image work = scene;
    pipeline.run(work.view(), opt); // warm-up: allocations, first touch
    std::vector<double> ms;
    for (int i = 0; i < iterations; ++i) {
        work.pixels() = scene.pixels();
        const auto t0 = Clock::now();
        pipeline.run(work.view(), opt);
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    SmashChainTiming t;
    t.runs = iterations;
    t.bestMs = ms.front();
    t.worstMs = ms.back();
    t.medianMs =
        ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
    return t;
}

} // namespace lut
