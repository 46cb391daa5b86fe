#include "lut/pipeline/SmashDisplayEdit.h"

#include "lut/interp/Sampler.h"
#include "lut/pipeline/SmashGrading.h"

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

// Piecewise sRGB in double, mirrored for negatives and following the power segment above 1
// (the extension lut/pipeline/Transfer.h documents).
double srgbEncodeD(double x) {
    if (!(x == x))
        return 0.0;
    const double a = std::abs(x);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * std::pow(a, 1.0 / 2.4) - 0.055;
    return x < 0 ? -e : e;
}

double srgbDecodeD(double e) {
    if (!(e == e))
        return 0.0;
    const double a = std::abs(e);
    const double x = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
    return e < 0 ? -x : x;
}

} // namespace

Lut3D smashLutForDisplayEdit(const Lut3D& edit, const Lut3D* gameLut,
                             Interpolation editInterpolation) {
    const int n = kSmashLutSize;
    const double mix = kSmashBrightenMix, scale = kSmashBrightenScale;
    const double decode = kSmashDecodeExponent;
    const auto editSampler = makeSampler(edit, editInterpolation);
    // The game samples its LUT trilinearly; on a 16^3 LUT over [0,1] the lattice inputs are its
    // entries, read directly.
    const bool direct = gameLut && gameLut->size() == n &&
                        gameLut->domainMin() == glm::vec3(0.0f) &&
                        gameLut->domainMax() == glm::vec3(1.0f);
    const auto gameSampler =
        gameLut && !direct ? makeSampler(*gameLut, Interpolation::Trilinear) : nullptr;
    const glm::vec3 lo = edit.domainMin(), hi = edit.domainMax();
    const Lut3D lattice = Lut3D::identity(n);
    Lut3D out(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 sf = lattice.at(r, g, b);
                const glm::vec3 gf = !gameLut ? sf
                                     : direct ? gameLut->at(r, g, b)
                                              : gameSampler->sample(sf);
                glm::vec3 d, dc;
                for (int c = 0; c < 3; ++c) {
                    const double rr = ((double(gf[c]) - sf[c]) * mix + sf[c]) * scale;
                    d[c] = static_cast<float>(srgbEncodeD(rr > 0 ? std::pow(rr, decode) : 0.0));
                    dc[c] = std::clamp(d[c], lo[c], hi[c]);
                }
                const glm::vec3 e = editSampler->sample(dc);
                glm::vec3 entry;
                for (int c = 0; c < 3; ++c) {
                    const double edited = double(e[c]) + (double(d[c]) - double(dc[c]));
                    const double t = srgbDecodeD(edited);
                    const double rr = t > 0 ? std::pow(t, 1.0 / decode) : 0.0;
                    entry[c] = static_cast<float>((rr / scale - sf[c]) / mix + sf[c]);
                }
                out.at(r, g, b) = entry;
            }
    out.setTitle(!edit.title().empty() || !gameLut ? edit.title() : gameLut->title());
    return out;
}

} // namespace lut
