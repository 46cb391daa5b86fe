// SPDX-License-Identifier: Apache-2.0
#include "check/CheckDetail.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/ops/Oklab.h"
#include "ops/OpsDetail.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace lut::check {

namespace {

Lut1D sanitized(const Lut1D& in) {
    Lut1D out = in;
    for (auto& e : out.entries())
        e = glm::vec3(detail::sanitizeValue(e.x), detail::sanitizeValue(e.y),
                      detail::sanitizeValue(e.z));
    return out;
}

// The inverse of one channel of a shaper, as its piecewise-linear curve.
double invertChannel(const Lut1D& s, int c, double y) {
    const int n = s.size();
    const double lo = s.domainMin()[c], hi = s.domainMax()[c];
    // Binary search on the running maximum (a shaper rises; a falling or flat part keeps the
    // first input that reaches y).
    double best = lo;
    double prevX = lo, prevY = s[0][c];
    if (y <= prevY)
        return lo;
    for (int i = 1; i < n; ++i) {
        const double x = lo + (hi - lo) * i / (n - 1);
        const double v = s[i][c];
        if (v >= y && prevY < y) {
            const double f = (y - prevY) / (v - prevY);
            return prevX + f * (x - prevX);
        }
        if (v > prevY) {
            prevY = v;
            prevX = x;
        }
        best = x;
    }
    return best;
}

} // namespace

Context::Context(const LutFile& file, const CheckOptions& options) : m_options(&options) {
    if (!file.cube && !file.shaper)
        throw Error("check: the file has neither a 3D table nor a 1D table");
    if (file.shaper) {
        m_rawShaper = &*file.shaper;
        m_shaper = std::make_shared<const Lut1D>(sanitized(*file.shaper));
        m_inMin = file.shaper->domainMin();
        m_inMax = file.shaper->domainMax();
    }
    if (file.cube) {
        m_rawTable = &*file.cube;
        std::size_t replaced = 0;
        m_table = detail::sanitizedCopy(*file.cube, replaced);
        m_n = m_table->size();
        if (!file.shaper) {
            m_inMin = m_table->domainMin();
            m_inMax = m_table->domainMax();
        }
        m_sampler = makeSampler(*m_table, Interpolation::Tetrahedral);
        const std::size_t cells = static_cast<std::size_t>(m_n - 1) * (m_n - 1) * (m_n - 1);
        m_cellWeight.assign(cells, 1.0f / static_cast<float>(cells));
    }
    m_hueWeight.fill(1.0 / 72.0);
    for (auto& ch : m_chanWeight)
        ch.fill(1.0 / 256.0);
    if (options.imageRows)
        weighFromImage(options.imageRows);
    else if (options.image && !options.image->empty())
        weighFromImage(
            [&](const std::function<void(const ImageView&)>& chunk) { chunk(*options.image); });
}

glm::vec3 Context::evaluate(glm::vec3 input) const {
    glm::vec3 x = input;
    if (m_shaper)
        x = m_shaper->apply(x);
    return m_sampler ? m_sampler->sample(x) : x;
}

