// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: a dip along grey repaired on the table rather than a reason to fall
// back to another method (issue 42). With the table alone and one domain for the three channels,
// grey is the table's diagonal, and tetrahedral interpolation is linear between its nodes (every
// tetrahedron of a cell holds the diagonal as an edge): grey goes up in every channel exactly when
// the diagonal's nodes do. Each channel's diagonal is replaced by its closest non-decreasing
// sequence (least squares, pool adjacent violators: the nodes of a dip and those around it take
// their mean), and the nodes near the diagonal move with it, fading out 3 nodes away: the repair
// is local and does not turn a channel's own axis down next to the diagonal.
#include "lut/Lut3D.h"

namespace lut::detail {

struct GreyRepair {
    int nodesMoved = 0;     // diagonal nodes changed (any channel)
    double largestMove = 0; // the most a node's channel moved, 8-bit steps of the table's values
};

GreyRepair repairGreyDip(Lut3D& table);

} // namespace lut::detail
