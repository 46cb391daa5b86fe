// SPDX-License-Identifier: Apache-2.0
// musl's libm functions compiled by lutkit (cmake/LutkitThirdParty.cmake) under their own names,
// beside the system's libm, which they never replace: lut/Math.h calls these. Every global
// symbol of the sources compiled, public functions, their helpers and their tables.
#pragma once
#define pow lutkit_pow
#define exp lutkit_exp
#define exp2 lutkit_exp2
#define log lutkit_log
#define log2 lutkit_log2
#define log10 lutkit_log10
#define cbrt lutkit_cbrt
#define sin lutkit_sin
#define cos lutkit_cos
#define atan lutkit_atan
#define atan2 lutkit_atan2
#define hypot lutkit_hypot
#define powf lutkit_powf
#define expf lutkit_expf
#define exp2f lutkit_exp2f
#define logf lutkit_logf
#define log2f lutkit_log2f
#define cbrtf lutkit_cbrtf
#define sinf lutkit_sinf
#define cosf lutkit_cosf
#define atanf lutkit_atanf
#define atan2f lutkit_atan2f
#define hypotf lutkit_hypotf
#define __sin lutkit___sin
#define __cos lutkit___cos
#define __rem_pio2 lutkit___rem_pio2
#define __rem_pio2_large lutkit___rem_pio2_large
#define __sindf lutkit___sindf
#define __cosdf lutkit___cosdf
#define __rem_pio2f lutkit___rem_pio2f
#define __math_oflow lutkit___math_oflow
#define __math_uflow lutkit___math_uflow
#define __math_invalid lutkit___math_invalid
#define __math_divzero lutkit___math_divzero
#define __math_xflow lutkit___math_xflow
#define __math_oflowf lutkit___math_oflowf
#define __math_uflowf lutkit___math_uflowf
#define __math_invalidf lutkit___math_invalidf
#define __math_divzerof lutkit___math_divzerof
#define __math_xflowf lutkit___math_xflowf
#define __exp_data lutkit___exp_data
#define __pow_log_data lutkit___pow_log_data
#define __log_data lutkit___log_data
#define __log2_data lutkit___log2_data
#define __exp2f_data lutkit___exp2f_data
#define __powf_log2_data lutkit___powf_log2_data
#define __logf_data lutkit___logf_data
#define __log2f_data lutkit___log2f_data
// musl's own build defines these (src/include/features.h, its endian.h).
#define hidden __attribute__((__visibility__("hidden")))
