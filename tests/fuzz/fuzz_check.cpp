// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: lutkit check's thresholds file and the check itself on any .cube the reader
// accepts. The target lives in CheckFuzzTarget.h so tests/regress replays findings in the normal
// build.
#include "CheckFuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runCheck(data, size);
    return 0;
}
