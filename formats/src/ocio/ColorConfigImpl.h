// SPDX-License-Identifier: Apache-2.0
#pragma once
// The OpenColorIO config behind lut::formats::ColorConfig (formats/src only).
#include "lut/formats/ColorConfig.h"
#include "ocio/OcioSession.h"

namespace lut::formats {

struct ColorConfig::Impl {
    ConfigLocation location;
    OCIO::ConstConfigRcPtr config;
    Diagnostics diagnostics;
};

} // namespace lut::formats
