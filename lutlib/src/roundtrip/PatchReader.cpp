// Reading the patch's blocks and evaluating the measured edit between them; see
// lut/roundtrip/PatchReader.h.
#include "lut/roundtrip/PatchReader.h"

#include "interp/LatticeMapping.h"
#include "interp/ScalarLattice.h"
#include "lut/Error.h"
#include "lut/io/Layout.h"
#include "roundtrip/ColourDistance.h"
#include "roundtrip/MarkerFrame.h"

#include <algorithm>
#include <cmath>

namespace lut {

using detail::maxDiff;

PatchReading readPatch(const ImageView& img, const PatchPlacement& pl) {
    PatchReading out;
    out.placement = pl;
    const int n = pl.size, cell = pl.cell;
    int cw = 0, ch = 0;
    detail::patchCells(pl.layout, n, cw, ch);
    const int px0 = pl.patchX(), py0 = pl.patchY();
    if (px0 < 0 || py0 < 0 ||
        static_cast<long long>(px0) + static_cast<long long>(cw) * cell > img.width ||
        static_cast<long long>(py0) + static_cast<long long>(ch) * cell > img.height)
        throw Error("the LUT patch does not fit inside the image");
    out.values = Lut3D(n);
    out.axis.resize(n);
    for (int i = 0; i < n; ++i)
        out.axis[i] = patchInputValue(pl.lattice, i, n, pl.bitDepth);
    // Average the inner part of each block: its border pixels take the brunt of resampling,
    // JPEG ringing and a neighbour's bleed. Uniformity is judged on the whole block: a global
    // edit leaves a uniform block uniform, a blur or sharpen does not.
    const int inset = cell >= 3 ? 1 : 0;
    const int m = cell - 2 * inset;
    const double inv = 1.0 / (static_cast<double>(m) * m);
    const bool judgeBlocks = pl.cell % pl.scale == 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                int x = 0, y = 0;
                layoutPixel(pl.layout, n, r, g, b, x, y);
                const int bx = px0 + x * cell + inset, by = py0 + y * cell + inset;
                double acc[3] = {0, 0, 0};
                for (int dy = 0; dy < m; ++dy)
                    for (int dx = 0; dx < m; ++dx) {
                        const float* p = img.pixel(bx + dx, by + dy);
                        for (int c = 0; c < 3; ++c)
                            acc[c] += std::isfinite(p[c]) ? p[c] : 0.0f;
                    }
                const glm::vec3 mean(static_cast<float>(acc[0] * inv),
                                     static_cast<float>(acc[1] * inv),
                                     static_cast<float>(acc[2] * inv));
                double dev = 0.0;
                if (judgeBlocks)
                    for (int dy = 0; dy < cell; ++dy)
                        for (int dx = 0; dx < cell; ++dx) {
                            const float* p = img.pixel(px0 + x * cell + dx, py0 + y * cell + dy);
                            dev = std::max(dev, static_cast<double>(
                                                    maxDiff(glm::vec3(p[0], p[1], p[2]), mean)));
                        }
                dev *= 255.0;
                out.blockMaxDeviation = std::max(out.blockMaxDeviation, dev);
                if (dev > 2.5)
                    ++out.nonUniformBlocks;
                out.values.at(r, g, b) = mean;
            }
    return out;
}

PatchFunction::PatchFunction(const Lut3D& values, std::vector<float> axis)
    : m_values(values), m_axis(std::move(axis)) {
    if (m_values.empty() || static_cast<int>(m_axis.size()) != m_values.size() || m_axis.size() < 2)
        throw Error("PatchFunction: axis and table sizes differ");
}

glm::vec3 PatchFunction::operator()(glm::vec3 in) const {
    int ir, ig, ib;
    float fr, fg, fb;
    const int n = static_cast<int>(m_axis.size());
    detail::locateOnAxis(m_axis.data(), n, in.x, ir, fr);
    detail::locateOnAxis(m_axis.data(), n, in.y, ig, fg);
    detail::locateOnAxis(m_axis.data(), n, in.z, ib, fb);
    return detail::tetrahedralBlend(
        [this](int r, int g, int b) -> const glm::vec3& { return m_values.at(r, g, b); }, ir, ig,
        ib, fr, fg, fb);
}

} // namespace lut
