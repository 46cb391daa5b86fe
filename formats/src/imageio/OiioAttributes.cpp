// SPDX-License-Identifier: Apache-2.0
#include "imageio/OiioAttributes.h"

#include <cstring>

namespace lut::formats {

void OiioAttributes::word(std::uint32_t v) {
    char b[4];
    std::memcpy(b, &v, 4); // host order, as the module's serialize() writes it
    m_bytes.append(b, 4);
}

void OiioAttributes::data(const void* p, std::size_t n) {
    word(static_cast<std::uint32_t>(n));
    m_bytes.append(static_cast<const char*>(p), n);
}

void OiioAttributes::head(const std::string& name, BaseType type) {
    data(name.data(), name.size());
    word(type);
    word(1); // SCALAR
    word(0); // NOSEMANTICS
    word(0); // not an array
    word(1); // one value
}

void OiioAttributes::addInt(const std::string& name, int value) {
    head(name, kInt32);
    data(&value, 4);
}

void OiioAttributes::addUInt(const std::string& name, unsigned value) {
    head(name, kUInt32);
    data(&value, 4);
}

void OiioAttributes::addFloat(const std::string& name, float value) {
    head(name, kFloat);
    data(&value, 4);
}

void OiioAttributes::addString(const std::string& name, const std::string& value) {
    head(name, kString);
    data(value.data(), value.size());
}

} // namespace lut::formats
