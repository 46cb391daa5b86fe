// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the smash-chain benchmarks run (`lutkit bench`'s "smash chain" row and bench/lutkit_bench's
// Pipeline benchmarks): a synthetic HDR scene, a non-identity grading LUT, and the timing of the
// full smash preview chain on them.
#include "lut/Image.h"
#include "lut/Lut3D.h"

namespace lut {

// The synthetic HDR scene: smooth gradients, highlights well above the bloom threshold, an
// alpha-0 band (background) along the top tenth.
Image makeSmashBenchScene(int width, int height);

// A 16^3 grading LUT that is not an identity (warm tint, contrast, cross-talk between channels),
// so no identity shortcut can flatter the benchmarks.
Lut3D makeSmashBenchLut();

struct SmashChainTiming {
    double medianMs = 0.0; // the typical frame: what the editor's frame rate follows
    double bestMs = 0.0;
    double worstMs = 0.0;
    int runs = 0;
};
// Times the full smash chain (Preset::Smash with makeSmashBenchLut, bloom on, sRGB display) on
// the synthetic w x h HDR frame, `iterations` runs after one warm-up. Throws lut::Error for a
// frame size that is not positive.
SmashChainTiming benchmarkSmashChain(int width = 1920, int height = 1080, int iterations = 10,
                                     int nthreads = 0);

} // namespace lut
