// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>

namespace lut {

struct LutFile;

// Evaluates a Lut3D at arbitrary inputs. One class per interpolation method, chosen once per LUT
// by makeSampler(); the sampler keeps its own copy of the table in whatever layout its kernel
// wants, so the Lut3D may change or die afterwards.
//
// Extreme-input policy (the same for every method, tested in tests/lutlib/test_sampler_extremes):
//  - An input is mapped to lattice coordinates (x - domainMin) / (domainMax - domainMin) * (N-1)
//    and clamped to [0, N-1] per channel: inputs outside the domain take the edge value
//    (clamp-to-edge, as GPUs and OpenColorIO do).
//  - NaN in a channel is treated as domainMin of that channel; +Inf as domainMax, -Inf as
//    domainMin; -0 as 0. Denormals and huge values (1e30) are just values outside or inside the
//    domain.
//  - The output is always a convex combination of table entries, so a table of finite entries
//    never yields NaN or Inf, and a point exactly on the lattice (including exactly domainMax,
//    e.g. 1.0) returns its entry exactly. Lattice coordinates are computed in float; a coordinate
//    within float rounding of a lattice point (|t - round(t)| <= (t + |min|*scale) * 2^-22) is
//    moved onto it, so lattice inputs given as floats (Lut3D::latticeInput) hit their entries.
//  - Degenerate domains (max - min tiny): the scale is computed in double and kept finite.
//  - applyPixels() runs a SIMD kernel (AVX2 + FMA when the CPU has it; tetrahedral on AVX-512
//    F + DQ where the CPU has that, bit-identical to its AVX2 twin; chosen at run time) that
//    follows this policy operation for operation and agrees with sample() to float rounding.
//    LUTKIT_SIMD=scalar in the environment makes new samplers use the scalar loop instead,
//    LUTKIT_SIMD=avx2 the AVX2 kernels on an AVX-512 CPU.
class Sampler {
public:
    virtual ~Sampler();
    virtual Interpolation method() const = 0;
    virtual glm::vec3 sample(glm::vec3 in) const = 0;
    // The hot kernel: rewrites the RGB of `count` RGBA pixels in place, alpha untouched.
    virtual void applyPixels(float* rgba, std::size_t count) const = 0;
    // Applies to a whole image on up to nthreads threads (0 = all cores). Alpha passes through.
    void apply(const ImageView& image, int nthreads = 0) const;
};

std::unique_ptr<Sampler> makeSampler(const Lut3D& lut, Interpolation method);

// A LUT file as it is meant to be applied: its 1D shaper (when it has one), then its 3D table
// (when it has one) with `method`, each exactly -- never merged into one lattice. The shaper
// follows the policy above on its own axis (N = its entry count, linear between entries, clamped
// to the end entries outside its domain, NaN as its domain minimum, an entry returned exactly at
// its input); its SIMD kernel agrees with sample() bit for bit. Inputs outside the file's input
// domain (LutFile::inputDomainMin/Max) take the edge value. Throws lut::Error if the file holds
// no table.
std::unique_ptr<Sampler> makeSampler(const LutFile& file, Interpolation method);

// Name of the SIMD path new samplers use on this CPU: "avx512" (tetrahedral on AVX-512, the
// other methods on AVX2), "avx2" or "scalar".
const char* samplerIsa();

} // namespace lut
