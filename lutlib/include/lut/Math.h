// SPDX-License-Identifier: Apache-2.0
#pragma once
// The transcendental functions lutkit computes with: the same results on every platform. glibc
// (which picks FMA code on CPUs that have it), MinGW-w64 and Emscripten's libm round some values
// differently, so a LUT, a figure or a picture computed with std::pow would differ between the
// Linux, Windows and browser editions (docs/portable.md). These are musl's implementations
// (ARM's optimized routines for exp/log/pow, fdlibm for the others; max error ~0.5-1 ULP),
// compiled from Debian's musl source by cmake/LutkitThirdParty.cmake under lutkit_ names.
//
// Use lut::math::pow (and the others) wherever std::pow would be used in lutlib, formats and the
// programs; tests keep the standard library as their independent reference. The overloads follow
// <cmath>'s: float for float arguments, double otherwise (integers promoted to double).
#include <type_traits>

extern "C" {
double lutkit_pow(double, double);
double lutkit_exp(double);
double lutkit_exp2(double);
double lutkit_log(double);
double lutkit_log2(double);
double lutkit_log10(double);
double lutkit_cbrt(double);
double lutkit_sin(double);
double lutkit_cos(double);
double lutkit_atan(double);
double lutkit_atan2(double, double);
double lutkit_hypot(double, double);
float lutkit_powf(float, float);
float lutkit_expf(float);
float lutkit_exp2f(float);
float lutkit_logf(float);
float lutkit_log2f(float);
float lutkit_cbrtf(float);
float lutkit_sinf(float);
float lutkit_cosf(float);
float lutkit_atanf(float);
float lutkit_atan2f(float, float);
float lutkit_hypotf(float, float);
}

namespace lut::math {

namespace detail {
template <class T> constexpr bool kArithmetic = std::is_arithmetic_v<T>;
template <class A, class B>
constexpr bool kMixed =
    kArithmetic<A>&& kArithmetic<B> && !(std::is_same_v<A, float> && std::is_same_v<B, float>)&&!(
                                           std::is_same_v<A, double> && std::is_same_v<B, double>);
} // namespace detail

#define LUTKIT_MATH_UNARY(name)                                                                    \
    inline double name(double x) {                                                                 \
        return lutkit_##name(x);                                                                   \
    }                                                                                              \
    inline float name(float x) {                                                                   \
        return lutkit_##name##f(x);                                                                \
    }                                                                                              \
    template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0> double name(T x) {        \
        return lutkit_##name(static_cast<double>(x));                                              \
    }
#define LUTKIT_MATH_BINARY(name)                                                                   \
    inline double name(double x, double y) {                                                       \
        return lutkit_##name(x, y);                                                                \
    }                                                                                              \
    inline float name(float x, float y) {                                                          \
        return lutkit_##name##f(x, y);                                                             \
    }                                                                                              \
    template <class A, class B, std::enable_if_t<detail::kMixed<A, B>, int> = 0>                   \
    double name(A x, B y) {                                                                        \
        return lutkit_##name(static_cast<double>(x), static_cast<double>(y));                      \
    }

LUTKIT_MATH_BINARY(pow)
LUTKIT_MATH_UNARY(exp)
LUTKIT_MATH_UNARY(exp2)
LUTKIT_MATH_UNARY(log)
LUTKIT_MATH_UNARY(log2)
LUTKIT_MATH_UNARY(cbrt)
LUTKIT_MATH_UNARY(sin)
LUTKIT_MATH_UNARY(cos)
LUTKIT_MATH_UNARY(atan)
LUTKIT_MATH_BINARY(atan2)
LUTKIT_MATH_BINARY(hypot)

#undef LUTKIT_MATH_UNARY
#undef LUTKIT_MATH_BINARY

// log10 in double only (musl has no log10f among the sources compiled).
inline double log10(double x) {
    return lutkit_log10(x);
}

} // namespace lut::math
