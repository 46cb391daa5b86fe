// SPDX-License-Identifier: Apache-2.0
#include "lut/roundtrip/RoundtripWarning.h"

namespace lut {

const char* toString(RoundtripWarning w) {
    switch (w) {
    case RoundtripWarning::NonGlobalEdit:
        return "non-global-edit";
    case RoundtripWarning::ProfileChange:
        return "profile-change";
    case RoundtripWarning::Clipping:
        return "clipping";
    case RoundtripWarning::Rescaled:
        return "rescaled";
    case RoundtripWarning::OutOfRange:
        return "out-of-range";
    case RoundtripWarning::StageMismatch:
        return "stage-mismatch";
    case RoundtripWarning::ChromaSubsampling:
        return "chroma-subsampling";
    case RoundtripWarning::LowCoverage:
        return "low-coverage";
    case RoundtripWarning::FewColours:
        return "few-colours";
    case RoundtripWarning::Outliers:
        return "outliers";
    }
    return "?";
}

} // namespace lut
