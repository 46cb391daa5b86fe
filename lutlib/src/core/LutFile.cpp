// SPDX-License-Identifier: Apache-2.0
// LutFile's domain; the table it stands for (toLut3D) is made in ops/LutFileTable.cpp (it
// resamples and interpolates), what it is for (decidePurpose, gameLutEvidence) in
// smash/GameLutEvidence.cpp (the game's numbers): core depends on no room above it.
#include "lut/LutFile.h"

namespace lut {

glm::vec3 LutFile::inputDomainMin() const {
    return shaper ? shaper->domainMin() : cube ? cube->domainMin() : glm::vec3(0.0f);
}

glm::vec3 LutFile::inputDomainMax() const {
    return shaper ? shaper->domainMax() : cube ? cube->domainMax() : glm::vec3(1.0f);
}

} // namespace lut
