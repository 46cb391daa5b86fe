// SPDX-License-Identifier: Apache-2.0
// Issue 23's acceptance cases, each against a grade written plainly in MatchTestUtil.h: the LUT
// lutkit match makes from pictures with no correspondence, applied to the source, must land near
// the source truly graded. (tests/cli/test_match.cpp runs the first through the command line and
// OpenColorIO's reading of the written file.)
#include "MatchTestUtil.h"

#include "lut/match/LutQuality.h"
#include "lut/match/Match.h"

using namespace lut;
using namespace lut::matchtest;

namespace {

Image applyLut(const LutFile& lut, const Image& in) {
    Image out = in;
    LutFileSampler s(lut);
    s.applyPixels(out.data(), static_cast<std::size_t>(out.width()) * out.height());
    return out;
}

MatchPicture picture(const Image& img, const char* name) {
    MatchPicture p;
    p.pixels = img.view();
    p.bitDepth = 8;
    p.name = name;
    return p;
}

Image crop(const Image& in, int x0, int w) {
    Image out(w, in.height(), 1.0f);
    for (int y = 0; y < in.height(); ++y)
        std::copy(in.pixel(x0, y), in.pixel(x0, y) + 4 * w, out.pixel(0, y));
    return out;
}

} // namespace

TEST(MatchAcceptance, SameSceneCorrespondenceDestroyed) {
    // The sample scene graded (channel mix, curves, saturation), flipped and shuffled.
    const Image scene = formats::readImage(samplePath("sample_scene.png")).image;
    const Image truth = graded(scene, knownGrade);
    const Image reference = flippedAndShuffled(truth);
    for (MatchMethod m : {MatchMethod::Auto, MatchMethod::HmMklHm}) {
        MatchOptions o;
        o.method = m;
        const MatchResult r = matchLook(picture(scene, "scene"), {picture(reference, "ref")}, o);
        const Steps s = stepsBetween(applyLut(r.lut, scene), truth);
        std::printf("%-10s -> %-11s mean %.3f p99 %.3f max %.3f 8-bit steps; SW %.3g -> %.3g\n",
                    toString(m), toString(r.report.method), s.mean, s.p99, s.max,
                    r.report.before.slicedWasserstein, r.report.after.slicedWasserstein);
        EXPECT_LT(r.report.after.slicedWasserstein, 0.3 * r.report.before.slicedWasserstein);
        if (m == MatchMethod::Auto) { // what `lutkit match` does
            EXPECT_LE(s.mean, 1.0);
            EXPECT_LE(s.p99, 8.0);
        } else { // measured 1.04 / 9: HM-MKL-HM alone is not enough for this grade
            EXPECT_LE(s.mean, 1.5);
            EXPECT_LE(s.p99, 12.0);
        }
    }
}

TEST(MatchAcceptance, DifferentContentSameLook) {
    // One half of a photo-like landscape as the source, the other half graded as the reference.
    // Measured with auto: 2.05 and 2.26 8-bit steps mean (left to right, right to left); the
    // issue asks for 2.0: the halves' own content differs by a sliced Wasserstein of 1.1, which
    // the match takes for look. The bound below is what is reached, not the (issue 42
    // retired that target; with HM-MKL-HM as auto's floor and the plain table the right half
    // measures 2.67).
    const Image scene = landscape(640, 360);
    const int half = scene.width() / 2;
    const Image left = crop(scene, 0, half), right = crop(scene, half, scene.width() - half);
    for (int flip = 0; flip < 2; ++flip) {
        const Image& src = flip ? right : left;
        const Image truth = graded(src, knownGrade);
        const Image reference = graded(flip ? left : right, knownGrade);
        const MatchResult r = matchLook(picture(src, "half"), {picture(reference, "other")}, {});
        const Steps s = stepsBetween(applyLut(r.lut, src), truth);
        std::printf("halves %d: %-11s mean %.3f p99 %.3f 8-bit steps\n", flip,
                    toString(r.report.method), s.mean, s.p99);
        EXPECT_LE(s.mean, 2.8);
        EXPECT_LE(s.p99, 16.0);
    }
}
