// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "lut/Error.h"
#include "lut/Lut1D.h"
#include "lut/Lut3D.h"
#include "lut/LutPurpose.h"

#include <optional>
#include <string>

namespace lut {

// What a LUT file holds once read: an optional 1D shaper applied first, then an optional 3D
// table (at least one of the two is present), plus what the reader found out about the file.
struct LutFile {
    std::optional<Lut1D> shaper;
    std::optional<Lut3D> cube;

    std::string format;  // registry name of the format that read it ("cube", "nutexb", ...)
    std::string dialect; // e.g. "adobe" or "resolve" for .cube, layout name for images
    Diagnostics diagnostics;
    // Bit depth of the stored values when the source was integer (8, 16), 0 = float.
    int sourceBitDepth = 0;
    // What the file says it is for (lut/LutPurpose.h): its LUTKIT_PURPOSE tag, or its format (a
    // .nutexb is the game's LUT); nullopt when it says nothing. Writers that have a place for it
    // write it (a .cube comment, an image's description).
    std::optional<LutPurpose> purpose;

    // The inputs the file takes: the shaper's domain when it has one, else the table's. Inputs
    // outside it take the edge value.
    glm::vec3 inputDomainMin() const;
    glm::vec3 inputDomainMax() const;

    // The whole file as one 3D table of edge `size` (0 = the cube's own size, else 33) over the
    // input domain: the shaper is baked in by sampling, with no word of what that costs. Pixels
    // are processed with makeSampler(LutFile) (lut/interp/Sampler.h), which runs the shaper then
    // the table exactly; where one lattice is needed, sampleOnLattice (lut/ops/Lattice.h) says
    // the error. Throws lut::Error if the file is empty.
    Lut3D toLut3D(int size = 0) const;
};

// What a command takes the file to be for (lut/LutPurpose.h): `given` (a flag, an answer), else
// what the file says (its tag; a .nutexb by its format), else, when `assumed` is raw, what its
// table says (gameLutEvidence: PurposeSource::Content, smash), else `assumed`.
PurposeDecision decidePurpose(const LutFile& file, std::optional<LutPurpose> given = std::nullopt,
                              LutPurpose assumed = LutPurpose::Raw);

// Whether a table's content says it is the game's LUT made for the default brighten pass (what
// Smush-LUT writes, and any tool that compensates the brighten for the displayed, clipped
// screenshot): the evidence in words, nullopt when it does not. Both must hold:
//   - no value above 187/255: the brighten multiplies by 1.3703, so the entry that shows white
//     is 1/1.3703 = 186.1/255, and no colour the game can show needs more;
//   - flat above the white point: every input the game shows as white (s > 1/1.3703 + 0.001 on
//     an axis) shows the same colour, so along every axis each channel stays within 2 codes over
//     those lattice points (at least two of them: 8^3 lattices and up, over [0,1]).
// An edit meets both only if it darkens white to 187 or less and flattens every channel above
// 0.73 (a hard highlight clamp that dark); docs/roundtrip.md, "What the file says it is for",
// lists the edits measured.
std::optional<std::string> gameLutEvidence(const Lut3D& table);

} // namespace lut
