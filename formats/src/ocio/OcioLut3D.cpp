// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioLut3D.h"

namespace lut::formats {

OCIO_NAMESPACE::Lut3DTransformRcPtr makeLut3DTransform(const Lut3D& lut,
                                                       OCIO_NAMESPACE::Interpolation interp) {
    const int n = lut.size();
    auto t = OCIO_NAMESPACE::Lut3DTransform::Create(static_cast<unsigned long>(n));
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 v = lut.at(r, g, b);
                t->setValue(static_cast<unsigned long>(r), static_cast<unsigned long>(g),
                            static_cast<unsigned long>(b), v.x, v.y, v.z);
            }
    t->setInterpolation(interp);
    return t;
}

} // namespace lut::formats
