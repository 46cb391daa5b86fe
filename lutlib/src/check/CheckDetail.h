// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's LUT check (lut/check/CheckLut.h): what its parts share. The check works
// on "table coordinates" u in [0, 1]^3 (the 3D table's lattice point (i, j, k) is at
// (i, j, k) / (N - 1)); Context maps them back to the file's input colours through the shaper.
#include "lut/Lut1D.h"
#include "lut/Lut3D.h"
#include "lut/check/CheckLut.h"
#include "lut/interp/Sampler.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace lut::check {

// What every part of the check works on: the file's function (shaper, then table) with NaN
// counted as 0, and how much each cell of the table weighs (its volume, or its share of a
// picture's pixels).
class Context {
public:
    Context(const LutFile& file, const CheckOptions& options);

    const CheckOptions& options() const { return *m_options; }
    const CheckThresholds& thresholds() const { return m_options->thresholds; }
    int nthreads() const { return m_options->nthreads; }

    bool hasTable() const { return m_table.has_value(); }
    const Lut3D& table() const { return *m_table; }      // sanitized
    const Lut3D* rawTable() const { return m_rawTable; } // as the file has it (NaN kept)
    const std::shared_ptr<const Lut1D>& shaper() const { return m_shaper; } // sanitized
    const Lut1D* rawShaper() const { return m_rawShaper; }
    int size() const { return m_n; } // the table's edge (0 without one)
    int cellsPerAxis() const { return m_n - 1; }
    glm::vec3 inputMin() const { return m_inMin; } // the file's input domain
    glm::vec3 inputMax() const { return m_inMax; }

    // The file's function at an input colour (NaN entries counted as 0).
    glm::vec3 evaluate(glm::vec3 input) const;
    // In place over many colours, on all cores.
    void evaluate(std::vector<glm::vec3>& colours) const;
    // Table coordinates -> the file's input colour (through the shaper's inverse) and back.
    glm::vec3 fileInput(glm::vec3 u) const;
    glm::vec3 tableCoordinates(glm::vec3 input) const;

    // Cells: index r + (N - 1) (g + (N - 1) b); weights sum to 1 (0 where a picture has no pixel).
    std::uint32_t cellIndex(int r, int g, int b) const {
        return static_cast<std::uint32_t>(r + (m_n - 1) * (g + (m_n - 1) * b));
    }
    float cellWeight(std::uint32_t cell) const { return m_cellWeight[cell]; }
    const std::vector<float>& cellWeights() const { return m_cellWeight; }
    bool image() const { return m_options->image != nullptr || bool(m_options->imageRows); }
    double imageOutsideDomain() const { return m_outsideDomain; }
    // The picture's share of pixels per 5-degree Oklab hue bin (uniform without a picture).
    const std::array<double, 72>& hueWeights() const { return m_hueWeight; }
    // 1D files with a picture: the share of pixels per input value bin (256 per channel).
    const std::array<std::array<double, 256>, 3>& channelWeights() const { return m_chanWeight; }

private:
    void weighFromImage(const ImageRows& feed);

    const CheckOptions* m_options;
    std::optional<Lut3D> m_table;
    const Lut3D* m_rawTable = nullptr;
    std::shared_ptr<const Lut1D> m_shaper;
    const Lut1D* m_rawShaper = nullptr;
    std::unique_ptr<Sampler> m_sampler;
    int m_n = 0;
    glm::vec3 m_inMin{0.0f}, m_inMax{1.0f};
    std::vector<float> m_cellWeight;
    std::array<double, 72> m_hueWeight{};
    std::array<std::array<double, 256>, 3> m_chanWeight{};
    double m_outsideDomain = 0.0;
};

// One flagged piece of the table: a lattice edge, a ray's segment or a lattice point, with the
// cells it touches. Flags of one kind (and channel, variant) that touch neighbouring cells make
// one finding.
struct Flag {
    FindingKind kind = FindingKind::FoldOver;
    std::int8_t channel = -1;
    std::int8_t variant = 0; // Clip/OutOfRange: 0 top, 1 bottom
    std::int8_t axis = -1;   // 0..2: a lattice line along that axis; -1: a ray or an entry
    bool point = false;      // `share` is a lattice point's (entries, second differences)
    std::int8_t ray = -1;    // the ray (rays()) when axis == -1
    std::uint8_t cellCount = 0;
    double size = 0.0;            // double: an entry near FLT_MAX times 255 stays finite
    float share = 0.0f;           // of the cube (or picture) along `axis`
    glm::vec3 at{0.0f};           // table coordinates of the worst place
    float from = 0.0f, to = 0.0f; // kind-specific detail (fold: the values it falls between ...)
    std::array<std::uint32_t, 8> cells{};
};

// Rays through the cube, in table coordinates: grey, from black to the primaries and
// secondaries, from the primaries to white, and the skin line.
struct Ray {
    const char* name; // "grey axis", "black to red", ..., "skin line"
    glm::vec3 from, to;
    glm::ivec3 direction; // channels that must move one way along it
    bool latticeLine;     // along one lattice axis: scanned with the lattice lines
};
const std::vector<Ray>& rays();
inline constexpr int kSkinRay = 10; // index of the skin line in rays()

// The lattice and ray scans: flags for folds, banding, clips and roughness, and the figures
// they measure (greyWorstFold, steepest, totalVariationRatio).
void scanLattice(const Context& ctx, std::vector<Flag>& flags, CheckFigures& figures);
// NaN/Inf and out-of-range entries, invertibility, the output gamut and the picture's range.
void scanEntries(const Context& ctx, std::vector<Flag>& flags, CheckFigures& figures);
void measureInvertibility(const Context& ctx, CheckFigures& figures, glm::vec3& worstFold);
void measureGamut(const Context& ctx, CheckFigures& figures);
// The hue check: findings (hue shift, skin drift) and figures.
void checkHue(const Context& ctx, std::vector<CheckFinding>& findings, CheckFigures& figures);
// A 1D-only file: its three curves scanned as lines.
void scan1D(const Context& ctx, std::vector<CheckFinding>& findings, CheckFigures& figures);

// Flags grouped into findings (connected cells of one kind), with severity by the thresholds.
void groupFlags(const Context& ctx, std::vector<Flag>& flags, std::vector<CheckFinding>& findings,
                CheckFigures& figures);

// The severity a figure earns: Fail at or above fail, Warn at or above warn, else Pass.
inline CheckStatus grade(double figure, const Threshold& t) {
    return figure >= t.fail   ? CheckStatus::Fail
           : figure >= t.warn ? CheckStatus::Warn
                              : CheckStatus::Pass;
}
const Threshold& thresholdFor(const CheckThresholds& t, FindingKind kind);

// "R", "G", "B"; "red", "green", "blue".
const char* channelLetter(int c);
const char* channelName(int c);

} // namespace lut::check
