#pragma once
// Authoring for the game: the LUT to ship so that Smash Ultimate's grading + brighten pass
// (docs/specs/smash-pipeline.md, "The Smush compensation") shows the edited LUT's look.
#include "lut/Lut3D.h"

namespace lut::gui {

// `edited` maps a gamma-space input s to the gamma-space colour the modder wants on screen.
// Returns the 16^3 LUT L with GetPostProcessingResult(pow(s, 2.2)) == pow(edited(s), 2.2) at
// every lattice input s = i/15 (lut::smashCompensateLut), entries unclamped (the writer
// quantises; values the game cannot reach stay outside [0,1] so callers can report them).
Lut3D smashGameLut(const Lut3D& edited);

} // namespace lut::gui
