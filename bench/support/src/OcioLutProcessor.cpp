// SPDX-License-Identifier: Apache-2.0
#include "lut/bench/OcioLutProcessor.h"

#include "ocio/OcioLut3D.h"

#include <OpenColorIO/OpenColorIO.h>

#include <glm/vec3.hpp>

namespace OCIO = OCIO_NAMESPACE;

namespace lut {

struct OcioLutProcessor::Impl {
    OCIO::ConstCPUProcessorRcPtr cpu;
};

OcioLutProcessor::OcioLutProcessor(const Lut3D& lut, Interpolation method)
    : m_impl(std::make_unique<Impl>()) {
    const auto t = formats::makeLut3DTransform(
        lut, method == Interpolation::Tetrahedral ? OCIO::INTERP_TETRAHEDRAL : OCIO::INTERP_LINEAR);
    m_impl->cpu = OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT);
}

OcioLutProcessor::~OcioLutProcessor() = default;
OcioLutProcessor::OcioLutProcessor(OcioLutProcessor&&) noexcept = default;
OcioLutProcessor& OcioLutProcessor::operator=(OcioLutProcessor&&) noexcept = default;

void OcioLutProcessor::apply(Image& image) const {
    OCIO::PackedImageDesc desc(image.data(), image.width(), image.height(), 4);
    m_impl->cpu->apply(desc);
}

} // namespace lut
