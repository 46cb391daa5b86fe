#pragma once
// Reading a found round-trip patch: what the edit did to each lattice input (PatchReading), and
// the edit as a function of any input (PatchFunction).
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace lut {

// What the patch says before any target is applied.
struct PatchReading {
    PatchPlacement placement;
    Lut3D values; // the edit E at the patch lattice, entry (r,g,b) = E(axis[r], axis[g], axis[b])
    std::vector<float> axis;        // input value of each lattice index (quantised neutral values)
    double blockMaxDeviation = 0.0; // largest pixel deviation from its block mean (8-bit steps)
    std::size_t nonUniformBlocks = 0; // blocks with a deviation above 2.5 8-bit steps
};
// Throws lut::Error when the placement does not fit inside the image.
PatchReading readPatch(const ImageView& image, const PatchPlacement& placement);

// Evaluates the edit the patch measured at any input: tetrahedral interpolation on the patch's
// (rectilinear, possibly quantised) lattice, clamped to the patch's input range.
class PatchFunction {
public:
    // Throws lut::Error when the axis and the table sizes differ or are below 2.
    PatchFunction(const Lut3D& values, std::vector<float> axis);
    glm::vec3 operator()(glm::vec3 in) const;

private:
    Lut3D m_values;
    std::vector<float> m_axis;
};

} // namespace lut
