/* SPDX-License-Identifier: Apache-2.0 */
/* The <math.h> musl's libm sources see when lutkit compiles them (cmake/LutkitThirdParty.cmake):
   what they use of it, from the compiler's builtins, instead of the system's header, whose
   declarations (glibc's vector variants, MinGW's inline functions) do not survive the renaming
   to lutkit_ names. Values as musl's own <math.h> has them; every target of lutkit evaluates
   float and double in their own precision (FLT_EVAL_METHOD 0). */
#pragma once
#include <float.h>

typedef double double_t;
typedef float float_t;

#define NAN __builtin_nanf("")
#define INFINITY __builtin_inff()
#define HUGE_VALF INFINITY
#define HUGE_VAL ((double)INFINITY)

#define MATH_ERRNO 1
#define MATH_ERREXCEPT 2
#define math_errhandling 2

#define M_PI_2 1.57079632679489661923 /* pi/2 */

#define FP_ILOGBNAN (-1 - 0x7fffffff)
#define FP_ILOGB0 FP_ILOGBNAN

#define FP_NAN 0
#define FP_INFINITE 1
#define FP_ZERO 2
#define FP_SUBNORMAL 3
#define FP_NORMAL 4

#define fpclassify(x) __builtin_fpclassify(FP_NAN, FP_INFINITE, FP_NORMAL, FP_SUBNORMAL, FP_ZERO, x)
#define isinf(x) __builtin_isinf(x)
#define isnan(x) __builtin_isnan(x)
#define isnormal(x) __builtin_isnormal(x)
#define isfinite(x) __builtin_isfinite(x)
#define signbit(x) __builtin_signbit(x)

/* Exact operations the sources call (the system's libm gives the same results everywhere). */
double fabs(double);
float fabsf(float);
double sqrt(double);
float sqrtf(float);
double floor(double);
float floorf(float);
double scalbn(double, int);
float scalbnf(float, int);
double copysign(double, double);
float copysignf(float, float);

/* The functions compiled, under their lutkit_ names (lutkit_math_prefix.h). */
double pow(double, double);
double exp(double);
double exp2(double);
double log(double);
double log2(double);
double log10(double);
double cbrt(double);
double sin(double);
double cos(double);
double atan(double);
double atan2(double, double);
double hypot(double, double);
float powf(float, float);
float expf(float);
float exp2f(float);
float logf(float);
float log2f(float);
float cbrtf(float);
float sinf(float);
float cosf(float);
float atanf(float);
float atan2f(float, float);
float hypotf(float, float);
