// SPDX-License-Identifier: Apache-2.0
// The marker frame's header bits, CRC and rings; see MarkerFrame.h.
#include "roundtrip/MarkerFrame.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <cstdint>
#include <string>

namespace lut::detail {

namespace {

constexpr std::uint64_t kSyncV1 = 0xB2;
constexpr std::uint64_t kSyncV2 = 0xB5;

// CRC-8, polynomial 0x07, over the `bits` low bits of value, most significant first.
std::uint8_t crc8(std::uint64_t value, int bits) {
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
    switch (layoutPlacement(l)) { // the 1024x32 names place pixels as unreal and unity
    case LutLayout::Pilot:
        return 0;
    case LutLayout::Unity:
        return 1;
    case LutLayout::Smush:
        return 2;
    case LutLayout::Hald:
        return 3;
    case LutLayout::Reshade:
    case LutLayout::Unity32:
        break;
    }
    return 0;
}
LutLayout layoutFromCode(int c) {
    static const LutLayout ls[4] = {LutLayout::Pilot, LutLayout::Unity, LutLayout::Smush,
                                    LutLayout::Hald};
    return ls[c & 3];
}
int latticeCode(PatchLattice l) {
    return l == PatchLattice::Uniform ? 0 : l == PatchLattice::Smash ? 1 : 2;
}

std::uint64_t bitsValue(const HeaderBits& bits, int from, int to) {
    std::uint64_t v = 0;
    for (int i = from; i < to; ++i)
        v = (v << 1) | static_cast<std::uint64_t>(bits[i] & 1);
    return v;
}

} // namespace

int headerBitCount(int version) {
    return version == 1 ? 35 : version == 2 ? 55 : 0;
}
int geometryBitCount(int version) {
    return version == 1 ? 22 : version == 2 ? 23 : 0;
}

int versionFromSync(const HeaderBits& bits) {
    const std::uint64_t sync = bitsValue(bits, 0, kSyncBits);
    return sync == kSyncV1 ? 1 : sync == kSyncV2 ? 2 : 0;
}

HeaderBits headerBits(const MarkerHeader& h) {
    const int version = h.version == 1 ? 1 : 2;
    std::uint64_t v = version == 1 ? kSyncV1 : kSyncV2;
    if (version == 1) {
        v = (v << 1) | (h.lattice == PatchLattice::Uniform ? 0u : 1u);
    } else {
        v = (v << 2) | static_cast<std::uint64_t>(latticeCode(h.lattice));
    }
    v = (v << 2) | static_cast<std::uint64_t>(depthCode(h.bitDepth));
    v = (v << 2) | static_cast<std::uint64_t>(layoutCode(h.layout));
    v = (v << 9) | static_cast<std::uint64_t>(h.size & 511);
    v = (v << 5) | static_cast<std::uint64_t>(h.scale & 31);
    if (version == 2) {
        const std::uint64_t target = !h.target ? 0u : *h.target == LutPurpose::Raw ? 1u : 2u;
        v = (v << 2) | target;
        v = (v << 1) | (h.stageDigest ? 1u : 0u);
        v = (v << 16) | (h.stageDigest ? *h.stageDigest : 0u);
    }
    const int payload = headerBitCount(version) - 8;
    const std::uint8_t crc = crc8(v, payload);
    HeaderBits bits{};
    for (int i = 0; i < payload; ++i)
        bits[i] = static_cast<int>((v >> (payload - 1 - i)) & 1u);
    for (int i = 0; i < 8; ++i)
        bits[payload + i] = (crc >> (7 - i)) & 1;
    return bits;
}

bool decodeGeometry(const HeaderBits& bits, MarkerHeader& h) {
    const int version = versionFromSync(bits);
    if (version == 0)
        return false;
    const int geometry = geometryBitCount(version);
    const std::uint64_t v = bitsValue(bits, kSyncBits, geometry);
    // after the sync: lattice (1 or 2) | depth (2) | layout (2) | N (9)
    const int size = static_cast<int>(v & 511u);
    const int layout = static_cast<int>((v >> 9) & 3u);
    const int depth = static_cast<int>((v >> 11) & 3u);
    const int latticeField = static_cast<int>(v >> 13);
    if (depth == 3 || size < limits::kMin3DSize || size > limits::kMax3DSize || latticeField > 2)
        return false;
    const PatchLattice lattice = latticeField == 0   ? PatchLattice::Uniform
                                 : latticeField == 1 ? PatchLattice::Smash
                                                     : PatchLattice::SmashStage;
    if (lattice == PatchLattice::Smash && size != kSmashLatticeSize)
        return false;
    h.version = version;
    h.lattice = lattice;
    h.bitDepth = depthFromCode(depth);
    h.layout = layoutFromCode(layout);
    h.size = size;
    return true;
}

bool decodeHeader(const HeaderBits& bits, MarkerHeader& h) {
    const int version = versionFromSync(bits);
    if (version == 0 || version != h.version)
        return false;
    const int total = headerBitCount(version), payload = total - 8;
    const std::uint64_t all = bitsValue(bits, 0, payload);
    const std::uint64_t crc = bitsValue(bits, payload, total);
    if (crc8(all, payload) != crc)
        return false;
    const int afterScale = version == 1 ? 0 : 19; // target (2) + digest flag (1) + digest (16)
    const int scale = static_cast<int>((all >> afterScale) & 31u);
    if (scale < 1)
        return false;
    h.scale = scale;
    h.target.reset();
    h.stageDigest.reset();
    if (version == 2) {
        const int target = static_cast<int>((all >> 17) & 3u);
        if (target == 3)
            return false;
        if (target != 0)
            h.target = target == 1 ? LutPurpose::Raw : LutPurpose::Smash;
        if ((all >> 16) & 1u)
            h.stageDigest = static_cast<std::uint16_t>(all & 0xFFFFu);
    }
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
