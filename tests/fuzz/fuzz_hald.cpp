// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the hald reader. The target itself lives in FuzzTargets.h so that
// tests/regress replays crashing inputs through the same path in the normal build.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runHald(data, size);
    return 0;
}
