// SPDX-License-Identifier: Apache-2.0
#pragma once
// Settings of the OpenColorIO reader ("ocio": every LUT file OpenColorIO reads but .cube), passed
// as FormatOptions attributes.
namespace lut::formats {

// The id of the correction to read from a .ccc or .cdl file holding several (a CCC id, or its
// index counted from 0): what ociobakelut --cccid and FileTransform::setCCCId take.
constexpr const char* kOcioCccIdAttribute = "ocio:cccid";

} // namespace lut::formats
