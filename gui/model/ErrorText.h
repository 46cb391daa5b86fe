// SPDX-License-Identifier: Apache-2.0
#pragma once
// Messages for people: library errors name their limits by C++ constant
// ("... over the limit of 256 (lut::limits::kMax3DSize)"); the editor shows what the limit means
// instead ("... (the largest LUT lutkit reads has 256 points per axis)"). Plain C++ over lutlib.
#include <string>

namespace lut::gui {

std::string humanErrorText(std::string message);

} // namespace lut::gui
