// SPDX-License-Identifier: Apache-2.0
#pragma once
// Box-filter reduction of an image by an integer factor: a quick, smooth proxy of a frame (the
// editor previews on one while a slider is dragged).
#include "lut/Image.h"

namespace lut {

// Each output pixel is the mean of the factor x factor block of input pixels it covers (all four
// channels). The output is ceil(width / factor) x ceil(height / factor): the blocks on the right
// and bottom edges may be partial and average only the pixels they hold, so every input pixel
// counts. factor <= 1 or an empty image: a copy. nthreads 0 = all cores.
Image downscale(const Image& image, int factor, int nthreads = 0);

} // namespace lut
