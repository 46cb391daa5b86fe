// SPDX-License-Identifier: Apache-2.0
#pragma once
// The space a colour match is computed in. The LUT maps the source's stored values to stored
// values of the same kind; the statistics (histograms, covariances, distances between lattice
// entries) are taken in a working encoding of them:
//   display-encoded values (8/16-bit pictures: sRGB as shown)   the values themselves;
//   scene-linear values (float pictures, HDR)                    the ACEScct curve (S-2016-001):
//       w = 10.5402377416545 x + 0.0729055341958355     x <= 2^-7
//       w = (log2(x) + 9.72) / 17.52                      x >  2^-7
//     continuous and increasing, linear below 2^-7 (negatives included), so a stop of light is
//     the same distance everywhere and the highlights do not swamp the covariance.
namespace lut {

double encodeWorking(double stored, bool linear);
double decodeWorking(double working, bool linear); // the inverse, limited to +-65504

// Conversions between the two kinds of stored values (the piecewise sRGB curve, mirrored below 0
// and continued above 1): a reference stored as the other kind is converted to the source's.
double srgbEncodeExtended(double linear);
double srgbDecodeExtended(double encoded);

} // namespace lut
