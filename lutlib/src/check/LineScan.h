// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's LUT check: one line of samples through the cube (a lattice line or a ray)
// looked at for fold-overs, banding (flat runs, steps, steep slopes), clips and second
// differences. Positions are in segment units: segment i runs from sample i to sample i + 1.
#include "lut/check/CheckFinding.h"
#include "lut/check/CheckThresholds.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lut::check {

// The values an output channel is clipped at: 0 and 1, and the table's own extremes.
struct ClipBounds {
    std::array<std::array<float, 2>, 3> top{};    // per channel
    std::array<std::array<float, 2>, 3> bottom{}; // per channel
    bool atTop(int c, float v) const {
        const auto& b = top[static_cast<std::size_t>(c)];
        return near(v, b[0]) || near(v, b[1]);
    }
    bool atBottom(int c, float v) const {
        const auto& b = bottom[static_cast<std::size_t>(c)];
        return near(v, b[0]) || near(v, b[1]);
    }
    bool atBound(int c, float v) const { return atTop(c, v) || atBottom(c, v); }
    // Both values within an 8-bit step of the same bound.
    bool heldNear(int c, float a, float b) const;

private:
    static bool near(float v, float bound) {
        const float d = v - bound, tolerance = 1e-4f * std::max(1.0f, std::fabs(bound));
        return d <= tolerance && d >= -tolerance;
    }
};

struct LineEvent {
    FindingKind kind = FindingKind::FoldOver;
    int channel = -1;
    int variant = 0;        // Clip: 0 top, 1 bottom
    int begin = 0, end = 0; // segments [begin, end); Rough: the sample is `begin`, end = begin
    double size = 0.0;      // in 8-bit steps (double: an entry near FLT_MAX times 255 stays finite)
    float at = 0.0f;        // the worst place, in segment units from sample 0
    float from = 0.0f, to = 0.0f;
    // Clip: the share of the first and last segment of [begin, end) that is clipped.
    float firstFraction = 1.0f, lastFraction = 1.0f;
};

struct LineFigures {
    double ownVariation = 0.0; // sum |step| of the line's own channel
    double ownNet = 0.0;       // |last - first| of it
    double worstFold = 0.0;    // 8-bit steps
    double steepest = 0.0;     // output steps per input step
};

struct LineSpec {
    const glm::vec3* values = nullptr;
    int count = 0;
    double step = 1.0; // input distance between samples, as a fraction of the domain
    // Where it varies (a table behind a 1D shaper: the file's input distance of each lattice
    // step), per segment; slopes are then output steps per input step of the file, each from its
    // sample over the segments that span one input 8-bit step at least.
    const double* segmentSteps = nullptr;
    glm::ivec3 direction{0}; // channels that must move one way along the line
    int ownChannel = -1;     // a lattice line's axis: clips, second differences; -1 for rays
};

// Appends the line's events (those at or above the warn thresholds) and accumulates figures.
void scanLine(const LineSpec& line, const ClipBounds& bounds, const CheckThresholds& thresholds,
              std::vector<LineEvent>& events, LineFigures& figures);

} // namespace lut::check
