// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the embed/extract patch finder (findPatch, readPatch, extractLut). The target
// itself lives in PatchFuzzTarget.h so that tests/regress replays crashing inputs through the same
// path in the normal build.
#include "PatchFuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runPatch(data, size);
    return 0;
}
