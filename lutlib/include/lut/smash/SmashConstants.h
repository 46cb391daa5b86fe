// SPDX-License-Identifier: Apache-2.0
#pragma once
// Smash Ultimate's numbers, in one place: the post-processing shader's literals
// (docs/specs/smash-pipeline.md sections 1 and 2) and the size of the game's grading LUT. Used
// by the preview pipeline, the grading maths (lut/smash/SmashGrading.h), the round trip's
// display model and the nutexb format. The largest value a frame keeps once sanitized (the
// game's half-float render targets) is lut::limits::kMaxColorValue (lut/Limits.h).

namespace lut {

// Every stage LUT of the game is 16^3 (color_grading_lut.nutexb).
constexpr int kSmashLutSize = 16;

// The grading shader's literals (section 2).
constexpr float kSmashEncodeExponent = 0.454545f; // the shader's 1/2.2 (not exactly 1/2.2)
constexpr float kSmashDecodeExponent = 2.2f;
constexpr float kSmashLutScale = 0.9375f;   // (N-1)/N for the game's N = 16
constexpr float kSmashLutOffset = 0.03125f; // 0.5/N
constexpr float kSmashBrightenMix = 0.99961f;
constexpr float kSmashBrightenScale = 1.3703f; // 1.3703^2.2 = 2.0: ~2x brighter in linear light

// Bloom (section 1).
constexpr float kSmashBloomThreshold = 0.4625f; // 0.925 * 0.5
constexpr float kSmashBloomGain = 6.0f;
constexpr float kSmashBloomMinComponent = 0.001f;
constexpr float kSmashBloomWeights[4] = {0.32f, 0.10f, 0.20f, 0.25f}; // 1/8, 1/16, 1/32, 1/64
constexpr float kSmashBloomExponent = 2.2f;

} // namespace lut
