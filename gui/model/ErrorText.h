// SPDX-License-Identifier: Apache-2.0
#pragma once
// Messages for people: library errors name their limits by C++ constant
// ("... over the limit of 256 (lut::limits::kMax3DSize)"); the editor shows what the limit means
// instead ("... (the largest 3D LUT lutkit reads has 256 points per axis)"), told by the error's
// type and its limit (lut/LimitError.h), never by its text. Plain C++ over lutlib.
#include "lut/LimitError.h"

#include <exception>
#include <string>

namespace lut::gui {

// What a limit means, in words.
std::string limitMeaning(LimitId limit);

// e.what(), with the limit it names in words when it is a limit's error.
std::string humanErrorText(const std::exception& e);

} // namespace lut::gui
