// SPDX-License-Identifier: Apache-2.0
// The pictures as samples, their histograms and moments: see match/MatchSamples.h.
#include "match/MatchSamples.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/match/WorkingSpace.h"

#include <algorithm>
#include <cmath>

namespace lut::detail {

namespace {

constexpr std::size_t kChunk = 1 << 16;

float sanitize(float v) {
    constexpr float m = static_cast<float>(limits::kMaxColorValue);
    return v < -m ? -m : v > m ? m : v; // NaN is tested before
}

} // namespace

int sampleStep(double total, std::size_t maxPerPicture) {
    return total > static_cast<double>(maxPerPicture)
               ? static_cast<int>(std::ceil(std::sqrt(total / static_cast<double>(maxPerPicture))))
               : 1;
}

SampleSet collectSamples(const std::vector<const MatchPicture*>& pictures, bool sourceLinear,
                         std::size_t maxPerPicture, std::vector<PictureFacts>& facts,
                         int nthreads) {
    SampleSet set;
    set.codeAligned = !sourceLinear;
    facts.clear();
    for (const MatchPicture* pic : pictures) {
        const ImageView& img = pic->pixels;
        if (img.empty())
            throw Error(pic->name + ": the picture has no pixels");
        // A picture read in part: its whole size, and the grid's step within what was read.
        const bool part = pic->step > 1;
        const int fullW = part ? pic->fullWidth : img.width;
        const int fullH = part ? pic->fullHeight : img.height;
        const int maskW = part ? pic->maskFullWidth : pic->mask.width;
        const int maskH = part ? pic->maskFullHeight : pic->mask.height;
        if (!pic->mask.empty() && (maskW != fullW || maskH != fullH))
            throw Error(pic->name + ": the mask is " + std::to_string(maskW) + "x" +
                        std::to_string(maskH) + ", the picture " + std::to_string(fullW) + "x" +
                        std::to_string(fullH) + " (a mask must be the size of its picture)");
        const bool convert = pic->linear != sourceLinear;
        if (convert || pic->bitDepth != 8)
            set.codeAligned = false;
        PictureFacts f;
        f.name = pic->name;
        f.converted = convert;
        f.pixels = static_cast<std::size_t>(fullW) * static_cast<std::size_t>(fullH);
        const int fullStride = sampleStep(static_cast<double>(f.pixels), maxPerPicture);
        if (part &&
            (fullStride % pic->step != 0 || (img.width != (fullW + pic->step - 1) / pic->step) ||
             img.height != (fullH + pic->step - 1) / pic->step))
            throw Error(pic->name + ": read every " + std::to_string(pic->step) +
                        "th pixel, which is not the grid the match samples (every " +
                        std::to_string(fullStride) + "th)");
        const int stride = part ? fullStride / pic->step : fullStride;
        const int rows = (img.height + stride - 1) / stride;
        const int cols = (img.width + stride - 1) / stride;
        // Fixed places per sampled pixel, compacted in order afterwards: the same samples on
        // any number of threads.
        std::vector<glm::vec3> values(static_cast<std::size_t>(rows) * cols);
        std::vector<std::uint8_t> state(values.size(), 0); // 0 used, 1 masked, 2 NaN
        parallelFor(rows, nthreads, [&](int r0, int r1) {
            for (int r = r0; r < r1; ++r) {
                const int y = r * stride;
                for (int c = 0; c < cols; ++c) {
                    const int x = c * stride;
                    const std::size_t i = static_cast<std::size_t>(r) * cols + c;
                    if (!pic->mask.empty()) {
                        const float* m = pic->mask.pixel(x, y);
                        const float cover = (m[0] + m[1] + m[2]) / 3.0f * m[3];
                        if (!(cover >= 0.5f)) {
                            state[i] = 1;
                            continue;
                        }
                    }
                    const float* p = img.pixel(x, y);
                    if (std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2])) {
                        state[i] = 2;
                        continue;
                    }
                    glm::vec3 v;
                    for (int k = 0; k < 3; ++k) {
                        double s = sanitize(p[k]);
                        if (convert)
                            s = sourceLinear ? srgbDecodeExtended(s) : srgbEncodeExtended(s);
                        v[k] = static_cast<float>(s);
                    }
                    values[i] = v;
                }
            }
        });
        struct Part {
            std::size_t masked = 0, invalid = 0, outside = 0;
            double lo = INFINITY, hi = -INFINITY;
            double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
            std::vector<std::uint32_t> distinct; // up to kDistinct, sorted
        };
        constexpr std::size_t kDistinct = 256;
        const Part stats = reduceChunks(
            values.size(), std::size_t(1) << 16, nthreads, Part{},
            [&](std::size_t a, std::size_t b, Part& p) {
                for (std::size_t i = a; i < b; ++i) {
                    if (state[i] == 1) {
                        ++p.masked;
                        continue;
                    }
                    if (state[i] == 2) {
                        ++p.invalid;
                        continue;
                    }
                    const glm::vec3 v = values[i];
                    std::uint32_t key = 0;
                    for (int k = 0; k < 3; ++k) {
                        p.lo = std::min(p.lo, static_cast<double>(v[k]));
                        p.hi = std::max(p.hi, static_cast<double>(v[k]));
                        if (v[k] < 0.0f || v[k] > 1.0f)
                            ++p.outside;
                        p.sum[k] += v[k];
                        p.sum2[k] += static_cast<double>(v[k]) * v[k];
                        key = key << 10 | static_cast<std::uint32_t>(
                                              std::clamp(std::lround(v[k] * 1023.0f), 0L, 1023L));
                    }
                    if (p.distinct.size() < kDistinct) {
                        auto it = std::lower_bound(p.distinct.begin(), p.distinct.end(), key);
                        if (it == p.distinct.end() || *it != key)
                            p.distinct.insert(it, key);
                    }
                }
            },
            [](Part& t, const Part& p) {
                t.masked += p.masked;
                t.invalid += p.invalid;
                t.outside += p.outside;
                t.lo = std::min(t.lo, p.lo);
                t.hi = std::max(t.hi, p.hi);
                for (int k = 0; k < 3; ++k) {
                    t.sum[k] += p.sum[k];
                    t.sum2[k] += p.sum2[k];
                }
                for (std::uint32_t key : p.distinct) {
                    if (t.distinct.size() >= kDistinct)
                        break;
                    auto it = std::lower_bound(t.distinct.begin(), t.distinct.end(), key);
                    if (it == t.distinct.end() || *it != key)
                        t.distinct.insert(it, key);
                }
            });
        f.sampled = values.size();
        f.masked = stats.masked;
        f.invalid = stats.invalid;
        f.outsideUnit = stats.outside;
        f.minStored = stats.lo;
        f.maxStored = stats.hi;
        f.distinct = stats.distinct.size();
        std::vector<glm::vec3> used;
        used.reserve(values.size() - f.masked - f.invalid);
        for (std::size_t i = 0; i < values.size(); ++i)
            if (state[i] == 0)
                used.push_back(values[i]);
        const double* sum = stats.sum;
        const double* sum2 = stats.sum2;
        f.used = used.size();
        if (used.empty())
            throw Error(pic->name + ": no pixel to match (" +
                        (f.masked > 0 ? std::to_string(f.masked) + " masked" : std::string()) +
                        (f.masked > 0 && f.invalid > 0 ? ", " : "") +
                        (f.invalid > 0 ? std::to_string(f.invalid) + " NaN" : std::string()) + ")");
        double spread = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double mean = sum[k] / static_cast<double>(used.size());
            spread +=
                std::sqrt(std::max(0.0, sum2[k] / static_cast<double>(used.size()) - mean * mean));
        }
        f.spread = spread / 3.0;
        const float weight = static_cast<float>(1.0 / static_cast<double>(used.size()));
        parallelFor(static_cast<int>(used.size()), nthreads, [&](int a, int b) {
            for (int i = a; i < b; ++i)
                for (int k = 0; k < 3; ++k)
                    used[static_cast<std::size_t>(i)][k] = static_cast<float>(
                        encodeWorking(used[static_cast<std::size_t>(i)][k], sourceLinear));
        });
        set.values.insert(set.values.end(), used.begin(), used.end());
        set.weights.insert(set.weights.end(), used.size(), weight);
        facts.push_back(std::move(f));
    }
    return set;
}

