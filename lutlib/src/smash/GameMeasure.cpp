// SPDX-License-Identifier: Apache-2.0
// The game's error where nothing was fitted; see GameMeasure.h.
#include "smash/GameMeasure.h"

#include "lut/Parallel.h"
#include "lut/Quantize.h"
#include "lut/ops/ErrorBound.h"
#include "lut/smash/GameDisplay.h"
#include "lut/smash/SmashConstants.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <unordered_map>

namespace lut::detail {

namespace {

// The game's trilinear lookup of its 16^3 LUT, in double.
glm::dvec3 gameLookup(const Lut3D& lut, const glm::dvec3& s) {
    const int n = lut.size();
    int i[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double x = clampUnit(s[c]) * (n - 1);
        i[c] = std::min(static_cast<int>(x), n - 2);
        f[c] = x - i[c];
    }
    glm::dvec3 v(0.0);
    for (int db = 0; db < 2; ++db)
        for (int dg = 0; dg < 2; ++dg)
            for (int dr = 0; dr < 2; ++dr) {
                const double w =
                    (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
                if (w != 0.0)
                    v += w * glm::dvec3(lut.at(i[0] + dr, i[1] + dg, i[2] + db));
            }
    return v;
}

// shown - wanted per channel, display units.
glm::dvec3 gameDifference(const Lut3D& lut8, const glm::dvec3& s, const glm::dvec3& wanted) {
    const glm::dvec3 l = gameLookup(lut8, s);
    glm::dvec3 d;
    for (int c = 0; c < 3; ++c)
        d[c] = gameShownTabulated(l[c], clampUnit(s[c])) - clampUnit(wanted[c]);
    return d;
}

GameSamples gridSamples(const WantedFn& wanted, int k, bool centres) {
    GameSamples samples(kSmashLutSize);
    const int cells = (kSmashLutSize - 1) * std::max(1, k);
    const int m = centres ? cells : cells + 1;
    samples.reserve(static_cast<std::size_t>(m) * m * m);
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r) {
                const glm::dvec3 s = centres ? (glm::dvec3(r, g, b) + 0.5) / double(cells)
                                             : glm::dvec3(r, g, b) / double(cells);
                samples.add(s, wanted(s));
            }
    return samples;
}

std::uint64_t mix64(std::uint64_t h) {
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    return h ^ (h >> 31);
}

// A deterministic number in [0, 1) for pixel p, channel c.
double jitter(std::size_t p, int c) {
    const std::uint64_t h = mix64((static_cast<std::uint64_t>(p) << 2 | static_cast<unsigned>(c)) +
                                  0x9E3779B97F4A7C15ull);
    return static_cast<double>(h >> 11) / 9007199254740992.0;
}

} // namespace

GameSamples gridCentres(const WantedFn& wanted, int subdivision) {
    return gridSamples(wanted, subdivision, true);
}

GameSamples gridPoints(const WantedFn& wanted, int subdivision) {
    return gridSamples(wanted, subdivision, false);
}

GameError gameErrorEverywhere(const WantedFn& wanted, const Lut3D& lut8, int subdivision,
                              int nthreads) {
    // The grid's points are the held-out centres: mean and p99 from them, the maximum bounded.
    std::vector<float> values;
    BoundOptions o;
    o.cells = kSmashLutSize - 1;
    o.perCell = std::max(1, subdivision);
    o.nthreads = nthreads;
    o.values = &values;
    const ErrorStats bound = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i)
                diff[i] = gameDifference(lut8, in[i], wanted(in[i]));
        },
        o);
    std::vector<double> steps(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        steps[i] = double(values[i]) * 255.0;
    GameError e = summariseSteps(steps);
    e.maxSteps = std::max(e.maxSteps, bound.maxAbs * 255.0);
    return e;
}

