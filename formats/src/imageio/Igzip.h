// SPDX-License-Identifier: Apache-2.0
#pragma once
// ISA-L's igzip deflate as lutkit compiles it from its portable C (cmake/LutkitThirdParty.cmake):
// the same bytes on every platform, where ISA-L's x86 assembly would write others. In the native
// build its symbols carry the prefix lutkit_ (third_party/isal/lutkit_prefix.h) and the system's
// libisal, linked beside it, inflates (PngCodec.cpp); the portable builds have only this copy.
// Include it before any other ISA-L header, in a file that deflates and does nothing else with
// ISA-L.
#if LUTKIT_IGZIP_PREFIXED
#include "lutkit_prefix.h"
#endif
#include <isa-l/igzip_lib.h>

#include <cstddef>

// The bytes of the level buffer ISA-L's state takes before the tokens of a block, for an igzip
// level (third_party/isal/lutkit_isal_level.c): smaller on a 32-bit machine.
extern "C" std::size_t lutkit_isal_level_state_bytes(int level);
