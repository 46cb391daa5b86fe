// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenImageIO's attributes of an image (its ImageSpec::extra_attribs), built by a native reader
// without OpenImageIO, in the bytes the image module serialises them to (OiioImage.cpp's
// serialize(): per attribute its name, TypeDesc base type, aggregate, vector semantics, array
// length and value count as 32-bit words, then the value bytes, a string as its length and
// bytes). ImageMetadata::oiioAttributes carries them to OpenImageIO's writers, so a file a native
// reader read is written back by OpenImageIO with what OpenImageIO's own reader kept (a TGA's
// compression and image ID, a BMP's resolution).
#include <cstdint>
#include <string>

namespace lut::formats {

class OiioAttributes {
public:
    void addInt(const std::string& name, int value);
    void addUInt(const std::string& name, unsigned value);
    void addFloat(const std::string& name, float value);
    void addString(const std::string& name, const std::string& value);
    const std::string& bytes() const { return m_bytes; }

private:
    // OpenImageIO's TypeDesc::BASETYPE values (typedesc.h, stable since 1.0).
    enum BaseType : std::uint32_t { kUInt32 = 6, kInt32 = 7, kFloat = 11, kString = 13 };
    void head(const std::string& name, BaseType type);
    void word(std::uint32_t v);
    void data(const void* p, std::size_t n);
    std::string m_bytes;
};

} // namespace lut::formats
