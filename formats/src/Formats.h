#pragma once
// Factories of the built-in formats (internal to formats/). One per format file.
#include "lut/Format.h"

#include <memory>

namespace lut::formats {

} // namespace lut::formats
