// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `lutkit match` and the editor's "Match to reference..." ask for: the method that carries
// the look of a reference picture over to a source picture, and what to keep of the source
// (docs/match.md). The names users type come from here (toString/parse*), so the command line,
// the editor and the messages cannot drift apart.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

// How the transfer is computed (docs/match.md, "Methods"):
//   Auto         every method below, each judged by its LUT applied to the source: HM-MKL-HM
//                (the floor) unless regularised or gradient-map is clean and 10% closer to the
//                reference (sliced Wasserstein distance in CIELAB); docs/match.md has the rule;
//   Hm           per-channel histogram matching: three 1D curves, no colour mixing;
//   Mkl          the linear Monge-Kantorovich map (Pitié & Kokaram 2007): a 3x3 matrix and an
//                offset taking the source's colour covariance to the reference's;
//   HmMklHm      histogram matching, MKL, histogram matching again: a 1D shaper and a 3D table;
//   Regularised  HM-MKL-HM refined towards the reference distribution by iterative 1D
//                transport along rotated axes (Pitié et al. 2005), then fitted as a smooth
//                lattice, monotone along each channel's own axis: for looks no affine or
//                per-channel map reaches;
//   GradientMap  a look whose colours lie on a curve of lightness (posterised palettes, gradient
//                maps, duotones, sepia): the source's luma (Rec. 709 weights on the working
//                values) histogram-matched to the reference's, with the steps the reference has,
//                then the reference's mean colour at that luma (lut/match/MatchTransfer.h).
//                auto tries it when the reference is such a look (lut/match/MatchReport.h).
enum class MatchMethod { Auto, Hm, Mkl, HmMklHm, Regularised, GradientMap };
// "auto", "hm", "mkl", "hm-mkl-hm", "regularised", "gradient-map"
const char* toString(MatchMethod method);
const std::vector<MatchMethod>& allMatchMethods();
std::vector<std::string> matchMethodAliases(MatchMethod method); // "regularized"
MatchMethod parseMatchMethod(std::string_view name);             // throws lut::Error

// What keeps the source's values (each blends towards the source in Oklab, per colour, smoothly):
//   Luma      lightness: only the colour of the look is taken (Oklab L of the source);
//   Neutrals  colours near grey keep their chroma (greys stay grey; weight falls off by CIELAB
//             chroma 6 .. 18);
//   Skin      skin tones keep their chroma and hue (CIELAB hue 30..70 degrees, chroma 10..45,
//             fading out to 15..85 degrees and 5..60) (lut/match/MatchFinish.h).
enum class MatchPreserve { Luma, Neutrals, Skin };
const char* toString(MatchPreserve preserve); // "luma", "neutrals", "skin"
const std::vector<MatchPreserve>& allMatchPreserves();
MatchPreserve parseMatchPreserve(std::string_view name); // throws lut::Error

// The LUT file's form:
//   Auto         matchLook: a 3D table alone (the .cube every program reads) unless the look needs
//   a 1D shaper before it to be
//                held (the table alone more than 8 8-bit steps from the transfer at the 99th
//                percentile, or 1 on average, over the source's colours): both are measured and
//                the report gives both errors; a scene-linear source always keeps its shaper (the
//                ACEScct curve and the range); bakeMatch: the shaper whenever the transfer has
//                one;
//   Table        a 3D table alone (the shaper's curves baked into it);
//   ShaperTable  a 1D shaper and a 3D table when the transfer has curves (DaVinci Resolve's
//                .cube, OpenColorIO).
enum class MatchLutForm { Auto, Table, ShaperTable };

struct MatchOptions {
    MatchLutForm form = MatchLutForm::Auto;
    MatchMethod method = MatchMethod::Auto;
    int size = 33; // edge of the 3D table, 2..129
    // The blend with neutral (lut/ops/Strength.h): 0 = neutral, 1 = the match, up to 2
    // exaggerates it; luma and chroma separately when set.
    double strength = 1.0;
    std::optional<double> lumaStrength, chromaStrength;
    std::vector<MatchPreserve> preserve;
    // Largest and smallest slope the 1D curves may take (contrast gain); beyond, the curve is
    // limited and a warning says so (a reference of two flat colours asks for a step).
    double maxSlope = 4.0;
    double minSlope = 1.0 / 16.0;
    // Largest colour gain of the MKL matrix (its eigenvalues are kept in [1/maxGain, maxGain]):
    // an almost grey source would otherwise have its noise blown up into colour.
    double maxGain = 4.0;
    int nthreads = 0; // 0 = all cores
};

} // namespace lut
