// SPDX-License-Identifier: Apache-2.0
#pragma once
// The quiet check of a LUT a command just wrote (lut/check/CheckLut.h, default thresholds): one
// warning line on standard error per check that fails, naming its worst finding and how to see
// the whole report (-q keeps them: they are warnings); nothing when every check passes or only
// warns. A command that writes a LUT calls it once, after the write:
//     checkWrittenLut(o.output, file, o.verbosity);
// A game LUT (Smash Ultimate's, compensated for the game's brighten pass) is judged by what the
// game shows with it (lut/smash/SmashShownEdit.h): the command passes the game LUT it wrote
// and shownByGame = true (the compensated table's own numbers, compressed under 0.73 and clipped
// there, say nothing about the look).
#include "Notes.h"

#include "lut/LutFile.h"

#include <string>

namespace lut::cli {

void checkWrittenLut(const std::string& path, const LutFile& written, const Verbosity& verbosity,
                     bool shownByGame = false);
void checkWrittenLut(const std::string& path, const Lut3D& written, const Verbosity& verbosity,
                     bool shownByGame = false);

} // namespace lut::cli