ShotColours::ShotColours(const ImageView& shot, const WantedFn& wanted,
                         const InputForShownFn& input, double clipInput)
    : m_input(input), m_clip(clipInput) {
    m_pixels = static_cast<std::size_t>(shot.width) * static_cast<std::size_t>(shot.height);
    m_pixelColour.resize(m_pixels);
    std::unordered_map<std::uint64_t, std::uint32_t> index;
    index.reserve(1 << 16);
    bool eightBit = true;
    for (std::size_t p = 0; p < m_pixels; ++p) {
        const float* px = shot.pixel(static_cast<int>(p % static_cast<std::size_t>(shot.width)),
                                     static_cast<int>(p / static_cast<std::size_t>(shot.width)));
        glm::dvec3 d(0.0);
        std::uint64_t key = 0;
        for (int c = 0; c < 3; ++c) {
            d[c] = clampUnit(px[c]);
            key = key << 16 | toUnorm16(static_cast<float>(d[c]));
        }
        const auto [it, added] =
            index.try_emplace(key, static_cast<std::uint32_t>(m_colours.size()));
        if (added) {
            Colour col;
            col.display = d;
            col.firstPixel = static_cast<std::uint32_t>(p);
            col.heldOut = (mix64(key) & 3u) == 0u; // a quarter of the colours
            m_colours.push_back(col);
            for (int c = 0; c < 3; ++c)
                eightBit = eightBit && std::fabs(d[c] * 255.0 - std::round(d[c] * 255.0)) < 1e-3;
        }
        ++m_colours[it->second].count;
        m_pixelColour[p] = it->second;
    }
    m_halfCode = 0.5 / (eightBit ? 255.0 : 65535.0);
    for (Colour& col : m_colours)
        addInputs(col, wanted, input);
}

// A pixel's colour is a code of the file: the game displayed something within half a code of it,
// for an input somewhere in that code's range. Per colour, sets of inputs: the one that displays
// the code exactly, and per channel the two that display the code's ends; a channel the
// unedited game clipped to white could have had any input from just below the clip point to 1,
// so one set per value across that range (the LUT's lattice points there and halfway between).
void ShotColours::addInputs(Colour& col, const WantedFn& wanted, const InputForShownFn& input) {
    const glm::dvec3 centre = input(col.display, col.firstPixel);
    col.wanted = static_cast<std::uint32_t>(m_wanted.size());
    m_wanted.push_back(wanted(centre));
    bool white[3];
    std::vector<double> whiteInputs;
    for (int c = 0; c < 3; ++c)
        white[c] = m_clip > 0.0 && col.display[c] >= 1.0 - 1e-7;
    int whites = 0;
    for (int c = 0; c < 3; ++c)
        whites += white[c];
    if (whites > 0) {
        glm::dvec3 below = col.display;
        for (int c = 0; c < 3; ++c)
            if (white[c])
                below[c] = 1.0 - m_halfCode;
        const glm::dvec3 sBelow = input(below, col.firstPixel);
        for (int c = 0; c < 3; ++c)
            if (white[c]) {
                whiteInputs.push_back(sBelow[c]);
                break;
            }
        whiteInputs.push_back(m_clip);
        for (double j = 11.0; j <= 15.0; j += 0.5)
            if (j / 15.0 > m_clip)
                whiteInputs.push_back(j / 15.0);
    }
    const int perWhite = static_cast<int>(whiteInputs.size());
    int sets = 1;
    for (int c = 0; c < 3; ++c)
        sets *= white[c] ? perWhite : 1;
    col.firstInput = static_cast<std::uint32_t>(m_s.size());
    col.sets = static_cast<std::uint32_t>(sets);
    for (int k = 0; k < sets; ++k) {
        glm::dvec3 s = centre;
        int rest = k;
        for (int c = 0; c < 3; ++c)
            if (white[c]) {
                s[c] = whiteInputs[static_cast<std::size_t>(rest % perWhite)];
                rest /= perWhite;
            }
        m_s.push_back(s);
        // the code's ends, one channel at a time (white channels: covered by the values above)
        for (int c = 0; c < 3; ++c)
            for (int side = -1; side <= 1; side += 2) {
                glm::dvec3 d = col.display;
                d[c] = clampUnit(d[c] + side * m_halfCode);
                glm::dvec3 e = s;
                if (!white[c])
                    e[c] = input(d, col.firstPixel)[c];
                m_s.push_back(e);
            }
    }
}

