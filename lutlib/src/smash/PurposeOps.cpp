// SPDX-License-Identifier: Apache-2.0
// Compose and mix with purposes; see lut/smash/PurposeOps.h.
#include "lut/smash/PurposeOps.h"

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
