// SPDX-License-Identifier: Apache-2.0
#include "ErrorText.h"

#include "lut/Limits.h"

namespace lut::gui {

namespace {

std::string withCommas(unsigned long long v) {
    std::string s = std::to_string(v), out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (i && (s.size() - i) % 3 == 0)
            out += ',';
        out += s[i];
    }
    return out;
}

} // namespace

std::string limitMeaning(LimitId limit) {
    using namespace lut::limits;
    switch (limit) {
    case LimitId::Max3DSize:
        return "the largest 3D LUT lutkit reads has " + std::to_string(kMax3DSize) +
               " points per axis";
    case LimitId::Max1DSize:
        return "the longest 1D LUT lutkit reads has " + withCommas(kMax1DSize) + " entries";
    case LimitId::MaxTextLineBytes:
        return "the longest line lutkit reads is " + withCommas(kMaxTextLineBytes) + " bytes";
    case LimitId::MaxLutFileBytes:
        return "the largest LUT file lutkit reads is " + withCommas(kMaxLutFileBytes / (1u << 20)) +
               " MB";
    }
    return limitName(limit);
}

std::string humanErrorText(const std::exception& e) {
    if (const auto* limit = dynamic_cast<const LimitExceeded*>(&e))
        return limit->whatWith(limitMeaning(limit->limit()));
    return e.what();
}

} // namespace lut::gui
