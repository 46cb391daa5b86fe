// SPDX-License-Identifier: Apache-2.0
#include "lut/formats/Edition.h"

namespace lut::formats {

const char* editionName() {
#if defined(__EMSCRIPTEN__)
    return "lutkit for the browser";
#elif defined(_WIN32)
    return "lutkit for Windows";
#else
    return "lutkit";
#endif
}

bool editionHasOpenColorIO() {
#if LUTKIT_PORTABLE
    return false;
#else
    return true;
#endif
}

bool editionHasOpenImageIO() {
    return editionHasOpenColorIO(); // both or neither (docs/portable.md)
}

std::string notInEdition(const std::string& what, const std::string& library,
                         const std::string& instead) {
    return what + " needs " + library + ", which " + editionName() + " does not include" +
           (instead.empty() ? "" : "; " + instead) + " (the Linux build of lutkit has it)";
}

} // namespace lut::formats
