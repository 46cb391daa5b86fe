// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioFacts.h"

#include <algorithm>

namespace lut::formats {

namespace {

int bitDepthBits(OCIO::BitDepth d) {
    switch (d) {
    case OCIO::BIT_DEPTH_UINT8:
        return 8;
    case OCIO::BIT_DEPTH_UINT10:
        return 10;
    case OCIO::BIT_DEPTH_UINT12:
        return 12;
    case OCIO::BIT_DEPTH_UINT14:
        return 14;
    case OCIO::BIT_DEPTH_UINT16:
        return 16;
    default:
        return 0;
    }
}

void collectMetadata(const OCIO::FormatMetadata& md, ProcessorFacts& facts) {
    if (facts.title.empty()) {
        const char* name = md.getName();
        if (name && *name)
            facts.title = name;
    }
    for (int i = 0; i < md.getNumChildrenElements(); ++i) {
        const auto& child = md.getChildElement(i);
        const char* v = child.getElementValue();
        if (v && *v && facts.comments.size() < 1000)
            facts.comments.emplace_back(v);
    }
}

} // namespace

ProcessorFacts inspectProcessor(const OCIO::ConstProcessorRcPtr& processor) {
    ProcessorFacts facts;
    collectMetadata(processor->getFormatMetadata(), facts);
    const auto group = processor->createGroupTransform();
    for (int i = 0; i < group->getNumTransforms(); ++i) {
        const auto t = group->getTransform(i);
        if (auto l3 = OCIO::DynamicPtrCast<const OCIO::Lut3DTransform>(t)) {
            ++facts.lut3dCount;
            facts.gridSize = std::max(facts.gridSize, l3->getGridSize());
            facts.bitDepth = std::max(facts.bitDepth, bitDepthBits(l3->getFileOutputBitDepth()));
            collectMetadata(l3->getFormatMetadata(), facts);
        } else if (auto l1 = OCIO::DynamicPtrCast<const OCIO::Lut1DTransform>(t)) {
            ++facts.lut1dCount;
            facts.length1d = std::max(facts.length1d, l1->getLength());
            facts.halfDomain = facts.halfDomain || l1->getInputHalfDomain();
            facts.bitDepth = std::max(facts.bitDepth, bitDepthBits(l1->getFileOutputBitDepth()));
            collectMetadata(l1->getFormatMetadata(), facts);
        } else {
            ++facts.otherCount;
        }
    }
    return facts;
}

std::string ProcessorFacts::opsText() const {
    return std::to_string(lut1dCount) + " 1D LUT, " + std::to_string(lut3dCount) + " 3D LUT, " +
           std::to_string(otherCount) + " other op" + (otherCount == 1 ? "" : "s");
}

OCIO::ConstCPUProcessorRcPtr faithfulCpu(const OCIO::ConstProcessorRcPtr& processor) {
    return processor->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                               OCIO::OPTIMIZATION_NONE);
}

} // namespace lut::formats
