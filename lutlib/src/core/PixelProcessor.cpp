#include "lut/PixelProcessor.h"

#include "lut/DomainProbe.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

namespace lut {

PixelProcessor::~PixelProcessor() = default;

namespace {

class SamplerStep final : public PixelProcessor {
public:
    explicit SamplerStep(std::shared_ptr<const Sampler> s) : m_sampler(std::move(s)) {}
    void processPixels(float* rgba, std::size_t count) const override {
        m_sampler->applyPixels(rgba, count);
    }

private:
    std::shared_ptr<const Sampler> m_sampler;
};

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string range(glm::vec3 lo, glm::vec3 hi) {
    if (lo.x == lo.y && lo.y == lo.z && hi.x == hi.y && hi.y == hi.z)
        return number(lo.x) + ".." + number(hi.x);
    return "(" + number(lo.x) + " " + number(lo.y) + " " + number(lo.z) + ")..(" + number(hi.x) +
           " " + number(hi.y) + " " + number(hi.z) + ")";
}

} // namespace

std::shared_ptr<const PixelProcessor> samplerProcessor(std::shared_ptr<const Sampler> sampler) {
    return std::make_shared<SamplerStep>(std::move(sampler));
}

void PixelChain::append(std::shared_ptr<const PixelProcessor> step) {
    if (step)
        m_steps.push_back(std::move(step));
}

void PixelChain::processPixels(float* rgba, std::size_t count) const {
    for (const auto& s : m_steps)
        s->processPixels(rgba, count);
}

void PixelChain::apply(const ImageView& image, int nthreads) const {
    if (image.empty() || m_steps.empty())
        return;
    const std::size_t w = static_cast<std::size_t>(image.width);
    const int band =
        std::max(1, std::min(256, static_cast<int>((1u << 16) / std::max<std::size_t>(w, 1))));
    const int bands = (image.height + band - 1) / band;
    const bool packed = image.strideFloats == static_cast<std::ptrdiff_t>(4 * w);
    parallelForDynamic(bands, nthreads, 1, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b) {
            const int y0 = b * band, y1 = std::min(image.height, y0 + band);
            if (packed)
                processPixels(image.row(y0), w * static_cast<std::size_t>(y1 - y0));
            else
                for (int y = y0; y < y1; ++y)
                    processPixels(image.row(y), w);
        }
    });
}

void DomainExcess::merge(const DomainExcess& o) {
    values += o.values;
    if (o.above)
        highest = above ? std::max(highest, o.highest) : o.highest;
    if (o.below)
        lowest = below ? std::min(lowest, o.lowest) : o.lowest;
    above += o.above;
    below += o.below;
    nonFinite += o.nonFinite;
}

std::string DomainExcess::str() const {
    if (!any())
        return {};
    std::string s;
    if (above)
        s += std::to_string(above) + " of " + std::to_string(values) +
             " channel values above the LUT's domain " + range(domainMin, domainMax) + " (up to " +
             number(highest) + ")";
    if (below)
        s += std::string(s.empty() ? std::to_string(below) + " of " + std::to_string(values) +
                                         " channel values below the LUT's domain " +
                                         range(domainMin, domainMax)
                                   : ", " + std::to_string(below) + " below") +
             " (down to " + number(lowest) + ")";
    if (nonFinite)
        s += (s.empty() ? "" : ", ") + std::to_string(nonFinite) + " NaN or infinite";
    return s;
}

DomainProbe::DomainProbe(glm::vec3 domainMin, glm::vec3 domainMax)
    : m_min(domainMin), m_max(domainMax) {
    m_total.domainMin = domainMin;
    m_total.domainMax = domainMax;
}

void DomainProbe::processPixels(float* rgba, std::size_t count) const {
    DomainExcess local;
    local.values = count * 3;
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = rgba + 4 * i;
        for (int c = 0; c < 3; ++c) {
            const float v = p[c];
            if (!std::isfinite(v)) {
                ++local.nonFinite;
            } else if (v > m_max[c]) {
                local.highest = local.above++ ? std::max(local.highest, v) : v;
            } else if (v < m_min[c]) {
                local.lowest = local.below++ ? std::min(local.lowest, v) : v;
            }
        }
    }
    std::lock_guard lock(m_mutex);
    m_total.merge(local);
}

DomainExcess DomainProbe::result() const {
    std::lock_guard lock(m_mutex);
    return m_total;
}

} // namespace lut
