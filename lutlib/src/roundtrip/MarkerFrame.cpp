// The marker frame's header bits, CRC and rings; see MarkerFrame.h.
#include "roundtrip/MarkerFrame.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <cstdint>
#include <string>

namespace lut::detail {

namespace {

constexpr std::uint32_t kSync = 0xB2;

// CRC-8, polynomial 0x07, over the `bits` low bits of value, most significant first.
std::uint8_t crc8(std::uint32_t value, int bits) {
    std::uint8_t crc = 0;
    for (int i = bits - 1; i >= 0; --i) {
        const bool bit = ((value >> i) & 1u) != 0;
        const bool top = (crc & 0x80u) != 0;
        crc = static_cast<std::uint8_t>(crc << 1);
        if (bit != top)
            crc ^= 0x07u;
    }
    return crc;
}

int depthCode(int bitDepth) {
    return bitDepth == 8 ? 0 : bitDepth == 16 ? 1 : 2;
}
int depthFromCode(int code) {
    return code == 0 ? 8 : code == 1 ? 16 : 32;
}
int layoutCode(LutLayout l) {
    switch (l) {
    case LutLayout::Pilot:
        return 0;
    case LutLayout::Unity:
        return 1;
    case LutLayout::Smush:
        return 2;
    case LutLayout::Hald:
        return 3;
    }
    return 0;
}
LutLayout layoutFromCode(int c) {
    static const LutLayout ls[4] = {LutLayout::Pilot, LutLayout::Unity, LutLayout::Smush,
                                    LutLayout::Hald};
    return ls[c & 3];
}

std::uint32_t bitsValue(const HeaderBits& bits, int from, int to) {
    std::uint32_t v = 0;
    for (int i = from; i < to; ++i)
        v = (v << 1) | static_cast<std::uint32_t>(bits[i]);
    return v;
}

} // namespace

HeaderBits headerBits(const MarkerHeader& h) {
    std::uint32_t v = kSync;
    v = (v << 1) | (h.lattice == PatchLattice::Smash ? 1u : 0u);
    v = (v << 2) | static_cast<std::uint32_t>(depthCode(h.bitDepth));
    v = (v << 2) | static_cast<std::uint32_t>(layoutCode(h.layout));
    v = (v << 9) | static_cast<std::uint32_t>(h.size & 511);
    v = (v << 5) | static_cast<std::uint32_t>(h.scale & 31);
    const std::uint8_t crc = crc8(v, kPayloadBits);
    HeaderBits bits{};
    for (int i = 0; i < kPayloadBits; ++i)
        bits[i] = static_cast<int>((v >> (kPayloadBits - 1 - i)) & 1u);
    for (int i = 0; i < 8; ++i)
        bits[kPayloadBits + i] = (crc >> (7 - i)) & 1;
    return bits;
}

bool decodeGeometry(const HeaderBits& bits, MarkerHeader& h) {
    const std::uint32_t v = bitsValue(bits, 0, kGeometryBits);
    if ((v >> 14) != kSync)
        return false;
    const PatchLattice lattice = ((v >> 13) & 1u) ? PatchLattice::Smash : PatchLattice::Uniform;
    const int depth = static_cast<int>((v >> 11) & 3u);
    const int size = static_cast<int>(v & 511u);
    if (depth == 3 || size < limits::kMin3DSize || size > limits::kMax3DSize)
        return false;
    if (lattice == PatchLattice::Smash && size != kSmashLatticeSize)
        return false;
    h.lattice = lattice;
    h.bitDepth = depthFromCode(depth);
    h.layout = layoutFromCode(static_cast<int>((v >> 9) & 3u));
    h.size = size;
    return true;
}

bool decodeHeader(const HeaderBits& bits, MarkerHeader& h) {
    const std::uint32_t all = bitsValue(bits, 0, kPayloadBits);
    const std::uint32_t crc = bitsValue(bits, kPayloadBits, kHeaderBits);
    if (crc8(all, kPayloadBits) != crc)
        return false;
    const int scale = static_cast<int>(all & 31u);
    if (scale < 1)
        return false;
    h.scale = scale;
    return true;
}

void patchCells(LutLayout layout, int size, int& cw, int& ch) {
    layoutImageSize(layout, size, cw, ch);
}

std::vector<std::pair<int, int>> innerRing(int fw, int fh) {
    std::vector<std::pair<int, int>> cells;
    for (int x = 1; x <= fw - 2; ++x)
        cells.emplace_back(x, 1);
    for (int y = 2; y <= fh - 2; ++y)
        cells.emplace_back(fw - 2, y);
    for (int x = fw - 3; x >= 1; --x)
        cells.emplace_back(x, fh - 2);
    for (int y = fh - 3; y >= 2; --y)
        cells.emplace_back(1, y);
    return cells;
}

} // namespace lut::detail

namespace lut {

void patchFrameSize(LutLayout layout, int size, int scale, int& width, int& height) {
    if (size < limits::kMin3DSize || size > limits::kMax3DSize)
        throw Error("patch size " + std::to_string(size) + " is out of range (" +
                    std::to_string(limits::kMin3DSize) + ".." + std::to_string(limits::kMax3DSize) +
                    ")");
    if (scale < 1 || scale > kMaxPatchScale)
        throw Error("patch scale " + std::to_string(scale) + " is out of range (1.." +
                    std::to_string(kMaxPatchScale) + ")");
    int cw = 0, ch = 0;
    detail::patchCells(layout, size, cw, ch);
    if (cw + 2 < detail::kMinHeaderRow)
        throw Error(
            std::string("a ") + std::to_string(size) + "^3 patch in the " + toString(layout) +
            " layout is too narrow for the marker header (use size >= 5, or >= 9 for hald)");
    width = (cw + 4) * scale;
    height = (ch + 4) * scale;
}

} // namespace lut
