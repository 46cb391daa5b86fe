// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/QuantizeLut.h"

#include "lut/Quantize.h"

#include <chrono>

namespace lut {

ErrorStats quantize8(Lut3D& lut) {
    const auto t0 = std::chrono::steady_clock::now();
    ErrorAccumulator acc;
    for (auto& v : lut.entries())
        for (int c = 0; c < 3; ++c) {
            const float q = fromUnorm8(toUnorm8(v[c]));
            acc.add(v[c], q);
            v[c] = q;
        }
    ErrorStats s = acc.result();
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
}

Lut3D quantized8(Lut3D lut) {
    for (auto& v : lut.entries())
        for (int c = 0; c < 3; ++c)
            v[c] = fromUnorm8(toUnorm8(v[c]));
    return lut;
}

} // namespace lut
