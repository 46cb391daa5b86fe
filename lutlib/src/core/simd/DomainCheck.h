// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the first, branch-free pass of lut::countOutsideDomain (core/PixelChain.cpp)
// with AVX2, two RGBA pixels per compare. Free of glm and the standard library's inline
// templates (see the note in interp/simd/SimdKernels.h): the _avx2.cpp file that defines it is
// compiled with -mavx2.
#include <cstddef>

namespace lut::detail {

// Whether any R, G or B of `count` RGBA pixels is outside [lo[c], hi[c]] or NaN (alpha ignored):
// exactly the scalar first pass's answer. Only call when the CPU has AVX2.
bool anyOutsideDomainAvx2(const float* rgba, std::size_t count, const float lo[3],
                          const float hi[3]);

} // namespace lut::detail
