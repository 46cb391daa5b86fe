// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the plain-data view of a sampler's table that the SIMD kernels read.
//
// Deliberately free of glm and of the standard library's inline templates: the *_avx2.cpp files
// that include it are compiled with -mavx2 -mfma, and any inline function they instantiated
// could be the copy the linker keeps for the whole program, which would then fault on a CPU
// without AVX2. The kernels are chosen at run time (see Sampler.cpp).
#include "interp/LatticeMapping.h"

#include <cstddef>

namespace lut::detail {

struct KernelTable {
    // N^3 entries of 4 floats each (R, G, B, unused 0), red fastest as in Lut3D. The padding makes
    // every entry one aligned 16-byte load that never straddles a cache line.
    const float* rgb = nullptr;
    LatticeMapping map; // input -> cell + fraction (interp/LatticeMapping.h)
};

using KernelFn = void (*)(const KernelTable&, float* rgba, std::size_t count);

// A 1D shaper (lut::Lut1D) as its kernel reads it: per channel, t from the same lattice mapping
// as a 3D table's axis (LatticeMapping with N = the shaper's entry count), then
// (1 - f) * entry[cell] + f * entry[cell + 1] -- exact at the entries, clamped to the end
// entries outside the domain, NaN taken as the domain's minimum.
struct ShaperTable {
    const float* planes = nullptr; // 3 planes of N floats: the R entries, then G, then B
    LatticeMapping map;
};

using ShaperFn = void (*)(const ShaperTable&, float* rgba, std::size_t count);

// AVX2 + FMA kernels (simd/SamplerKernels_avx2.cpp). Only call when the CPU has AVX2 and FMA.
void nearestAvx2(const KernelTable& table, float* rgba, std::size_t count);
void trilinearAvx2(const KernelTable& table, float* rgba, std::size_t count);
void tetrahedralAvx2(const KernelTable& table, float* rgba, std::size_t count);
void shaperAvx2(const ShaperTable& table, float* rgba, std::size_t count);

// The AVX2 kernels' arithmetic one pixel at a time in portable C++ (interp/PortableKernels.cpp),
// with fused multiply-adds where they have them: the same bits on any machine, where no SIMD
// kernel runs (the browser edition, a CPU without AVX2). Nearest needs none: its scalar loop
// already picks the kernel's entry.
void trilinearPortable(const KernelTable& table, float* rgba, std::size_t count);
void tetrahedralPortable(const KernelTable& table, float* rgba, std::size_t count);
// The same two in WebAssembly SIMD (simd/SamplerKernels_wasm.cpp, the browser edition only): the
// portable kernels' bits, three channels at once.
void trilinearWasm(const KernelTable& table, float* rgba, std::size_t count);
void tetrahedralWasm(const KernelTable& table, float* rgba, std::size_t count);
// AVX-512 F + DQ (simd/SamplerKernels_avx512.cpp): bit-identical to its AVX2 twin, 16 pixels per
// iteration. Only call when the CPU has AVX-512 F and DQ (and AVX2 + FMA).
void tetrahedralAvx512(const KernelTable& table, float* rgba, std::size_t count);

} // namespace lut::detail
