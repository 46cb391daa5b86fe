// SPDX-License-Identifier: Apache-2.0
#include "lut/roundtrip/EditCause.h"

namespace lut {

const char* toString(EditCause c) {
    switch (c) {
    case EditCause::None:
        return "none";
    case EditCause::Blur:
        return "blur";
    case EditCause::Sharpen:
        return "sharpen";
    case EditCause::Noise:
        return "noise";
    case EditCause::LocalEdit:
        return "local-edit";
    case EditCause::Lossy:
        return "lossy";
    case EditCause::Unknown:
        return "unknown";
    }
    return "?";
}

} // namespace lut
