#pragma once
// What a round-trip LUT is for (docs/roundtrip.md): the edit itself, for engines that apply the
// LUT to the displayed picture, or the game's LUT that makes Smash Ultimate show the edit.
#include <string_view>

namespace lut {

enum class ExtractTarget {
    Raw,   // "raw": the edit itself (Pilot, Unreal, Unity apply the LUT to the displayed image)
    Smash, // "smash": compensated for the game's grading and brighten step (the nutexb)
};
const char* toString(ExtractTarget);
ExtractTarget parseTarget(std::string_view name); // "raw", "smash"; throws lut::Error

} // namespace lut
