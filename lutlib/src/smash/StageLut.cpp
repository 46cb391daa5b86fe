// SPDX-License-Identifier: Apache-2.0
#include "lut/smash/StageLut.h"

#include "lut/ops/Lattice.h"
#include "lut/smash/SmashConstants.h"

namespace lut {

StageLutFile stageLutFromFile(const LutFile& file, const std::string& path) {
    StageLutFile out;
    if (!file.shaper) {
        if (!file.cube)
            throw Error("the LUT file holds no table");
        out.lut = *file.cube;
        return out;
    }
    LatticeRequest q;
    q.size = kSmashLutSize;
    q.domainMin = glm::vec3(0.0f);
    q.domainMax = glm::vec3(1.0f);
    q.readWith = Interpolation::Trilinear;
    LatticeResult r = sampleOnLattice(file, q);
    r.error.seconds = 0.0;
    Diagnostic d;
    d.severity =
        r.error.maxSteps8() > 1.0 ? Diagnostic::Severity::Warning : Diagnostic::Severity::Info;
    d.path = path;
    d.message = std::string("its 1D shaper") +
                (file.cube ? " and " + std::to_string(file.cube->size()) + "^3 table" : "") +
                " sampled at the game's " + std::to_string(kSmashLutSize) +
                "^3 lattice over [0,1] (read trilinearly): " + r.error.str() + " on " +
                std::to_string(r.heldOut) + " inputs between lattice points";
    out.diagnostics.push_back(std::move(d));
    out.lut = std::move(r.lut);
    return out;
}

} // namespace lut
