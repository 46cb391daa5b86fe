// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: image reading into apply and preview. The target itself lives in
// ImageFuzzTarget.h so that tests/regress replays crashing inputs through the same path in the
// normal build.
#include "ImageFuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runImageApply(data, size);
    return 0;
}
