#pragma once
// Counting the pixel values a LUT cannot see: inputs outside its domain are clamped to the edge by
// every sampler (lut/interp/Sampler.h), so an HDR frame (values above 1) or a frame in the wrong
// colour space loses information there without a word. A DomainProbe is a pixel step that
// changes nothing and counts, so `lutkit apply` can say how many values were clamped and the
// worst one.
#include "lut/PixelProcessor.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <mutex>
#include <string>

namespace lut {

struct DomainExcess {
    glm::vec3 domainMin{0.0f}, domainMax{1.0f};
    std::size_t values = 0;    // channel values checked (3 per pixel)
    std::size_t above = 0;     // channel values above domainMax
    std::size_t below = 0;     // channel values below domainMin
    std::size_t nonFinite = 0; // NaN or infinite channel values
    float highest = 0.0f;      // the largest value above the domain (0 if none)
    float lowest = 0.0f;       // the smallest value below the domain (0 if none)

    bool any() const { return above + below + nonFinite > 0; }
    void merge(const DomainExcess& other);
    // "1234 of 3000000 channel values above the LUT's domain 0..1 (up to 12.5), 3 below (down to
    // -0.02)"; "" when nothing was outside.
    std::string str() const;
};

class DomainProbe final : public PixelProcessor {
public:
    DomainProbe(glm::vec3 domainMin, glm::vec3 domainMax);
    void processPixels(float* rgba, std::size_t count) const override;
    DomainExcess result() const;

private:
    glm::vec3 m_min, m_max;
    mutable std::mutex m_mutex;
    mutable DomainExcess m_total;
};

} // namespace lut
