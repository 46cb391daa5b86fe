#pragma once
// Internal to lutlib: the plain-data view of a sampler's table that the SIMD kernels read.
//
// Deliberately free of glm and of the standard library's inline templates: the *_avx2.cpp files
// that include it are compiled with -mavx2 -mfma, and any inline function they instantiated
// could be the copy the linker keeps for the whole program, which would then fault on a CPU
// without AVX2. The kernels are chosen at run time (see Sampler.cpp).
#include <cstddef>

namespace lut::detail {

struct KernelTable {
    // N^3 entries of 4 floats each (R, G, B, unused 0), red fastest as in Lut3D. The padding makes
    // every entry one aligned 16-byte load that never straddles a cache line.
    const float* rgb = nullptr;
    int size = 0;           // N
    float scale[3] = {};    // (N-1) / (max - min), kept finite
    float offset[3] = {};   // domain min
    float snapBias[3] = {}; // |min| * scale: the domain's share of the lattice snapping tolerance
};

// Inputs whose lattice coordinate t is within (t + snapBias) * kSnapRelative of an integer are
// moved onto it: that bound covers the float rounding of a lattice input and of (x - min) * scale,
// so lattice points given as floats return their entries exactly.
constexpr float kSnapRelative = 1.0f / 4194304.0f; // 2^-22

using KernelFn = void (*)(const KernelTable&, float* rgba, std::size_t count);

// AVX2 + FMA kernels (simd/SamplerKernels_avx2.cpp). Only call when the CPU has AVX2 and FMA.
void nearestAvx2(const KernelTable& table, float* rgba, std::size_t count);
void trilinearAvx2(const KernelTable& table, float* rgba, std::size_t count);
void tetrahedralAvx2(const KernelTable& table, float* rgba, std::size_t count);

} // namespace lut::detail
