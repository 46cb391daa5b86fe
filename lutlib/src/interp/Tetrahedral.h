#pragma once
// The tetrahedral blend of one lattice cell, shared by the scalar sampler and the extracted
// patch function (Embed.cpp), so both interpolate identically.
#include <glm/vec3.hpp>

namespace lut::detail {

// e(r, g, b) returns the entry at a lattice point; (r, g, b) is the cell's lower corner and
// fr, fg, fb in [0, 1] the position inside it. The cube is split into six tetrahedra by the order
// of the fractions; each shares the main diagonal c000-c111, so greys stay on it. Every weight is
// a difference of fractions, so a corner is returned exactly.
template <class Entry>
glm::vec3 tetrahedralBlend(const Entry& e, int r, int g, int b, float fr, float fg, float fb) {
    const glm::vec3 c000 = e(r, g, b);
    const glm::vec3 c111 = e(r + 1, g + 1, b + 1);
    if (fr > fg) {
        if (fg > fb)
            return (1 - fr) * c000 + (fr - fg) * e(r + 1, g, b) + (fg - fb) * e(r + 1, g + 1, b) +
                   fb * c111;
        if (fr > fb)
            return (1 - fr) * c000 + (fr - fb) * e(r + 1, g, b) + (fb - fg) * e(r + 1, g, b + 1) +
                   fg * c111;
        return (1 - fb) * c000 + (fb - fr) * e(r, g, b + 1) + (fr - fg) * e(r + 1, g, b + 1) +
               fg * c111;
    }
    if (fb > fg)
        return (1 - fb) * c000 + (fb - fg) * e(r, g, b + 1) + (fg - fr) * e(r, g + 1, b + 1) +
               fr * c111;
    if (fb > fr)
        return (1 - fg) * c000 + (fg - fb) * e(r, g + 1, b) + (fb - fr) * e(r, g + 1, b + 1) +
               fr * c111;
    return (1 - fg) * c000 + (fg - fr) * e(r, g + 1, b) + (fr - fb) * e(r + 1, g + 1, b) +
           fb * c111;
}

} // namespace lut::detail