std::size_t ShotColours::heldOutColours() const {
    return static_cast<std::size_t>(std::count_if(m_colours.begin(), m_colours.end(),
                                                  [](const Colour& c) { return c.heldOut; }));
}

GameError ShotColours::error(const Lut3D& lut8, bool heldOutOnly, int nthreads) const {
    std::mutex mutex;
    std::vector<std::pair<double, double>> all;
    double worst = 0.0;
    const int chunks = static_cast<int>(std::min<std::size_t>(m_colours.size(), 256));
    parallelFor(chunks, nthreads, [&](int c0, int c1) {
        std::vector<std::pair<double, double>> part;
        double partWorst = 0.0;
        const std::size_t n = m_colours.size();
        const std::size_t i0 = n * static_cast<std::size_t>(c0) / static_cast<std::size_t>(chunks);
        const std::size_t i1 = n * static_cast<std::size_t>(c1) / static_cast<std::size_t>(chunks);
        for (std::size_t i = i0; i < i1; ++i) {
            const Colour& col = m_colours[i];
            if (heldOutOnly && !col.heldOut)
                continue;
            const glm::dvec3& want = m_wanted[col.wanted];
            const double w = double(col.count) / col.sets;
            for (std::uint32_t k = 0; k < col.sets; ++k) {
                const std::size_t q = col.firstInput + 7 * static_cast<std::size_t>(k);
                const glm::dvec3 e0 = gameDifference(lut8, m_s[q], want);
                glm::dvec3 bound = glm::abs(e0);
                // within the code's range: the change towards either end of each channel's
                // (the display is near linear over half a code, the LUT is linear in a cell)
                for (int c = 0; c < 3; ++c) {
                    glm::dvec3 step(0.0);
                    for (int side = 0; side < 2; ++side) {
                        const glm::dvec3 e =
                            gameDifference(lut8,
                                           m_s[q + 1 + 2 * static_cast<std::size_t>(c) +
                                               static_cast<std::size_t>(side)],
                                           want);
                        step = glm::max(step, glm::abs(e - e0));
                    }
                    bound += step;
                }
                for (int c = 0; c < 3; ++c) {
                    part.emplace_back(std::fabs(e0[c]) * 255.0, w);
                    partWorst = std::max(partWorst, bound[c] * 255.0);
                }
            }
        }
        std::lock_guard lock(mutex);
        all.insert(all.end(), part.begin(), part.end());
        worst = std::max(worst, partWorst);
    });
    GameError e = summariseWeightedSteps(all);
    e.maxSteps = std::max(e.maxSteps, worst);
    return e;
}

GameSamples ShotColours::training(std::size_t maxSamples, bool withHeldOut) const {
    std::size_t trainingPixels = 0;
    for (const Colour& c : m_colours)
        if (withHeldOut || !c.heldOut)
            trainingPixels += c.count;
    const std::size_t stride = std::max<std::size_t>(1, (trainingPixels + maxSamples - 1) /
                                                            std::max<std::size_t>(1, maxSamples));
    GameSamples samples(kSmashLutSize);
    samples.reserve(trainingPixels / stride + 1);
    std::size_t seen = 0;
    for (std::size_t p = 0; p < m_pixels; ++p) {
        const Colour& col = m_colours[m_pixelColour[p]];
        if ((col.heldOut && !withHeldOut) || seen++ % stride != 0)
            continue;
        // somewhere in the code's range (the input that shows it exactly is one of many), so the
        // refinement fits what the game shows over the range, not at one point of it
        glm::dvec3 d = col.display;
        for (int c = 0; c < 3; ++c)
            d[c] = clampUnit(d[c] + m_halfCode * (2.0 * jitter(p, c) - 1.0));
        const glm::dvec3 s = m_input(d, p);
        samples.add(s, m_wanted[col.wanted]);
    }
    return samples;
}

} // namespace lut::detail
