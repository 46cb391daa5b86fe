// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenColorIO's CPU processor for a 3D LUT, set up the way OCIO's own tools run one: the table
// as a Lut3DTransform, an optimized float -> float CPU processor, one apply() over the whole
// image (single-threaded, as ocioconvert does). The peer `lutkit bench` and bench/lutkit_bench
// compare the samplers with; OpenColorIO stays private to this library.
//
// The table goes to OpenColorIO through the product's own builder (formats/src/ocio/OcioLut3D.h,
// what the OCIO writers use). Tests do not use it: a test oracle must not share code with what it
// checks, so tests/lutlib/test_sampler_ocio.cpp builds its own Lut3DTransform.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

#include <memory>

namespace lut {

class OcioLutProcessor {
public:
    // Tetrahedral runs as OCIO's tetrahedral interpolation, anything else as its linear one
    // (OCIO has no nearest for 3D LUTs). Throws what OpenColorIO throws on a table it refuses.
    OcioLutProcessor(const Lut3D& lut, Interpolation method);
    ~OcioLutProcessor();
    OcioLutProcessor(OcioLutProcessor&&) noexcept;
    OcioLutProcessor& operator=(OcioLutProcessor&&) noexcept;

    // Rewrites the RGB of every pixel in place (alpha passes through).
    void apply(Image& image) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace lut
