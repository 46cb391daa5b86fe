// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Smash Ultimate colour grading + brighten pass (docs/specs/smash-pipeline.md section 2) as
// plain functions, shared by the preview pipeline (lutlib/src/pipeline), the screenshot "deprocess"
// and the round-trip code that authors game-compensated LUTs (embed/extract --target smash).
//
// The shader, GetPostProcessingResult(linear):
//     s   = pow(linear, 0.454545)                    gamma 2.2 encode
//     lut = texture(lut16, s * 0.9375 + 0.03125)     hardware trilinear, clamp to edge
//     r   = ((lut - s) * 0.99961 + s) * 1.3703        brighten
//     out = pow(r, 2.2)
// On a 16^3 texture, s * 0.9375 + 0.03125 puts texel centres exactly on the inputs i/15, so the
// lookup IS lut::Trilinear on the LUT over the domain [0,1] (inputs outside [0,1] take the edge
// value); for an N^3 LUT the same holds with the scale (N-1)/N and offset 0.5/N, so any size works.
//
// Defined where the shader is not: pow() of a negative or NaN is taken of 0 (clamp before every
// pow); +Inf is clamped to limits::kMaxColorValue first. Finite input never gives NaN or Inf.
#include "lut/Error.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"
#include "lut/interp/Sampler.h"
#include "lut/smash/SmashConstants.h"

#include <glm/vec3.hpp>

#include <cstddef>

namespace lut {

// s = pow(x, 0.454545) with x clamped to [0, limits::kMaxColorValue] (NaN -> 0).
float smashEncode(float linear);
glm::vec3 smashEncode(glm::vec3 linear);
// The exact inverse of smashEncode for s >= 0: pow(s, 1 / 0.454545) (negatives/NaN -> 0).
float smashEncodeInverse(float s);
// pow(max(r, 0), 2.2) (NaN -> 0).
float smashDecode(float r);

// r = ((lutOut - s) * 0.99961 + s) * 1.3703, in gamma space.
glm::vec3 smashBrighten(glm::vec3 lutOut, glm::vec3 s);
// The inverse of smashBrighten for a known s: the LUT output that gives r.
//     L = (r / 1.3703 - s) / 0.99961 + s
glm::vec3 smashBrightenInverse(glm::vec3 r, glm::vec3 s);

// GetPostProcessingResult(linear): linear in, linear out. `lut` samples the grading LUT over
// [0,1] (makeSampler(lut, Interpolation::Trilinear) is what the game does).
glm::vec3 smashGrade(glm::vec3 linear, const Sampler& lut);
// mix(linear, smashGrade(linear), clamp(alpha, 0, 1)): alpha 0 is left ungraded.
glm::vec3 smashGradeMix(glm::vec3 linear, float alpha, const Sampler& lut);

// Authoring compensation, per lattice point: the LUT entry L (gamma space) that makes
// smashGrade give `targetLinear` for the gamma-space input s (s = i/15 at lattice point i):
//     L = (pow(target, 1/2.2) / 1.3703 - s) / 0.99961 + s
// The result may leave [0,1] (targets the game cannot reach); the caller clamps/quantizes.
glm::vec3 smashLutEntryForTarget(glm::vec3 targetLinear, glm::vec3 s);
// The whole LUT at once: `targetLinear` holds, at each lattice point, the linear colour the game
// should output for that lattice point's input; returns the LUT to ship (same size, domain [0,1]).
Lut3D smashCompensateLut(const Lut3D& targetLinear);

// Inverts the grading + brighten + alpha mix for one pixel: the linear scene colour x with
// smashGradeMix(x, alpha, lut) == outputLinear. Closed form for a neutral (identity) LUT, else a
// damped Newton solve in gamma space on the piecewise-trilinear map (starting from the neutral
// solution). Returns the best x found; *converged (optional) says whether the residual fell
// below 1e-6 in gamma space. Output >= 0, finite.
glm::vec3 smashGradeInverse(glm::vec3 outputLinear, float alpha, const Sampler& lut,
                            bool identityLut = false, bool* converged = nullptr);

struct UngradeResult {
    std::size_t pixels = 0;
    std::size_t unconverged = 0; // pixels whose colour the LUT cannot produce (best fit kept)
    Diagnostics diagnostics;     // includes the note that bloom cannot be undone
};
// "Deprocess" a frame that went through the game's grading with `originalLut` (nullptr = the
// neutral 16^3 LUT): rewrites the linear RGB of `frame` (display encoding already undone) to the
// pre-grading scene, alpha kept. Bloom is not undone (it is not invertible): it stays in the frame.
UngradeResult smashUngrade(const ImageView& frame, const Lut3D* originalLut,
                           Interpolation interp = Interpolation::Trilinear, int nthreads = 0);

} // namespace lut
