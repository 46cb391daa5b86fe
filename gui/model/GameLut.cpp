#include "GameLut.h"

#include "lut/interp/Sampler.h"
#include "lut/pipeline/SmashGrading.h"

namespace lut::gui {

Lut3D smashGameLut(const Lut3D& edited) {
    const int n = kSmashLutSize;
    const auto sampler = makeSampler(edited, Interpolation::Trilinear);
    const Lut3D lattice = Lut3D::identity(n);
    Lut3D target(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 e = sampler->sample(lattice.at(r, g, b));
                target.at(r, g, b) =
                    glm::vec3(smashDecode(e.x), smashDecode(e.y), smashDecode(e.z));
            }
    target.setTitle(edited.title());
    return smashCompensateLut(target);
}

} // namespace lut::gui
