// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the OpenColorIO bridge (files OCIO reads, through our ocio format reader). The
// target itself lives in OcioFuzzTarget.h so that tests/regress replays crashing inputs through the
// same path in the normal build.
#include "OcioFuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runOcio(data, size);
    return 0;
}
