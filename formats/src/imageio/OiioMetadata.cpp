// SPDX-License-Identifier: Apache-2.0
// OpenImageIO's attributes as bytes lutkit carries between a source and a sink (ImageMetadata's
// oiioAttributes), and the metadata blocks lutkit's own readers keep, decoded into attributes.
// Inside lutkit_imageio.so only.
#include "imageio/OiioMetadata.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace lut::formats::module {

namespace OIIO = OIIO_NAMESPACE;

namespace {

// ParamValueList <-> bytes: name, type, count, then the values (strings as length + bytes). The
// native BMP and TGA readers write the same layout without OpenImageIO (OiioAttributes.h): a change
// here is a change there.
void putInt(std::string& s, std::uint32_t v) {
    s.append(reinterpret_cast<const char*>(&v), 4);
}
std::uint32_t getInt(const std::string& s, std::size_t& at) {
    std::uint32_t v = 0;
    if (at + 4 <= s.size())
        std::memcpy(&v, s.data() + at, 4);
    at += 4;
    return v;
}
void putBytes(std::string& s, const void* p, std::size_t n) {
    putInt(s, static_cast<std::uint32_t>(n));
    s.append(static_cast<const char*>(p), n);
}
std::string getBytes(const std::string& s, std::size_t& at) {
    const std::uint32_t n = getInt(s, at);
    if (at + n > s.size())
        return {};
    std::string v = s.substr(at, n);
    at += n;
    return v;
}

} // namespace

std::string serialize(const OIIO::ParamValueList& list) {
    std::string s;
    for (const auto& p : list) {
        const OIIO::TypeDesc t = p.type();
        putBytes(s, p.name().c_str(), p.name().size());
        putInt(s, t.basetype);
        putInt(s, t.aggregate);
        putInt(s, t.vecsemantics);
        putInt(s, static_cast<std::uint32_t>(t.arraylen));
        putInt(s, static_cast<std::uint32_t>(p.nvalues()));
        if (t.basetype == OIIO::TypeDesc::STRING) {
            const auto* strs = static_cast<const OIIO::ustring*>(p.data());
            for (int i = 0; i < p.nvalues() * static_cast<int>(t.numelements()); ++i)
                putBytes(s, strs[i].c_str(), strs[i].size());
        } else {
            putBytes(s, p.data(), t.size() * static_cast<std::size_t>(p.nvalues()));
        }
    }
    return s;
}

void deserialize(const std::string& s, OIIO::ImageSpec& spec) {
    std::size_t at = 0;
    while (at < s.size()) {
        const std::string name = getBytes(s, at);
        OIIO::TypeDesc t;
        t.basetype = static_cast<unsigned char>(getInt(s, at));
        t.aggregate = static_cast<unsigned char>(getInt(s, at));
        t.vecsemantics = static_cast<unsigned char>(getInt(s, at));
        t.arraylen = static_cast<int>(getInt(s, at));
        const int n = static_cast<int>(getInt(s, at));
        if (at > s.size() || name.empty())
            return;
        if (t.basetype == OIIO::TypeDesc::STRING) {
            std::vector<std::string> vals;
            const int count = n * static_cast<int>(t.numelements());
            for (int i = 0; i < count && at < s.size(); ++i)
                vals.push_back(getBytes(s, at));
            std::vector<const char*> ptrs;
            for (const auto& v : vals)
                ptrs.push_back(v.c_str());
            if (static_cast<int>(ptrs.size()) == count)
                spec.extra_attribs.emplace_back(name, t, n, ptrs.data());
        } else {
            const std::string bytes = getBytes(s, at);
            if (bytes.size() == t.size() * static_cast<std::size_t>(n))
                spec.extra_attribs.emplace_back(name, t, n, bytes.data());
        }
    }
}

// A JPEG's APP13 block ("Photoshop 3.0" taken off): its 8BIM resources, of which 0x0404 is the
// IPTC-IIM record OpenImageIO decodes into attributes.
void decodePhotoshopIptc(const std::string& block, OIIO::ImageSpec& spec) {
    std::size_t at = 0;
    const auto u8 = [&](std::size_t i) { return static_cast<unsigned char>(block[i]); };
    while (at + 12 <= block.size() && block.compare(at, 4, "8BIM") == 0) {
        const unsigned id = (u8(at + 4) << 8) | u8(at + 5);
        std::size_t p = at + 6;
        const std::size_t nameLen = u8(p);
        p += (nameLen + 2) & ~std::size_t(1); // a padded Pascal string
        if (p + 4 > block.size())
            return;
        const std::size_t size = (std::size_t(u8(p)) << 24) | (std::size_t(u8(p + 1)) << 16) |
                                 (std::size_t(u8(p + 2)) << 8) | u8(p + 3);
        p += 4;
        if (size > block.size() - p)
            return;
        if (id == 0x0404)
            OIIO::decode_iptc_iim(block.data() + p, static_cast<int>(size), spec);
        at = p + size + (size & 1);
    }
}

} // namespace lut::formats::module
