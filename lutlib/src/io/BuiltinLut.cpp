// SPDX-License-Identifier: Apache-2.0
#include "lut/io/BuiltinLut.h"

#include "lut/Error.h"

namespace lut {

const std::vector<int>& smashDefaultLutValues() {
    static const std::vector<int> v = {0,   15,  30,  46,  64,  82,  101, 121,
                                       140, 158, 176, 193, 209, 224, 240, 255};
    return v;
}

std::vector<BuiltinLutInfo> builtinLuts() {
    return {{"neutral", "the identity, 16^3", false},
            {"smash-default",
             "Smash Ultimate's stage LUT when a stage has none (the reference renderer's: per "
             "channel 0,15,30,46,64,82,101,121,140,158,176,193,209,224,240,255 of 255, 16^3)",
             true}};
}

bool isBuiltinGameLut(std::string_view path) {
    if (!isBuiltinLutName(path))
        return false;
    const std::string_view name = path.substr(kBuiltinLutPrefix.size());
    for (const BuiltinLutInfo& b : builtinLuts())
        if (b.name == name)
            return b.gameLut;
    return false;
}

bool isBuiltinLutName(std::string_view path) {
    return path.substr(0, kBuiltinLutPrefix.size()) == kBuiltinLutPrefix;
}

Lut3D builtinLut(std::string_view path) {
    const std::string_view name =
        isBuiltinLutName(path) ? path.substr(kBuiltinLutPrefix.size()) : path;
    if (name == "neutral") {
        Lut3D l = Lut3D::identity(16);
        l.setTitle("builtin:neutral");
        return l;
    }
    if (name == "smash-default") {
        const std::vector<int>& v = smashDefaultLutValues();
        const int n = static_cast<int>(v.size());
        Lut3D l(n);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r)
                    l.at(r, g, b) = glm::vec3(static_cast<float>(v[static_cast<std::size_t>(r)]),
                                              static_cast<float>(v[static_cast<std::size_t>(g)]),
                                              static_cast<float>(v[static_cast<std::size_t>(b)])) /
                                    255.0f;
        l.setTitle("builtin:smash-default");
        return l;
    }
    std::string known;
    for (const BuiltinLutInfo& b : builtinLuts())
        known += (known.empty() ? "" : ", ") + std::string(kBuiltinLutPrefix) + b.name;
    throw Error("unknown built-in LUT '" + std::string(path) + "' (known: " + known +
                "; a file named so is ./" + std::string(path) + ")");
}

} // namespace lut
