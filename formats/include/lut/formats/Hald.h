// SPDX-License-Identifier: Apache-2.0
#pragma once
// Hald CLUT sizes, as ImageMagick names them: a Hald image of level L is L^3 x L^3 pixels and
// holds an N^3 LUT with N = L^2 (hald:8 is 512x512, a 64^3 LUT). lutkit's --size N means the
// lattice (N^3) everywhere; --level L asks for a Hald of level L. Messages name both.
#include <string>

namespace lut::formats {

constexpr int kMinHaldLevel = 2;
constexpr int kMaxHaldLevel = 16; // N = 256, the largest lattice lutkit holds

// The lattice size to write for a requested size: itself when it is L^2 (L >= 2), else the next
// larger square, capped at 256.
int haldSizeFor(int size);
// L for N = L^2 (rounded down for a size that is not a square).
int haldLevelOf(int size);
// "64^3 (Hald level 8, 512x512)"
std::string haldSizeText(int size);

} // namespace lut::formats
