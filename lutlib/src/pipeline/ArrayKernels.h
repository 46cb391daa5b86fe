#pragma once
// Flat-array forms of the table functions, with an AVX2 path chosen at run time. The AVX2 path
// performs the same IEEE operations in the same order as the scalar one (no FMA), so both give
// bit-identical results and the choice of path never changes a frame.
#include "FastMath.h"

#include <cstddef>

namespace lut::detail {

// out[i] = pow(in[i]) (PowTable semantics); in == out allowed.
void powArray(const PowTable& t, const float* in, float* out, std::size_t n);
// out[i] = t(in[i]) for in[i] in [0, hi) (the caller checks covers(); other lanes: garbage-free
// but meaningless values).
void uniformArray(const UniformTable& t, const float* in, float* out, std::size_t n);
// out[i] = srgbEncodeFast(in[i], t) (t = the x^(1/2.4) table); in == out allowed.
void srgbEncodeArray(const PowTable& t, const float* in, float* out, std::size_t n);
const char* arrayKernelIsa();

} // namespace lut::detail
