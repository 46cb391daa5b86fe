#include "Tables.h"

#include "lut/pipeline/SmashGrading.h"

namespace lut::detail {

const PowTable& powSmashEncode() {
    static const PowTable t(static_cast<double>(kSmashEncodeExponent));
    return t;
}
const PowTable& powSmashDecode() {
    static const PowTable t(static_cast<double>(kSmashDecodeExponent));
    return t;
}
const PowTable& powSrgbEncode() {
    static const PowTable t(1.0 / 2.4);
    return t;
}

} // namespace lut::detail
