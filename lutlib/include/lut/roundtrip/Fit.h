// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fitting a 3D LUT to a before/after image pair, for when no patch was embedded.
//
// Per output channel, the lattice values v minimise
//     sum_p w_p (sum_k t_pk v_k - y_p)^2  +  lambda * sum_axes |D2 v|^2  +  mu * |v - identity|^2
// where t_pk are the trilinear weights of pixel p's 8 lattice neighbours, y_p its edited value,
// D2 the second difference along each lattice axis (zero for anything multilinear, so empty
// regions are filled by the smoothest continuation of the data) and mu a tiny ridge that keeps
// the system positive definite when the data leave directions undetermined (few colours).
// The normal equations are SPD; they are solved per channel by conjugate gradients with a Jacobi
// preconditioner. Outliers are down-weighted by iteratively reweighted least squares (Huber).
#include "lut/Error.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/roundtrip/RoundtripWarning.h"

#include <cstddef>
#include <vector>

namespace lut {

struct FitOptions {
    int size = 33;
    // lambda, in units of pixels: a lattice point with much more than ~lambda*20 pixel weight
    // follows its pixels exactly, one with little follows its neighbours.
    double smoothness = 1.0;
    bool robust = true;      // Huber IRLS against outliers
    double huberSteps = 4.0; // Huber threshold in 8-bit steps
    int robustRounds = 4;
    int maxIterations = 4000; // per CG solve
    double tolerance = 1e-6;  // relative residual of the preconditioned CG
    // Also measure the error on colours a fit never saw: a second fit on seven eighths of the
    // distinct colours, measured on the other eighth (FitResult::heldOut*).
    bool heldOut = true;
    int nthreads = 0;
};

struct FitResult {
    Lut3D lut;
    std::size_t pixels = 0;          // pixel pairs used (a regular subsample beyond 8 megapixels)
    std::size_t distinctColours = 0; // distinct input colours (8-bit)
    // The fit's error over the pixels it was fitted to, 8-bit steps: a residual, smaller than
    // what the LUT does on other pixels. rms over the pixels used (trilinear); max over every pixel
    // of the picture (not only those sampled), read trilinearly and tetrahedrally.
    double rmsSteps8 = 0.0;
    double maxSteps8 = 0.0;
    // With FitOptions::heldOut (and 16 colours or more): the error of a fit on seven eighths of
    // the colours on the pixels of the other eighth: what to expect on colours not fitted. The
    // max is the larger of that and maxSteps8, plus half a step (a margin: a sample's largest
    // value is a low estimate of the largest elsewhere).
    std::size_t heldOutColours = 0, heldOutPixels = 0;
    double heldOutRmsSteps8 = 0.0;
    double heldOutMaxSteps8 = 0.0;
    double extrapolatedShare = 0.0; // share of lattice cells no pixel falls in
    std::size_t outlierPixels = 0;  // pixels off the fit by more than 4x the Huber threshold
    int iterations = 0; // CG iterations, summed over the robust rounds (largest channel)
    bool converged = true;
    Diagnostics diagnostics;
    std::vector<RoundtripWarning> warnings;
    bool has(RoundtripWarning w) const;
};

// Throws lut::Error if the images differ in size or are empty.
FitResult fitLut(const ImageView& before, const ImageView& after, const FitOptions& options = {});

} // namespace lut
