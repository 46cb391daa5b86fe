// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the CLI's argument handling where it parses numbers and words. The bytes
// are an argument list for the real subcommand set-up (CliTarget.h, stub run functions that
// check what validation promised) and, whole, one word for the parse helpers (FuzzTargets.h).
// tests/regress replays findings through the same two targets.
#include "CliTarget.h"
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runCliArgs(data, size);
    (void)lut::fuzz::runCliWords(data, size);
    return 0;
}