void Context::evaluate(std::vector<glm::vec3>& colours) const {
    const int count = static_cast<int>(colours.size());
    parallelFor(count, nthreads(), [&](int begin, int end) {
        std::vector<float> rgba(4 * static_cast<std::size_t>(end - begin));
        for (int i = begin; i < end; ++i) {
            glm::vec3 x = colours[static_cast<std::size_t>(i)];
            if (m_shaper)
                x = m_shaper->apply(x);
            float* p = &rgba[4 * static_cast<std::size_t>(i - begin)];
            p[0] = x.x;
            p[1] = x.y;
            p[2] = x.z;
            p[3] = 1.0f;
        }
        if (m_sampler)
            m_sampler->applyPixels(rgba.data(), static_cast<std::size_t>(end - begin));
        for (int i = begin; i < end; ++i) {
            const float* p = &rgba[4 * static_cast<std::size_t>(i - begin)];
            colours[static_cast<std::size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
        }
    });
}

glm::vec3 Context::fileInput(glm::vec3 u) const {
    if (!m_table) // 1D: table coordinates are the shaper's normalised input
        return m_inMin + (m_inMax - m_inMin) * u;
    const glm::vec3 x = m_table->domainMin() + (m_table->domainMax() - m_table->domainMin()) * u;
    if (!m_shaper)
        return x;
    glm::vec3 in;
    for (int c = 0; c < 3; ++c)
        in[c] = static_cast<float>(invertChannel(*m_shaper, c, x[c]));
    return in;
}

glm::vec3 Context::tableCoordinates(glm::vec3 input) const {
    glm::vec3 x = input;
    if (!m_table)
        return (x - m_inMin) / (m_inMax - m_inMin);
    if (m_shaper)
        x = m_shaper->apply(x);
    const glm::vec3 u = (x - m_table->domainMin()) / (m_table->domainMax() - m_table->domainMin());
    glm::vec3 out;
    for (int c = 0; c < 3; ++c)
        out[c] = std::isnan(u[c]) ? 0.0f : std::clamp(u[c], 0.0f, 1.0f);
    return out;
}

void Context::weighFromImage(const ImageRows& feed) {
    const int cells = m_n > 1 ? m_n - 1 : 0;
    std::vector<double> cellCount(m_cellWeight.size(), 0.0);
    std::vector<double> colourBins(32 * 32 * 32, 0.0);
    std::array<std::array<double, 256>, 3> chan{};
    double outside = 0.0, total = 0.0;
    std::mutex mutex;
    // Counts of whole pixels, exact in double: the same sums whatever the chunks and threads.
    feed([&](const ImageView& image) {
        parallelFor(image.height, nthreads(), [&](int y0, int y1) {
            std::vector<double> localCells(cellCount.size(), 0.0);
            std::vector<double> localBins(colourBins.size(), 0.0);
            std::array<std::array<double, 256>, 3> localChan{};
            double localOutside = 0.0, localTotal = 0.0;
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < image.width; ++x) {
                    const float* p = image.pixel(x, y);
                    const glm::vec3 in(p[0], p[1], p[2]);
                    localTotal += 1.0;
                    bool out = false;
                    for (int c = 0; c < 3; ++c)
                        out = out || !(in[c] >= m_inMin[c] && in[c] <= m_inMax[c]);
                    localOutside += out ? 1.0 : 0.0;
                    const glm::vec3 v = (in - m_inMin) / (m_inMax - m_inMin);
                    int bin[3];
                    for (int c = 0; c < 3; ++c) {
                        const float f = std::isnan(v[c]) ? 0.0f : std::clamp(v[c], 0.0f, 1.0f);
                        bin[c] = std::min(31, static_cast<int>(f * 32.0f));
                        localChan[static_cast<std::size_t>(c)][static_cast<std::size_t>(
                            std::min(255, static_cast<int>(f * 256.0f)))] += 1.0;
                    }
                    localBins[static_cast<std::size_t>(bin[0] + 32 * (bin[1] + 32 * bin[2]))] +=
                        1.0;
                    if (cells > 0) {
                        const glm::vec3 u = tableCoordinates(in);
                        int idx[3];
                        for (int c = 0; c < 3; ++c)
                            idx[c] = std::min(cells - 1, static_cast<int>(u[c] * cells));
                        localCells[cellIndex(idx[0], idx[1], idx[2])] += 1.0;
                    }
                }
            std::lock_guard<std::mutex> lock(mutex);
            for (std::size_t i = 0; i < cellCount.size(); ++i)
                cellCount[i] += localCells[i];
            for (std::size_t i = 0; i < colourBins.size(); ++i)
                colourBins[i] += localBins[i];
            for (std::size_t c = 0; c < 3; ++c)
                for (std::size_t i = 0; i < 256; ++i)
                    chan[c][i] += localChan[c][i];
            outside += localOutside;
            total += localTotal;
        });
    });
    if (total <= 0.0)
        return;
    m_outsideDomain = outside / total;
    for (std::size_t i = 0; i < m_cellWeight.size(); ++i)
        m_cellWeight[i] = static_cast<float>(cellCount[i] / total);
    for (std::size_t c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < 256; ++i)
            m_chanWeight[c][i] = chan[c][i] / total;
    // Hues from the 32^3 colour histogram: each occupied bin's centre, by its count. Colours
    // too grey to have a hue (Oklab chroma under 0.02) weigh nothing.
    m_hueWeight.fill(0.0);
    double hueTotal = 0.0;
    for (int b = 0; b < 32; ++b)
        for (int g = 0; g < 32; ++g)
            for (int r = 0; r < 32; ++r) {
                const double n = colourBins[static_cast<std::size_t>(r + 32 * (g + 32 * b))];
                if (n <= 0.0)
                    continue;
                const glm::dvec3 lab = srgbToOklab(glm::dvec3(r + 0.5, g + 0.5, b + 0.5) / 32.0);
                if (oklabChroma(lab) < 0.02)
                    continue;
                const int bin = std::min(71, static_cast<int>(oklabHue(lab) / 5.0));
                m_hueWeight[static_cast<std::size_t>(bin)] += n / total;
                hueTotal += n / total;
            }
    (void)hueTotal;
}

const Threshold& thresholdFor(const CheckThresholds& t, FindingKind kind) {
    switch (kind) {
    case FindingKind::FoldOver:
        return t.foldOver;
    case FindingKind::Flat:
        return t.flat;
    case FindingKind::Step:
        return t.step;
    case FindingKind::Steep:
        return t.steep;
    case FindingKind::HueShift:
        return t.hueShift;
    case FindingKind::SkinDrift:
        return t.skinDrift;
    case FindingKind::NonFinite:
        return t.nonFinite;
    case FindingKind::OutOfRange:
        return t.outOfRange;
    case FindingKind::Clip:
        return t.clip;
    case FindingKind::Rough:
        return t.rough;
    }
    return t.foldOver;
}

const char* channelLetter(int c) {
    static const char* const names[] = {"R", "G", "B"};
    return c >= 0 && c < 3 ? names[c] : "RGB";
}

const char* channelName(int c) {
    static const char* const names[] = {"red", "green", "blue"};
    return c >= 0 && c < 3 ? names[c] : "all";
}

} // namespace lut::check
