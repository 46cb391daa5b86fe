// SPDX-License-Identifier: Apache-2.0
#include "ocio/CspWriter.h"

#include "ocio/OcioSession.h"

#include "lut/Error.h"
#include "lut/ops/Resample.h"

#include <algorithm>
#include <cstdio>

namespace lut::formats {

namespace {

constexpr int kMinPrelutPoints = 4096;

// %.9g: every float reads back as itself.
void put(std::string& out, double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    out += buf;
}

void putTriplet(std::string& out, glm::vec3 v) {
    put(out, v.x);
    out += ' ';
    put(out, v.y);
    out += ' ';
    put(out, v.z);
    out += '\n';
}

} // namespace

std::string cspWithShaperBytes(const std::string& path, const LutFile& file, int size,
                               Diagnostics& diags) {
    std::optional<Lut3D> cube = file.cube;
    if (cube && size != 0 && size != cube->size()) {
        diags.push_back(ocioDiagnostic(path, "3D table resampled from " +
                                                 std::to_string(cube->size()) + "^3 to " +
                                                 std::to_string(size) + "^3 (tetrahedral)"));
        Lut3D r = resample(*cube, size, Interpolation::Tetrahedral);
        r.setDomain(cube->domainMin(), cube->domainMax());
        cube = std::move(r);
    }
    if (!cube && !file.shaper)
        throw Error(path + ": the LUT holds no table");
    // The table after the prelut spans [0,1]: a cube's own input range is folded into the
    // prelut's outputs (a straight map, exact).
    const glm::vec3 cmin = cube ? cube->domainMin() : glm::vec3(0.0f);
    const glm::vec3 cmax = cube ? cube->domainMax() : glm::vec3(1.0f);
    std::string text = "CSPLUTV100\n";
    text += cube ? "3D\n\n" : "1D\n\n";
    const std::string title = cube ? cube->title() : file.shaper->title();
    text += "BEGIN METADATA\n";
    if (!title.empty())
        text += title + "\n";
    if (file.purpose)
        text += purposeTag(*file.purpose) + "\n";
    text += "END METADATA\n\n";
    for (int c = 0; c < 3; ++c) {
        if (file.shaper && cube) {
            // OCIO reads the prelut as a cubic through its points: between the points of a coarse
            // curved shaper that bends away from lutkit's straight segments. Each segment is cut
            // into k straight pieces (at least 4096 points in all), so the cubic has little room.
            const Lut1D& sh = *file.shaper;
            const int n = sh.size();
            const int k = std::max(1, (kMinPrelutPoints + n - 2) / (n - 1));
            const int points = (n - 1) * k + 1;
            text += std::to_string(points) + "\n";
            const double lo = sh.domainMin()[c], hi = sh.domainMax()[c];
            for (int i = 0; i < points; ++i) {
                put(text, lo + (hi - lo) * i / (points - 1));
                text += i + 1 < points ? ' ' : '\n';
            }
            for (int i = 0; i < points; ++i) {
                const int seg = std::min(i / k, n - 2);
                const double t = double(i - seg * k) / k;
                const double v = double(sh[seg][c]) + t * (double(sh[seg + 1][c]) - sh[seg][c]);
                put(text, (v - cmin[c]) / (double(cmax[c]) - cmin[c]));
                text += i + 1 < points ? ' ' : '\n';
            }
        } else {
            // A straight prelut: the table's own input range onto [0,1].
            const double lo = cube ? cmin[c] : file.shaper->domainMin()[c];
            const double hi = cube ? cmax[c] : file.shaper->domainMax()[c];
            text += "2\n";
            put(text, lo);
            text += ' ';
            put(text, hi);
            text += "\n0 1\n";
        }
    }
    text += "\n";
    if (cube) {
        const int n = cube->size();
        text += std::to_string(n) + " " + std::to_string(n) + " " + std::to_string(n) + "\n";
        // Red fastest, as .csp stores it.
        for (const glm::vec3& v : cube->entries())
            putTriplet(text, v);
    } else {
        const Lut1D& sh = *file.shaper;
        text += std::to_string(sh.size()) + "\n";
        for (const glm::vec3& v : sh.entries())
            putTriplet(text, v);
    }
    return text;
}

} // namespace lut::formats
