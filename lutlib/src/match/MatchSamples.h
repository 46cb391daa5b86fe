// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: the pictures' pixels as working-space samples, and the histograms
// and moments taken of them. Reductions run in fixed chunks merged in order, so the results do
// not depend on the number of threads.
#include "lut/Parallel.h"
#include "lut/match/HistogramMatch.h"
#include "lut/match/Match.h"
#include "lut/match/MongeKantorovich.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lut::detail {

struct SampleSet {
    std::vector<glm::vec3> values; // working encoding
    std::vector<float> weights;    // each picture of a set weighs the same in total
    bool codeAligned = false;      // every value is an 8-bit code of display-encoded data
    std::size_t size() const { return values.size(); }
};

// What a picture held, for the warnings and the report.
struct PictureFacts {
    std::string name;
    std::size_t pixels = 0;                  // in the picture
    std::size_t sampled = 0;                 // looked at (a regular subsample beyond maxPerPicture)
    std::size_t used = 0;                    // ... and counted
    std::size_t masked = 0;                  // ... left out by the mask
    std::size_t invalid = 0;                 // ... left out for NaN
    bool converted = false;                  // stored as the other kind than the source, converted
    double minStored = 0.0, maxStored = 0.0; // of the used values, converted, over channels
    std::size_t outsideUnit = 0;             // channel values outside [0, 1] (converted)
    double spread = 0.0;      // standard deviation over the used values, mean of the channels
    std::size_t distinct = 0; // distinct colours (10 bits per channel), up to 256 counted
};

// The pixels the fit takes of each picture at most: 4 megapixels of the source, a share of them
// of each of `references` (at least 65536).
inline std::size_t maxSamples(bool source, std::size_t references) {
    constexpr std::size_t kMaxPerPicture = std::size_t(1) << 22;
    return source ? kMaxPerPicture
                  : std::max<std::size_t>(kMaxPerPicture / std::max<std::size_t>(references, 1),
                                          std::size_t(1) << 16);
}
// The step of the regular grid that keeps a picture of `pixels` within maxPerPicture.
int sampleStep(double pixels, std::size_t maxPerPicture);

// The pictures' counted pixels as working-space samples of the source's kind. At most
// maxPerPicture pixels of each (a regular grid beyond). Throws lut::Error for an empty picture,
// a mask of another size, or a picture with no counted pixel.
SampleSet collectSamples(const std::vector<const MatchPicture*>& pictures, bool sourceLinear,
                         std::size_t maxPerPicture, std::vector<PictureFacts>& facts, int nthreads);

// Every k-th sample (k chosen to keep at most `count`), weights kept.
SampleSet thinSamples(const SampleSet& set, std::size_t count);

// fn over [0, count) in chunks of `chunk`, on up to nthreads threads; partial results merged in
// chunk order.
template <class T, class Fn, class Merge>
T reduceChunks(std::size_t count, std::size_t chunk, int nthreads, const T& zero, Fn fn,
               Merge merge) {
    const std::size_t chunks = count == 0 ? 0 : (count + chunk - 1) / chunk;
    std::vector<T> parts(chunks, zero);
    parallelForDynamic(static_cast<int>(chunks), nthreads, 1, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const std::size_t a = static_cast<std::size_t>(k) * chunk;
            fn(a, std::min(count, a + chunk), parts[static_cast<std::size_t>(k)]);
        }
    });
    T total = zero;
    for (const T& p : parts)
        merge(total, p);
    return total;
}

// Per-channel histograms of values (8-bit code bins when codeAligned, else 4096 bins over the
// values' range) and the curve smoothing that suits them.
struct ChannelStats {
    std::array<ChannelHistogram, 3> histograms;
    std::array<double, 3> smoothing{};
};
ChannelStats channelStats(const std::vector<glm::vec3>& values, const std::vector<float>& weights,
                          bool codeAligned, int nthreads);

ColourMoments colourMoments(const std::vector<glm::vec3>& values, const std::vector<float>& weights,
                            int nthreads);

// Values mapped through fn on all threads.
std::vector<glm::vec3> mapValues(const std::vector<glm::vec3>& values,
                                 const std::function<glm::dvec3(const glm::dvec3&)>& fn,
                                 int nthreads);

} // namespace lut::detail
