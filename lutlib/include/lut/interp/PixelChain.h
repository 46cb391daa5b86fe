// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `lutkit apply` does to every pixel, as one chain of steps run on small runs of float RGBA
// pixels (a few thousand at a time, from the streaming image reader, lut/formats/ApplyImage.h):
//
//     before[0] ... before[n-1]   ->   the LUT   ->   after[0] ... after[m-1]
//
// A step rewrites `count` interleaved RGBA float pixels in place. Steps before the LUT bring the
// values into the LUT's input space (an OpenColorIO processor for --from, an exposure ...), steps
// after it take the LUT's output to the file's space (--to, a display transform ...). Alpha is
// the step's to keep or change; the LUT keeps it.
//
// Contract for a step: it is called concurrently from several threads on disjoint runs of
// pixels, so it must be thread-safe (const state only, or its own locking); the result for a
// pixel must depend only on that pixel (never on the run it came in, nor on the thread), which
// makes the streamed result bit-identical to a whole-frame run; it throws lut::Error to stop the
// image (the writer then keeps the old output).
//
// Before the LUT, the chain counts the values outside the LUT's domain (DomainStats): the LUT
// clamps them to its edge, and the caller reports how many there were instead of clamping
// silently.
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/interp/Interpolation.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lut {

class Sampler;

// One step: rewrites count RGBA float pixels (4 * count floats) in place.
using PixelStep = std::function<void(float* rgba, std::size_t count)>;

// Values the LUT saw outside its domain [domainMin, domainMax] (per channel), NaN included.
struct DomainStats {
    std::uint64_t pixels = 0;   // pixels seen
    std::uint64_t outside = 0;  // pixels with at least one of R, G, B outside the domain
    std::uint64_t nan = 0;      // pixels with a NaN in R, G or B (counted in outside too)
    float worst = 0.0f;         // the finite or infinite value farthest outside (0 if none)
    double worstDistance = 0.0; // how far outside the domain `worst` is
    void merge(const DomainStats& other);
    // "12 of 4096 pixels (0.29%) outside the LUT's domain [0, 1] (worst 3.25, 2 NaN)"; "" if
    // none was outside.
    std::string str(glm::vec3 domainMin, glm::vec3 domainMax) const;
};

class PixelChain {
public:
    PixelChain();
    ~PixelChain();
    PixelChain(const PixelChain&);
    PixelChain& operator=(const PixelChain&);
    PixelChain(PixelChain&&) noexcept;
    PixelChain& operator=(PixelChain&&) noexcept;

    // The LUT stage: lut sampled with `method` (the sampler keeps its own copy of the table).
    void setLut(const Lut3D& lut, Interpolation method = Interpolation::Tetrahedral);
    // A LUT file as it is meant to be applied: its 1D shaper, then its table, each exactly
    // (makeSampler(LutFile)); the domain watched is the file's input domain (the shaper's).
    void setLut(const LutFile& file, Interpolation method = Interpolation::Tetrahedral);
    // Steps before and after the LUT, run in the order added. `name` is for reports (-v).
    void addBefore(std::string name, PixelStep step);
    void addAfter(std::string name, PixelStep step);

    bool hasLut() const { return m_sampler != nullptr; }
    glm::vec3 domainMin() const { return m_domainMin; }
    glm::vec3 domainMax() const { return m_domainMax; }
    // Whether running the chain cannot change a pixel whose R, G, B lie in [0, 1] (every
    // integer-typed pixel): no step, and no LUT or one that is the identity (every entry within
    // 1e-6 of its lattice input: a neutral LUT, also as written with 6 decimals) over a domain
    // containing [0, 1]. Callers then skip the chain and keep the stored values bit for bit. (An
    // identity LUT does change values outside its domain: it clamps them.)
    bool isIdentityOnUnitRange() const {
        return m_before.empty() && m_after.empty() && m_identityLut;
    }
    // Whether a pixel whose R, G, B lie in [0, 1] (every integer-typed pixel) reaches the LUT
    // inside its domain: no step before it and a domain containing [0, 1]. Callers of such
    // input then need not count what the LUT saw outside its domain (run's stats stay empty).
    bool unitInputStaysInDomain() const {
        return m_before.empty() && m_domainMin.x <= 0.0f && m_domainMin.y <= 0.0f &&
               m_domainMin.z <= 0.0f && m_domainMax.x >= 1.0f && m_domainMax.y >= 1.0f &&
               m_domainMax.z >= 1.0f;
    }
    // Whether such a pixel also leaves the chain with R, G, B in [0, 1] (give or take float
    // rounding, far below half a 16-bit step): the above and no step after a 3D table whose
    // entries all lie in [0, 1], as every interpolation is a convex combination of entries.
    // Callers then need not count values an integer output type would clamp.
    bool unitInputGivesUnitOutput() const {
        return unitInputStaysInDomain() && m_after.empty() && m_sampler && m_entriesInUnit;
    }
    // The step names in order, the LUT as "lut"; for -v.
    std::vector<std::string> stepNames() const;

    // Runs every step on count RGBA pixels in place; stats (when given) receives what the LUT
    // saw outside its domain. Const and thread-safe when the steps are.
    void run(float* rgba, std::size_t count, DomainStats* stats = nullptr) const;

private:
    struct Named {
        std::string name;
        PixelStep step;
    };
    std::vector<Named> m_before;
    std::vector<Named> m_after;
    std::shared_ptr<const Sampler> m_sampler;
    glm::vec3 m_domainMin{0.0f};
    glm::vec3 m_domainMax{1.0f};
    bool m_identityLut = true;
    bool m_entriesInUnit = false; // every entry of the 3D table in [0, 1]
};

// Counts the values of count RGBA pixels outside [min, max] (R, G, B only) into stats.
void countOutsideDomain(const float* rgba, std::size_t count, glm::vec3 min, glm::vec3 max,
                        DomainStats& stats);

} // namespace lut
