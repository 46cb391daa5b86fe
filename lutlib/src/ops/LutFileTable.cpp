// SPDX-License-Identifier: Apache-2.0
// LutFile::toLut3D (lut/LutFile.h): the whole file as one 3D table, made here in ops/ because it
// resamples (lut/ops/Resample.h) and interpolates (lut/interp/Sampler.h).
#include "lut/LutFile.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/Resample.h"

#include <memory>

namespace lut {

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

} // namespace lut
