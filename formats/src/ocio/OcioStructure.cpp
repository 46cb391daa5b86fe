// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioStructure.h"

#include "ocio/OcioFacts.h"

#include "lut/Parallel.h"

#include <algorithm>
#include <cmath>

namespace lut::formats {

namespace {

enum class OpKind { Affine, Lut1D, Lut3D, Other };

OpKind kindOf(const OCIO::ConstTransformRcPtr& t) {
    if (auto l3 = OCIO::DynamicPtrCast<const OCIO::Lut3DTransform>(t))
        return l3->getDirection() == OCIO::TRANSFORM_DIR_FORWARD ? OpKind::Lut3D : OpKind::Other;
    if (auto l1 = OCIO::DynamicPtrCast<const OCIO::Lut1DTransform>(t))
        return l1->getDirection() == OCIO::TRANSFORM_DIR_FORWARD && !l1->getInputHalfDomain() &&
                       l1->getHueAdjust() == OCIO::HUE_NONE && l1->getLength() >= 2 &&
                       l1->getLength() <= 65536
                   ? OpKind::Lut1D
                   : OpKind::Other;
    if (OCIO::DynamicPtrCast<const OCIO::MatrixTransform>(t) ||
        OCIO::DynamicPtrCast<const OCIO::RangeTransform>(t))
        return OpKind::Affine;
    return OpKind::Other;
}

OCIO::ConstProcessorRcPtr processorOf(const OCIO::ConstConfigRcPtr& config,
                                      const OCIO::ConstGroupTransformRcPtr& group, int begin,
                                      int end) {
    auto g = OCIO::GroupTransform::Create();
    for (int i = begin; i < end; ++i) {
        auto t = group->getTransform(i)->createEditableCopy();
        // The 3D tables are evaluated as lutkit's sampler evaluates them.
        if (auto l3 = OCIO::DynamicPtrCast<OCIO::Lut3DTransform>(t))
            l3->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
        g->appendTransform(t);
    }
    return config->getProcessor(g);
}

glm::vec3 eval(const OCIO::ConstCPUProcessorRcPtr& cpu, glm::vec3 v) {
    cpu->applyRGB(&v.x);
    return v;
}

// The input range [lo, hi] that the scale-and-offset ops [begin, end) map onto [0,1] per
// channel, if they are exactly that (increasing, no channel mixing, affine within the range).
bool affineDomain(const OCIO::ConstConfigRcPtr& config, const OCIO::ConstGroupTransformRcPtr& g,
                  int begin, int end, glm::vec3& lo, glm::vec3& hi) {
    if (begin == end) {
        lo = glm::vec3(0.0f);
        hi = glm::vec3(1.0f);
        return true;
    }
    const auto p = processorOf(config, g, begin, end);
    if (p->hasChannelCrosstalk())
        return false;
    const auto cpu = faithfulCpu(p);
    const glm::vec3 a0 = eval(cpu, glm::vec3(0.0f)), a1 = eval(cpu, glm::vec3(1.0f));
    for (int c = 0; c < 3; ++c) {
        const double s = double(a1[c]) - a0[c];
        if (!(s > 1e-12) || !std::isfinite(s))
            return false;
        lo[c] = static_cast<float>((0.0 - a0[c]) / s);
        hi[c] = static_cast<float>((1.0 - a0[c]) / s);
        if (!std::isfinite(lo[c]) || !std::isfinite(hi[c]) || !(hi[c] > lo[c]))
            return false;
    }
    // Affine inside the range: the ends land on 0 and 1 and the quarter points in between.
    for (const float t : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
        const glm::vec3 x = lo + (hi - lo) * t;
        const glm::vec3 y = eval(cpu, x);
        for (int c = 0; c < 3; ++c)
            if (!(std::fabs(double(y[c]) - t) <= 1e-5))
                return false;
    }
    return true;
}

bool allAffine(const std::vector<OpKind>& kinds, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
        if (kinds[i] != OpKind::Affine)
            return false;
    return true;
}

} // namespace

OcioStructure analyseProcessor(const OCIO::ConstConfigRcPtr& config,
                               const OCIO::ConstProcessorRcPtr& processor) {
    OcioStructure s;
    const auto group = processor->createGroupTransform();
    const int n = group->getNumTransforms();
    std::vector<OpKind> kinds;
    int first1d = -1, first3d = -1, count1d = 0, count3d = 0;
    for (int i = 0; i < n; ++i) {
        kinds.push_back(kindOf(group->getTransform(i)));
        if (kinds.back() == OpKind::Lut1D) {
            count1d++;
            if (first1d < 0)
                first1d = i;
        } else if (kinds.back() == OpKind::Lut3D) {
            count3d++;
            if (first3d < 0)
                first3d = i;
        } else if (kinds.back() == OpKind::Other) {
            return s;
        }
    }
    const auto sz = [](int i) { return static_cast<std::size_t>(i); };
    if (count3d == 1 && count1d == 0) {
        if (!affineDomain(config, group, 0, first3d, s.domainMin, s.domainMax))
            return s;
        s.kind = OcioStructure::Kind::Cube;
        s.gridSize = OCIO::DynamicPtrCast<const OCIO::Lut3DTransform>(group->getTransform(first3d))
                         ->getGridSize();
        s.rest = processorOf(config, group, 0, n);
        return s;
    }
    if (count1d == 1 && count3d == 1 && first1d < first3d &&
        allAffine(kinds, sz(first1d + 1), sz(first3d))) {
        if (!affineDomain(config, group, 0, first1d, s.domainMin, s.domainMax))
            return s;
        s.kind = OcioStructure::Kind::ShaperCube;
        s.length1d = OCIO::DynamicPtrCast<const OCIO::Lut1DTransform>(group->getTransform(first1d))
                         ->getLength();
        s.gridSize = OCIO::DynamicPtrCast<const OCIO::Lut3DTransform>(group->getTransform(first3d))
                         ->getGridSize();
        s.shaper = processorOf(config, group, 0, first3d);
        s.rest = processorOf(config, group, first3d, n);
        return s;
    }
    if (count1d == 1 && count3d == 0) {
        if (!affineDomain(config, group, 0, first1d, s.domainMin, s.domainMax))
            return s;
        s.kind = OcioStructure::Kind::Curves;
        s.length1d = OCIO::DynamicPtrCast<const OCIO::Lut1DTransform>(group->getTransform(first1d))
                         ->getLength();
        s.rest = processorOf(config, group, 0, n);
        return s;
    }
    return s;
}

void applyRgb(const OCIO::ConstCPUProcessorRcPtr& cpu, float* rgb, std::size_t count,
              int nthreads) {
    constexpr std::size_t kChunk = 1 << 14;
    const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
    parallelForDynamic(chunks, nthreads, 1, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            const std::size_t begin = static_cast<std::size_t>(c) * kChunk;
            const std::size_t n = std::min(kChunk, count - begin);
            OCIO::PackedImageDesc desc(rgb + 3 * begin, static_cast<long>(n), 1, 3);
            cpu->apply(desc);
        }
    });
}

void applyRgba(const OCIO::ConstCPUProcessorRcPtr& cpu, float* rgba, std::size_t count) {
    OCIO::PackedImageDesc desc(rgba, static_cast<long>(count), 1, 4);
    cpu->apply(desc);
}

} // namespace lut::formats
