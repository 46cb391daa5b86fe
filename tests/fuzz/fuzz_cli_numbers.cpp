// libFuzzer harness: the parse helpers behind the CLI's words and numbers (interpolation names,
// layout names, sizes). The target lives in FuzzTargets.h so tests/regress replays findings.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runCliWords(data, size);
    return 0;
}
