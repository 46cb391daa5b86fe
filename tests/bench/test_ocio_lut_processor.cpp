// SPDX-License-Identifier: Apache-2.0
// lut/bench/OcioLutProcessor.h (bench/support): OpenColorIO's processor as `lutkit bench` sets it
// up must hold the LUT in the right order and run the interpolation it was asked for, or the
// speed comparison compares different work. Oracle: the interpolation formulas at points where
// they are simple, written here (a lattice point returns its entry; at a cell's centre trilinear
// is the mean of the 8 corners and tetrahedral the mean of c000 and c111).
#include "lut/bench/OcioLutProcessor.h"

#include <gtest/gtest.h>

#include <random>

using namespace lut;

namespace {

Lut3D randomLut(int n) {
    Lut3D lut(n);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (auto& e : lut.entries())
        e = glm::vec3(u(rng), u(rng), u(rng));
    return lut;
}

glm::vec3 run(const OcioLutProcessor& p, glm::vec3 in, float alpha = 0.25f) {
    Image img(1, 1);
    float* px = img.pixel(0, 0);
    px[0] = in.r;
    px[1] = in.g;
    px[2] = in.b;
    px[3] = alpha;
    p.apply(img);
    EXPECT_EQ(px[3], alpha);
    return glm::vec3(px[0], px[1], px[2]);
}

void expectNear(glm::vec3 got, glm::vec3 want, float tol, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], tol) << what << " channel " << c;
}

} // namespace

TEST(OcioLutProcessor, LatticePointsReturnTheirEntries) {
    const int n = 5;
    const Lut3D lut = randomLut(n);
    for (Interpolation m : {Interpolation::Trilinear, Interpolation::Tetrahedral}) {
        const OcioLutProcessor p(lut, m);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r)
                    expectNear(run(p, glm::vec3(r, g, b) / float(n - 1)), lut.at(r, g, b), 1e-5f,
                               "lattice point");
    }
}

TEST(OcioLutProcessor, RunsTheInterpolationItWasAskedFor) {
    const int n = 3;
    const Lut3D lut = randomLut(n);
    const glm::vec3 centre(0.25f, 0.75f, 0.25f); // centre of cell (0, 1, 0)
    glm::vec3 mean8(0.0f);
    for (int db = 0; db < 2; ++db)
        for (int dg = 0; dg < 2; ++dg)
            for (int dr = 0; dr < 2; ++dr)
                mean8 += lut.at(dr, 1 + dg, db) / 8.0f;
    const glm::vec3 diagonal = (lut.at(0, 1, 0) + lut.at(1, 2, 1)) * 0.5f;
    expectNear(run(OcioLutProcessor(lut, Interpolation::Trilinear), centre), mean8, 1e-5f,
               "trilinear");
    expectNear(run(OcioLutProcessor(lut, Interpolation::Tetrahedral), centre), diagonal, 1e-5f,
               "tetrahedral");
}
