// The round trip's target names; see lut/LutPurpose.h.
#include "lut/LutPurpose.h"

#include "lut/Error.h"

#include <string>

namespace lut {

const char* toString(ExtractTarget t) {
    return t == ExtractTarget::Raw ? "raw" : "smash";
}

ExtractTarget parseTarget(std::string_view name) {
    if (name == "raw")
        return ExtractTarget::Raw;
    if (name == "smash")
        return ExtractTarget::Smash;
    throw Error("unknown target '" + std::string(name) + "' (expected raw or smash)");
}

} // namespace lut
