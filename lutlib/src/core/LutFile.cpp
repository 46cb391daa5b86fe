// SPDX-License-Identifier: Apache-2.0
#include "lut/LutFile.h"

#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/Resample.h"

namespace lut {

glm::vec3 LutFile::inputDomainMin() const {
    return shaper ? shaper->domainMin() : cube ? cube->domainMin() : glm::vec3(0.0f);
}

glm::vec3 LutFile::inputDomainMax() const {
    return shaper ? shaper->domainMax() : cube ? cube->domainMax() : glm::vec3(1.0f);
}

Lut3D LutFile::toLut3D(int size) const {
    if (!cube && !shaper)
        throw Error("the LUT file holds no table");
    if (!shaper) {
        if (size == 0 || size == cube->size())
            return *cube;
        return resample(*cube, size, Interpolation::Tetrahedral);
    }
    if (size == 0)
        size = cube ? cube->size() : 33;
    // Bake: the lattice spans the shaper's input domain; each point goes through the shaper,
    // then the cube.
    Lut3D out(size);
    out.setDomain(shaper->domainMin(), shaper->domainMax());
    out.setTitle(cube ? cube->title() : shaper->title());
    if (cube)
        out.comments() = cube->comments();
    std::unique_ptr<Sampler> sampler;
    if (cube)
        sampler = makeSampler(*cube, Interpolation::Tetrahedral);
    parallelFor(size, 0, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r) {
                    glm::vec3 v = shaper->apply(out.latticeInput(r, g, b));
                    if (sampler)
                        v = sampler->sample(v);
                    out.at(r, g, b) = v;
                }
    });
    return out;
}

PurposeDecision decidePurpose(const LutFile& file, std::optional<LutPurpose> given,
                              LutPurpose assumed) {
    PurposeDecision d = decidePurpose(file.purpose, file.format == "nutexb", given, assumed);
    if (d.source == PurposeSource::File && file.format == "builtin")
        d.source = PurposeSource::Builtin; // builtin:smash-default says so by its name
    return d;
}

} // namespace lut
