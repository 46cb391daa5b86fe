// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenImageIO attribute lists as bytes and a JPEG's IPTC block as attributes (OiioMetadata.cpp),
// inside lutkit_imageio.so only.
#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

// From OpenImageIO/tiffutils.h, which needs libtiff's headers for the rest of what it declares.
OIIO_NAMESPACE_BEGIN
OIIO_API bool decode_exif(string_view exif, ImageSpec& spec);
OIIO_API void encode_exif(const ImageSpec& spec, std::vector<char>& blob);
OIIO_API bool decode_iptc_iim(const void* iptc, int length, ImageSpec& spec);
OIIO_API bool decode_xmp(string_view xml, ImageSpec& spec);
OIIO_NAMESPACE_END

namespace lut::formats::module {

// ParamValueList <-> bytes: name, type, count, then the values (strings as length + bytes).
std::string serialize(const OIIO_NAMESPACE::ParamValueList& list);
void deserialize(const std::string& s, OIIO_NAMESPACE::ImageSpec& spec);
// A JPEG's APP13 block ("Photoshop 3.0" taken off): its 8BIM resources, of which 0x0404 is the
// IPTC-IIM record OpenImageIO decodes into attributes.
void decodePhotoshopIptc(const std::string& block, OIIO_NAMESPACE::ImageSpec& spec);

} // namespace lut::formats::module
