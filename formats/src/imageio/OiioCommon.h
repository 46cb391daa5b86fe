// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the OpenImageIO source and sink share, inside lutkit_imageio.so only (OiioCommon.cpp):
// sample types, messages, metadata as bytes, private scratch files.
#include "imageio/ImageCodec.h"

#include "lut/io/TempFiles.h"

#include <OpenImageIO/imageio.h>

#include <string>

namespace lut::formats::module {

// The first line of an OpenImageIO message (it stacks libpng's and libjpeg's own lines).
std::string oneLine(std::string s);
// A writer's error, never empty (OpenImageIO's IFF writer fails without a message).
std::string writerError(const std::string& s);

PixelType pixelTypeOf(OIIO_NAMESPACE::TypeDesc t);
OIIO_NAMESPACE::TypeDesc typeDescOf(PixelType t);

// An ImageSpec's attributes as bytes and back (ImageMetadata::oiioAttributes): name, type,
// count, then the values (strings as length + bytes).
std::string serializeAttributes(const OIIO_NAMESPACE::ParamValueList& list);
void deserializeAttributes(const std::string& s, OIIO_NAMESPACE::ImageSpec& spec);

// What lutkit's own JPEG reader keeps (JpegCodec.cpp: XMP, IPTC, subsampling, the JFIF
// resolution) as OpenImageIO's JPEG reader would have read it into a spec, XMP and IPTC in the
// file's order (decoding the second adds to the first's repeatable fields).
void applyJpegMetadata(const ImageMetadata& metadata, OIIO_NAMESPACE::ImageSpec& spec);

// A private file holding `bytes` (mode 0600, in the temporary folder, named ...suffix),
// registered for removal on an interrupt; its path.
std::string scratchFile(const std::string& bytes, const std::string& suffix,
                        TempPathRegistration& registration);

} // namespace lut::formats::module
