// SPDX-License-Identifier: Apache-2.0
#include "ErrorText.h"

#include "lut/Limits.h"

#include <utility>

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

std::string humanErrorText(std::string message) {
    using namespace lut::limits;
    const std::pair<std::string, std::string> names[] = {
        {"kMax3DSize",
         "the largest 3D LUT lutkit reads has " + std::to_string(kMax3DSize) + " points per axis"},
        {"kMin3DSize",
         "a 3D LUT needs at least " + std::to_string(kMin3DSize) + " points per axis"},
        {"kMax1DSize",
         "the longest 1D LUT lutkit reads has " + withCommas(kMax1DSize) + " entries"},
        {"kMin1DSize", "a 1D LUT needs at least " + std::to_string(kMin1DSize) + " entries"},
        {"kMaxTextLineBytes",
         "the longest line lutkit reads is " + withCommas(kMaxTextLineBytes) + " bytes"},
        {"kMaxImagePixels",
         "the largest picture lutkit reads has " + withCommas(kMaxImagePixels) + " pixels"},
        {"kMaxLutFileBytes", "the largest LUT file lutkit reads is " +
                                 withCommas(kMaxLutFileBytes / (1u << 20)) + " MB"},
    };
    for (const auto& [name, meaning] : names) {
        for (const std::string& form :
             {"lut::limits::" + name, "limits::" + name, std::string(name)}) {
            for (std::size_t at; (at = message.find(form)) != std::string::npos;)
                message.replace(at, form.size(), meaning);
        }
    }
    return message;
}

} // namespace lut::gui
