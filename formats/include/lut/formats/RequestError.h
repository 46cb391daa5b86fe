// SPDX-License-Identifier: Apache-2.0
#pragma once
// What was asked cannot be done as asked (options that do not go together, a size the output
// cannot hold): bad usage, not bad input (exit code 2 in lutkit). Thrown where the library
// resolves what the user said (lut/formats/LutDestination.h, convertLut); front ends print
// what() and decide by the type, never by the text. Other lut::Errors are bad input or a failed
// operation (exit code 1); ColorOptionError (ColorConfig.h) is the colour options' own.
#include "lut/Error.h"

namespace lut::formats {

class RequestError : public Error {
public:
    using Error::Error;
};

} // namespace lut::formats
