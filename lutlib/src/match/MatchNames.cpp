// SPDX-License-Identifier: Apache-2.0
// The names users type for match's methods and what it preserves (lut/match/MatchOptions.h).
#include "lut/Error.h"
#include "lut/match/MatchOptions.h"

namespace lut {

const char* toString(MatchMethod m) {
    switch (m) {
    case MatchMethod::Auto:
        return "auto";
    case MatchMethod::Hm:
        return "hm";
    case MatchMethod::Mkl:
        return "mkl";
    case MatchMethod::HmMklHm:
        return "hm-mkl-hm";
    case MatchMethod::Regularised:
        return "regularised";
    case MatchMethod::GradientMap:
        return "gradient-map";
    }
    return "auto";
}

const std::vector<MatchMethod>& allMatchMethods() {
    static const std::vector<MatchMethod> all = {
        MatchMethod::Auto,    MatchMethod::Hm,          MatchMethod::Mkl,
        MatchMethod::HmMklHm, MatchMethod::Regularised, MatchMethod::GradientMap};
    return all;
}

std::vector<std::string> matchMethodAliases(MatchMethod m) {
    if (m == MatchMethod::Regularised)
        return {"regularized"};
    return {};
}

MatchMethod parseMatchMethod(std::string_view name) {
    for (MatchMethod m : allMatchMethods()) {
        if (name == toString(m))
            return m;
        for (const auto& a : matchMethodAliases(m))
            if (name == a)
                return m;
    }
    throw Error("unknown match method '" + std::string(name) +
                "' (expected auto, hm, mkl, hm-mkl-hm, regularised or gradient-map)");
}

const char* toString(MatchPreserve p) {
    switch (p) {
    case MatchPreserve::Luma:
        return "luma";
    case MatchPreserve::Neutrals:
        return "neutrals";
    case MatchPreserve::Skin:
        return "skin";
    }
    return "luma";
}

const std::vector<MatchPreserve>& allMatchPreserves() {
    static const std::vector<MatchPreserve> all = {MatchPreserve::Luma, MatchPreserve::Neutrals,
                                                   MatchPreserve::Skin};
    return all;
}

MatchPreserve parseMatchPreserve(std::string_view name) {
    for (MatchPreserve p : allMatchPreserves())
        if (name == toString(p))
            return p;
    throw Error("unknown preserve '" + std::string(name) + "' (expected luma, neutrals or skin)");
}

} // namespace lut
