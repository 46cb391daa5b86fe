#pragma once
// Sizes an image file declares in its header, checked against the file's length before a codec
// believes them (issue 17: memory bounded by what the file holds, not what it claims). No
// OpenImageIO here: the check runs before the image module opens the file.
//  - OpenEXR: every header attribute's declared size must fit in the bytes that follow it (a
//    330-byte file whose "Software" attribute claimed 1.7 GB made OpenEXR, inside
//    OpenImageIO's open, take 1.8 GB and 3 s before failing; found by fuzz_image_apply).
#include <string>

namespace lut::formats {

// Throws lut::Error "PATH: ..." naming the field when a declared size cannot be true; returns
// for anything it does not recognise (the codec then reports what is wrong).
void checkImageHeader(const std::string& path);

} // namespace lut::formats
