// SPDX-License-Identifier: Apache-2.0
#pragma once
// The linear Monge-Kantorovich colour map (F. Pitié and A. Kokaram, "The linear
// Monge-Kantorovitch linear colour mapping for example-based colour transfer", IET CVMP 2007):
// the affine map x -> T (x - mean_src) + mean_ref that takes a distribution of covariance
// S_src to one of covariance S_ref with the least mean squared displacement,
//     T = S_src^-1/2 (S_src^1/2 S_ref S_src^1/2)^1/2 S_src^-1/2.
// T is symmetric positive definite: the map never folds colours over. lutkit keeps its eigenvalues
// (the gains along its principal axes) in [1/maxGain, maxGain], so a source with almost no
// spread in some direction (an almost grey picture) does not have its noise turned into colour.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace lut {

// Weighted mean and covariance of a set of colours.
class ColourMoments {
public:
    void add(const glm::dvec3& colour, double weight = 1.0);
    void merge(const ColourMoments& other);
    double weight() const { return m_weight; }
    glm::dvec3 mean() const;
    glm::dmat3 covariance() const; // zero when the weight is zero

private:
    double m_weight = 0.0;
    glm::dvec3 m_sum{0.0};
    glm::dmat3 m_sumSquares{0.0}; // sum of w x x^T
};

struct AffineColourMap {
    glm::dmat3 matrix{1.0}; // column-major, as GLM: y = matrix * x + offset
    glm::dvec3 offset{0.0};
    glm::dvec3 operator()(const glm::dvec3& x) const { return matrix * x + offset; }
};

struct MklNotes {
    bool gainLimited = false; // an eigenvalue of T was moved into [1/maxGain, maxGain]
    double largestGain = 1.0; // eigenvalues of T before limiting
    double smallestGain = 1.0;
    double sourceSpread = 0.0; // sqrt of the smallest eigenvalue of S_src (the flattest direction)
};

// The MKL map; `maxGain` >= 1. Covariances are floored at `floor` (variance units) in every
// direction before the square roots, so flat distributions give finite maps.
AffineColourMap mongeKantorovich(const ColourMoments& source, const ColourMoments& reference,
                                 double maxGain = 4.0, double floor = 1e-8,
                                 MklNotes* notes = nullptr);

// Eigen-decomposition of a symmetric 3x3 matrix (Jacobi rotations, double precision):
// m = vectors * diag(values) * transpose(vectors), eigenvectors in the columns.
void symmetricEigen(const glm::dmat3& m, glm::dvec3& values, glm::dmat3& vectors);

} // namespace lut
