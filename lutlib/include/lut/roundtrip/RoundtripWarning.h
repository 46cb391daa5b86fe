// SPDX-License-Identifier: Apache-2.0
#pragma once
// The warnings extract and fit can give (lut/roundtrip/Extract.h, lut/roundtrip/Fit.h), each with
// a test that triggers it.

namespace lut {

enum class RoundtripWarning {
    NonGlobalEdit,     // blocks not uniform / entries a smooth global edit cannot give
    ProfileChange,     // greys follow a pure gamma / sRGB<->2.2 curve: a colour-profile conversion?
    Clipping,          // many entries at 0 or 1
    Rescaled,          // the image was upscaled by a whole number (read anyway)
    OutOfRange,        // smash: entries the game cannot reach, clamped
    StageMismatch,     // the original LUT given is not the one the patch was embedded for
    ChromaSubsampling, // a 4:2:0 / 4:2:2 save blended the colours of entries not on its grid
    LowCoverage,       // fit: the pixels cover little of the cube
    FewColours,        // fit: too few distinct colours for a 3D fit
    Outliers,          // fit: pixels the robust fit down-weighted
};
// "non-global-edit", "profile-change", "clipping", ...
const char* toString(RoundtripWarning);

} // namespace lut
