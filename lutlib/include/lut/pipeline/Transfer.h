// SPDX-License-Identifier: Apache-2.0
#pragma once
// Display transfer functions used by the preview pipeline, scalar reference forms.
//
// Piecewise sRGB (IEC 61966-2-1), extended the way scRGB does it: the curve is mirrored for
// negative values (encode(-x) = -encode(x)) so it stays invertible and never produces NaN; values
// above 1 follow the power segment. NaN maps to 0.
#include "lut/Image.h"

namespace lut {

float srgbEncode(float linear);
float srgbDecode(float encoded);
// Pure power gamma: pow(max(x, 0), 1/gamma) and its inverse (negatives and NaN -> 0).
float gammaEncode(float linear, float gamma);
float gammaDecode(float encoded, float gamma);

// Whole-frame forms on up to nthreads threads (0 = all cores); RGB only, alpha untouched.
void srgbEncode(const ImageView& frame, int nthreads = 0);
void srgbDecode(const ImageView& frame, int nthreads = 0);

} // namespace lut
