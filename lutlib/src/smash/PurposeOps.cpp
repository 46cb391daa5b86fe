// SPDX-License-Identifier: Apache-2.0
// Compose and mix with purposes; see lut/smash/PurposeOps.h.
#include "lut/smash/PurposeOps.h"

#include "lut/interp/Sampler.h"

#include <glm/common.hpp>

#include <algorithm>
#include <memory>

namespace lut {

namespace {

// `x` made for `to`, the conversion recorded under `name`.
Lut3D madeFor(const PurposedLut3D& x, LutPurpose to, const PurposeOptions& o,
              const std::string& name, PurposeOpResult& out) {
    if (x.purpose == to)
        return *x.lut;
    PurposeConversion c = convertPurpose(*x.lut, x.purpose, to, o);
    Lut3D lut = c.lut;
    out.conversions.emplace_back(name, std::move(c));
    return lut;
}

} // namespace

PurposeOpResult mixForPurpose(const PurposedLut3D& a, const PurposedLut3D& b, double t,
                              LutPurpose to, Interpolation method, const PurposeOptions& o) {
    PurposeOpResult out;
    const Lut3D la = madeFor(a, to, o, "A", out);
    const Lut3D lb = madeFor(b, to, o, "B", out);
    out.result = mix(la, lb, t, method, o.nthreads);
    return out;
}

PurposeDiff diffForPurpose(const PurposedLut3D& a, const PurposedLut3D& b, const ImageView* image,
                           const DiffOptions& options) {
    PurposeDiff out;
    if (a.purpose == LutPurpose::Raw && b.purpose == LutPurpose::Raw) {
        out.report = image ? diffLutsOnImage(*a.lut, *b.lut, *image, options)
                           : diffLuts(*a.lut, *b.lut, options);
        out.compared = "the two edits";
        return out;
    }
    // What the player sees for the display colour d with each.
    auto seen = [&](const PurposedLut3D& x) -> ColourMap {
        if (x.purpose == LutPurpose::Raw) {
            std::shared_ptr<const Sampler> edit = makeSampler(*x.lut, options.method);
            return [edit](glm::vec3 d) { return edit->sample(d); };
        }
        std::shared_ptr<const Sampler> game = makeSampler(*x.lut, Interpolation::Trilinear);
        return [game](glm::vec3 d) {
            return glm::vec3(gameShownForDisplayed(*game, glm::dvec3(glm::clamp(d, 0.0f, 1.0f))));
        };
    };
    DiffOptions o = options;
    if (o.size == 0)
        o.size = std::max({a.lut->size(), b.lut->size(), 33});
    out.report =
        image ? diffMapsOnImage(seen(a), seen(b), *image, o) : diffMaps(seen(a), seen(b), o);
    auto what = [](const PurposedLut3D& x) {
        return x.purpose == LutPurpose::Smash ? "the game's LUT, as the game shows it"
                                              : "an edit, as it is";
    };
    out.compared = std::string("what the player sees with each (A: ") + what(a) +
                   "; B: " + what(b) +
                   "; where the neutral game shows each colour, as lutkit preview "
                   "shows a screenshot)";
    return out;
}

PurposeOpResult composeForPurpose(const PurposedLut3D& a, const PurposedLut3D& b, LutPurpose to,
                                  const ComposeOptions& compose, const PurposeOptions& o) {
    PurposeOpResult out;
    const Lut3D editB = madeFor(b, LutPurpose::Raw, o, "B", out);
    if (to == LutPurpose::Smash && a.purpose == LutPurpose::Smash) {
        // B's edit on the picture A makes: A is the stage.
        PurposeOptions staged = o;
        staged.stageLut = a.lut;
        PurposeConversion c = convertPurpose(editB, LutPurpose::Raw, LutPurpose::Smash, staged);
        out.result.lut = c.lut;
        out.tableOp = false;
        out.conversions.emplace_back("B on A's picture", std::move(c));
        return out;
    }
    const Lut3D editA = madeFor(a, LutPurpose::Raw, o, "A", out);
    out.result = lut::compose(editA, editB, compose);
    if (to == LutPurpose::Smash) {
        PurposeConversion c = convertPurpose(out.result.lut, LutPurpose::Raw, to, o);
        out.result.lut = c.lut;
        out.conversions.emplace_back("result", std::move(c));
    }
    return out;
}

} // namespace lut
