// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which edition of lutkit this is (docs/portable.md): the Linux build, with OpenColorIO and
// OpenImageIO, or a portable one (the browser, Windows), without them. What an edition lacks is
// refused with one line that names the edition, never failed at silently.
#include <string>

namespace lut::formats {

// "lutkit for the browser", "lutkit for Windows", or "lutkit" (the Linux build).
const char* editionName();
// Whether this edition has OpenColorIO (foreign LUT formats, colour management, bake) and
// OpenImageIO (image formats other than PNG, JPEG, PNM and OpenEXR scanline files).
bool editionHasOpenColorIO();
bool editionHasOpenImageIO();
// "<what> needs <library>, which lutkit for the browser does not include; <instead> (the Linux
// build of lutkit has it)": the one wording of such a refusal.
std::string notInEdition(const std::string& what, const std::string& library,
                         const std::string& instead = {});

} // namespace lut::formats
