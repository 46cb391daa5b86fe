#include "Commands.h"

#include "lut/Error.h"

namespace lut::cli {

std::optional<LutLayout> layoutOption(const std::string& option, const std::string& value) {
    try {
        return parseOptionalLayout(value);
    } catch (const Error& e) {
        throw UsageError(option + ": " + e.what());
    }
}

} // namespace lut::cli
