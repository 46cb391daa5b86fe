// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: what the game shows with an 8-bit LUT against the wanted colours, measured
// where nothing was fitted (lut/smash/SmashAuthoring.h), and the colours a refinement is
// fitted on and checked against.
//   Every input: the error bounded over every s in [0,1]^3 (held-out inputs at the centres of a
//   grid four times finer than the LUT's lattice, plus the slope between them,
//   lut/ops/ErrorBound.h); mean and p99 over those held-out inputs. A refinement is fitted on
//   the (61^3) grid's points and checked on the held-out centres.
//   A screenshot: the error over every pixel (each distinct colour once, weighted by its pixels;
//   the game displayed something within half a code of the file's colour, so the maximum covers
//   that range, and a channel the unedited game clipped to white could have had any input from
//   the clip point to 1, so those are measured across that range). The distinct colours are
//   split by a hash: three quarters to fit a refinement on, a quarter held out to check it; a
//   refinement that wins there is fitted again on every colour.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/smash/GameError.h"
#include "smash/GameSamples.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lut::detail {

using WantedFn = std::function<glm::dvec3(const glm::dvec3& s)>;
// The input s the unedited game had for a displayed colour d; `pixel` picks one input in the
// clipped range for a white channel (the training samples spread over it).
using InputForShownFn = std::function<glm::dvec3(const glm::dvec3& d, std::size_t pixel)>;

// Every input: the bound of the error over [0,1]^3 (maxSteps) and mean and p99 over the held-out
// centres of the grid `subdivision` times finer than the LUT's lattice. `lut8` as the game gets it.
GameError gameErrorEverywhere(const WantedFn& wanted, const Lut3D& lut8, int subdivision,
                              int nthreads);
// The held-out centres as samples (to check a refinement on).
GameSamples gridCentres(const WantedFn& wanted, int subdivision);
// The grid's points, lattice points included (to fit a refinement on).
GameSamples gridPoints(const WantedFn& wanted, int subdivision);

class ShotColours {
public:
    // `clipInput` is the input above which the unedited game showed white (0: no clipping to
    // account for, e.g. with a stage LUT, where the input is solved for).
    ShotColours(const ImageView& shot, const WantedFn& wanted, const InputForShownFn& input,
                double clipInput);

    std::size_t pixels() const { return m_pixels; }
    std::size_t distinct() const { return m_colours.size(); }
    std::size_t heldOutColours() const;
    // The error with `lut8` over every pixel (heldOutOnly: the held-out colours' pixels): mean and
    // p99 at the inputs that display each colour exactly, the max bounded over each colour's code
    // range (and a white channel's whole input range).
    GameError error(const Lut3D& lut8, bool heldOutOnly, int nthreads) const;
    // Samples to fit on: the training colours' pixels (withHeldOut: every pixel), every
    // `stride`th so that at most maxSamples are kept, each at an input somewhere in its code.
    GameSamples training(std::size_t maxSamples, bool withHeldOut) const;

private:
    struct Colour {
        glm::dvec3 display{0.0};
        std::uint32_t count = 0;
        std::uint32_t firstPixel = 0;
        bool heldOut = false;
        std::uint32_t wanted = 0;
        // `sets` sets of 7 inputs from firstInput: the centre, then each channel's code ends
        std::uint32_t firstInput = 0, sets = 0;
    };
    void addInputs(Colour& col, const WantedFn& wanted, const InputForShownFn& input);

    std::vector<Colour> m_colours;
    std::vector<glm::dvec3> m_s, m_wanted;
    std::vector<std::uint32_t> m_pixelColour; // per pixel: its colour
    std::size_t m_pixels = 0;
    InputForShownFn m_input;
    double m_clip = 0.0;
    double m_halfCode = 0.5 / 255.0; // half a code of the file (8 or 16 bits)
};

} // namespace lut::detail
