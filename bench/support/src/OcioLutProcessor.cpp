#include "lut/bench/OcioLutProcessor.h"

#include <OpenColorIO/OpenColorIO.h>

#include <glm/vec3.hpp>

namespace OCIO = OCIO_NAMESPACE;

namespace lut {

struct OcioLutProcessor::Impl {
    OCIO::ConstCPUProcessorRcPtr cpu;
};

OcioLutProcessor::OcioLutProcessor(const Lut3D& lut, Interpolation method)
    : m_impl(std::make_unique<Impl>()) {
    const int n = lut.size();
    // setValue takes the red, green and blue lattice indices explicitly: no storage order to
    // agree on.
    auto t = OCIO::Lut3DTransform::Create(static_cast<unsigned long>(n));
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 e = lut.at(r, g, b);
                t->setValue(static_cast<unsigned long>(r), static_cast<unsigned long>(g),
                            static_cast<unsigned long>(b), e.r, e.g, e.b);
            }
    t->setInterpolation(method == Interpolation::Tetrahedral ? OCIO::INTERP_TETRAHEDRAL
                                                             : OCIO::INTERP_LINEAR);
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
