// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUT strength ("intensity", "contribution"): a LUT blended with the neutral LUT, separately in
// lightness and in chroma, in a perceptual space (Oklab), so "half the grade" looks like half and
// a colour-only or a contrast-only share of a grade can be kept. The result is a plain 3D LUT on
// the source's lattice and domain that any engine reads; `mix` (lut/ops/Compose.h) stays the
// per-entry RGB blend of two LUTs.
#include "lut/Lut3D.h"

#include <glm/vec3.hpp>

#include <optional>

namespace lut {

// How the LUT's colour and its input are blended:
// - Oklab (the default): lightness and chroma apart in a perceptual space (below);
// - ReShade: what ReShade's LUT.fx sliders "LUT luma amount" and "LUT chroma amount" compute
//   (crosire/reshade-shaders, Shaders/LUT.fx), on the stored (display-encoded) RGB as vectors:
//       out = lerp(normalize(x), normalize(y), chroma) * lerp(length(x), length(y), luma)
//   where an RGB of length 0 has direction 0 (the shader's normalize gives NaN there). For
//   strips made for ReShade that are to look as ReShade's sliders make them look.
enum class StrengthBlend { Oklab, ReShade };

struct StrengthOptions {
    // Both amounts at once: 0 = neutral, 1 = the LUT; up to 2 exaggerates it.
    double strength = 1;
    // The lightness amount (Oklab L) and the chroma amount (Oklab a and b), each in [0, 2]; when
    // unset, `strength`.
    std::optional<double> luma, chroma;
    StrengthBlend blend = StrengthBlend::Oklab;
};

// The lightness and chroma amounts options asks for (luma and chroma, else strength). Throws
// lut::Error naming the option when an amount is NaN or outside [0, 2].
struct StrengthAmounts {
    double luma = 1, chroma = 1;
    StrengthBlend blend = StrengthBlend::Oklab;
};
StrengthAmounts strengthAmounts(const StrengthOptions& options);

// True when options leaves a LUT as it is (both amounts 1).
bool isFullStrength(const StrengthOptions& options);

// Entry (r, g, b) of the result, with x the lattice input and y the LUT's entry there:
//     Lab(x) = Oklab(decode(x)), Lab(y) = Oklab(decode(y))
//     L  = L(x)  + luma   * (L(y)  - L(x))
//     ab = ab(x) + chroma * (ab(y) - ab(x))
//     out = encode(linear sRGB of (L, ab))
// decode/encode: the sRGB transfer curve (IEC 61966-2-1) continued above 1 and mirrored below 0,
// since game LUTs hold display-encoded colour; Oklab as Björn Ottosson defines it
// (https://bottosson.github.io/posts/oklab/). Any fixed invertible encoding keeps the guarantees:
// - both amounts 0 give the lattice inputs (the neutral LUT over the LUT's domain) bit for bit,
//   and both 1 a copy of the LUT bit for bit (NaN entries included);
// - luma-only (chroma 0) keeps every entry's Oklab a, b those of its input, chroma-only (luma 0)
//   keeps its Oklab L; to float rounding of the stored entries;
// - NaN entries count as 0 and +-Inf as +-65504 (lut/Limits.h) before blending, so every entry
//   of a partial blend is finite; values above 1 (HDR) and below 0 are kept, never clipped: a
//   blend may leave the RGB cube where the LUT's colours are far from their inputs, and writing
//   to an 8-bit format then reports that as storage error.
// Title, comments and domain are kept. Throws lut::Error for an empty LUT or a bad amount.
Lut3D applyStrength(const Lut3D& lut, const StrengthOptions& options);

// The same blend for one colour: `graded` is what the LUT (or any transfer) gives for `input`.
// applyStrength is this at every lattice point; a transfer that is not a plain 3D table on its
// own inputs (lutkit match: a shaper, then a table) blends with it before it is tabulated. The
// amounts are taken as they are (strengthAmounts checks them); NaN and Inf as above.
glm::dvec3 blendStrength(const glm::dvec3& input, const glm::dvec3& graded,
                         const StrengthAmounts& amounts);

} // namespace lut
