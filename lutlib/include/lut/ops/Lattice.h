// SPDX-License-Identifier: Apache-2.0
#pragma once
// A LUT file (a 1D shaper, then a 3D table) as one 3D table, where one lattice is truly needed:
// the game's 16^3 LUT, a format that stores no shaper, a lattice to invert. Each entry is the
// file evaluated exactly (makeSampler(LutFile): the shaper, then the table) at its lattice input,
// and the cost of reading the lattice instead of the file is bounded over the whole domain
// (boundError, lut/ops/ErrorBound.h): held-out points between the lattice points (never at them,
// where the lattice is exact by construction), plus the slope between them, on a grid whose planes
// include the lattice's, the shaper's entries and where the shaper crosses the table's planes.
// The maximum is an upper bound over every input of the domain, the mean a mean over it.
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/interp/Interpolation.h"
#include "lut/ops/ErrorBound.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <optional>

namespace lut {

struct LatticeRequest {
    int size = 0; // edge of the lattice; 0 = the file's table's size (33 for a 1D-only file)
    // The lattice's domain; unset = the file's input domain (LutFile::inputDomainMin/Max).
    std::optional<glm::vec3> domainMin, domainMax;
    Interpolation fileMethod = Interpolation::Tetrahedral; // how the file's table is evaluated
    // How the lattice will be read (the game: trilinear).
    Interpolation readWith = Interpolation::Tetrahedral;
    int nthreads = 0; // 0 = all cores
    // What the lattice holds at input x given the file's value y there (a strength blend with
    // neutral: lut::blendStrength); empty = y. The error is measured against finish(x, file(x)).
    std::function<glm::dvec3(const glm::dvec3& x, const glm::dvec3& y)> finish;
};

struct LatticeResult {
    Lut3D lut;
    // The lattice read with readWith against the exact file: maxAbs bounds it over the domain.
    ErrorStats error;
    std::size_t heldOut = 0; // inputs the error was measured on
};

// Where the file, evaluated exactly, kinks inside (lo, hi), per axis in input coordinates: its
// shaper's entries and where the shaper crosses its table's planes (at most 256 per axis), or a
// table alone's lattice planes. What a bound needs among its grid's planes (ErrorBound.h).
Breaks fileBreaks(const LutFile& file, glm::vec3 lo, glm::vec3 hi);

// Throws lut::Error if the file is empty or the domain is not finite with min < max.
LatticeResult sampleOnLattice(const LutFile& file, const LatticeRequest& request = {});

// The same finish (request.finish) applied keeping the file's 1D shaper S: its table's entry at u
// becomes finish(x, T(u)) with x = S^-1(u), per channel (S inverted exactly, piecewise linear), so
// the result is a shaper and a table of the file's sizes. The error against finish(x, file(x)) is
// bounded over request's domain (default: the file's input domain) as sampleOnLattice bounds it.
// nullopt when the file has no shaper and table, or S is not strictly increasing on every channel
// over that domain (no one x per u: sampleOnLattice then).
struct ShaperLatticeResult {
    LutFile file;
    ErrorStats error;
};
std::optional<ShaperLatticeResult> finishKeepingShaper(const LutFile& file,
                                                       const LatticeRequest& request);

} // namespace lut
