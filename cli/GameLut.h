#pragma once
// The game's LUT from an edit given as a LUT (a graded strip such as Smush-LUT's neutral.png, a
// .cube): lutkit convert --target smash and lutkit extract on a LUT image both make it with
// lut::authorSmashLutForEdit and say the same about it.
#include "Notes.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/interp/Interpolation.h"
#include "lut/pipeline/SmashAuthoring.h"

#include <optional>
#include <ostream>
#include <string>

namespace lut::cli {

struct GameLutRequest {
    std::string stageLut;   // --original-lut: the stage's LUT ("" = neutral)
    std::string screenshot; // --screenshot: the colours that occur ("" = the input grid)
    bool refine = false;    // --refine: ship the least-squares refinement
    Interpolation interp = Interpolation::Tetrahedral; // how the edit is evaluated
};

// Reads the stage LUT and the screenshot the request names, authors the game's LUT for `edit`
// and prints what the game will show (exact composition and refinement, 8-bit display steps,
// over which colours) to `os`. Returns the LUT to write.
Lut3D makeGameLut(const Lut3D& edit, const GameLutRequest& request, const Verbosity& verbosity,
                  std::ostream& os, SmashAuthoringResult* result = nullptr);
// The same for an edit given as a LUT file: a file with a 1D shaper is evaluated exactly (the
// shaper, then its table) wherever the game's LUT is computed and measured, never merged into one
// table first.
Lut3D makeGameLut(const LutFile& edit, const GameLutRequest& request, const Verbosity& verbosity,
                  std::ostream& os, SmashAuthoringResult* result = nullptr);

} // namespace lut::cli