SampleSet thinSamples(const SampleSet& set, std::size_t count) {
    if (set.size() <= count || count == 0)
        return set;
    SampleSet out;
    out.codeAligned = set.codeAligned;
    const double step = static_cast<double>(set.size()) / static_cast<double>(count);
    out.values.reserve(count);
    out.weights.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t k = static_cast<std::size_t>(static_cast<double>(i) * step);
        out.values.push_back(set.values[k]);
        out.weights.push_back(set.weights[k]);
    }
    return out;
}

ChannelStats channelStats(const std::vector<glm::vec3>& values, const std::vector<float>& weights,
                          bool codeAligned, int nthreads) {
    ChannelStats s;
    glm::dvec3 lo(0.0), hi(1.0);
    int bins = 256;
    if (codeAligned) {
        lo = glm::dvec3(-0.5 / 255.0);
        hi = glm::dvec3(1.0 + 0.5 / 255.0);
    } else {
        using Range = std::pair<glm::dvec3, glm::dvec3>;
        const Range r = reduceChunks(
            values.size(), kChunk, nthreads, Range{glm::dvec3(INFINITY), glm::dvec3(-INFINITY)},
            [&](std::size_t a, std::size_t b, Range& part) {
                for (std::size_t i = a; i < b; ++i)
                    for (int c = 0; c < 3; ++c) {
                        part.first[c] = std::min(part.first[c], static_cast<double>(values[i][c]));
                        part.second[c] =
                            std::max(part.second[c], static_cast<double>(values[i][c]));
                    }
            },
            [](Range& t, const Range& p) {
                t.first = glm::min(t.first, p.first);
                t.second = glm::max(t.second, p.second);
            });
        bins = 4096;
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::isfinite(r.first[c]) ? r.first[c] : 0.0;
            hi[c] = std::isfinite(r.second[c]) ? r.second[c] : 1.0;
            if (!(hi[c] - lo[c] > 1e-6)) { // a flat channel: one code either side
                lo[c] -= 0.5 / 255.0;
                hi[c] += 0.5 / 255.0;
            }
        }
    }
    using Hists = std::array<ChannelHistogram, 3>;
    const Hists zero = {ChannelHistogram(lo.x, hi.x, bins), ChannelHistogram(lo.y, hi.y, bins),
                        ChannelHistogram(lo.z, hi.z, bins)};
    s.histograms = reduceChunks(
        values.size(), kChunk, nthreads, zero,
        [&](std::size_t a, std::size_t b, Hists& part) {
            for (std::size_t i = a; i < b; ++i)
                for (int c = 0; c < 3; ++c)
                    part[static_cast<std::size_t>(c)].add(values[i][c], weights[i]);
        },
        [](Hists& t, const Hists& p) {
            for (std::size_t c = 0; c < 3; ++c)
                t[c].merge(p[c]);
        });
    for (std::size_t c = 0; c < 3; ++c) {
        if (codeAligned) {
            s.smoothing[c] = 1.0 / 255.0;
        } else {
            const auto& h = s.histograms[c];
            const double spread =
                h.total() > 0.0 ? h.quantile(0.999) - h.quantile(0.001) : hi[c] - lo[c];
            s.smoothing[c] = std::max(spread, 1e-4) / 256.0;
        }
    }
    return s;
}

ColourMoments colourMoments(const std::vector<glm::vec3>& values, const std::vector<float>& weights,
                            int nthreads) {
    return reduceChunks(
        values.size(), kChunk, nthreads, ColourMoments{},
        [&](std::size_t a, std::size_t b, ColourMoments& part) {
            for (std::size_t i = a; i < b; ++i)
                part.add(glm::dvec3(values[i]), weights[i]);
        },
        [](ColourMoments& t, const ColourMoments& p) { t.merge(p); });
}

std::vector<glm::vec3> mapValues(const std::vector<glm::vec3>& values,
                                 const std::function<glm::dvec3(const glm::dvec3&)>& fn,
                                 int nthreads) {
    std::vector<glm::vec3> out(values.size());
    parallelFor(static_cast<int>(values.size()), nthreads, [&](int a, int b) {
        for (int i = a; i < b; ++i)
            out[static_cast<std::size_t>(i)] =
                glm::vec3(fn(glm::dvec3(values[static_cast<std::size_t>(i)])));
    });
    return out;
}

} // namespace lut::detail
