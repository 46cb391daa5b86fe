// SPDX-License-Identifier: Apache-2.0
// The text of a match report: see lut/match/MatchReport.h.
#include "lut/match/MatchReport.h"
#include "core/Printf.h"

#include <algorithm>
#include <cstdio>

namespace lut {

namespace {

using detail::fmt;

std::string distance(const DistributionDistance& d) {
    return fmt("sliced Wasserstein %.3g (CIELAB), quantile ΔE2000 %.3g", d.slicedWasserstein,
               d.quantileDeltaE);
}

double share(std::size_t part, std::size_t whole) {
    return 100.0 * static_cast<double>(part) / static_cast<double>(std::max<std::size_t>(whole, 1));
}

} // namespace

std::string MatchReport::str() const {
    std::string s;
    s += fmt("method   %s (%s)\n", toString(method), choice.c_str());
    if (candidates.size() > 1)
        for (const auto& c : candidates)
            s += fmt("         %-11s %s; fitted in %.3g s%s\n", toString(c.method),
                     distance(c.after).c_str(), c.seconds, c.shapeNote().c_str());
    if (sharpSecondMatch)
        s += "curves   hm-mkl-hm's second histogram match kept sharp (not smoothed): its LUT is "
             "clean and at least 10% closer to the reference\n";
    if (!look.empty())
        s += fmt("look     the reference is a colour per lightness: %s (its colours within %.2g "
                 "8-bit steps of that curve, root mean square)\n",
                 look.c_str(), lookRmsSteps);
    s += fmt("pixels   source: %zu of %zu counted; reference%s: %zu of %zu\n", sourceUsed,
             sourcePixels, references == 1 ? "" : "s", referenceUsed, referencePixels);
    s += fmt("before   %s\n", distance(before).c_str());
    s += fmt("after    %s\n", distance(after).c_str());
    s += fmt("LUT      against the transfer it tabulates, over the source's %zu colours: %s%s%s\n",
             interpolationColours, interpolation.str().c_str(), linear ? " (ACEScct steps)" : "",
             tableFitted ? " (the table's values fitted over these colours, so its steps fall "
                           "where the pixels put them)"
                         : "");
    if (bothForms)
        s += shaper ? fmt("form     a 1D shaper then the table: the look needs it (the table alone "
                          "would be %s)\n",
                          tableAloneError.str().c_str())
                    : fmt("form     the table alone, which every program reads (with a 1D shaper "
                          "before it: %s)\n",
                          shaperError.str().c_str());
    if (greyNodesMoved > 0)
        s += fmt("repaired the dip along grey (down by %.3g 8-bit steps): %d of the table's grey "
                 "nodes moved, by up to %.3g 8-bit steps\n",
                 greyDipRepaired, greyNodesMoved, greyLargestMove);
    s += fmt("shape    %s\n", quality.str().c_str());
    if (clippedValues > 0 || tableValuesOutside > 0)
        s += fmt("clipped  %.3g%% of the source's channel values land %s (up to %.3g 8-bit steps "
                 "beyond); %.3g%% of the table's values are there\n",
                 share(clippedValues, values), linear ? "below 0" : "outside [0, 1]",
                 clippedMaxSteps, share(tableValuesOutside, tableValues));
    else
        s += fmt("clipped  nothing: the result stays %s\n",
                 linear ? "at or above 0" : "inside [0, 1]");
    s += fmt("time     %.3g s (fit %.3g, LUT %.3g, measures %.3g)\n", secondsTotal(), secondsFit,
             secondsBake, secondsMeasure);
    return s;
}

} // namespace lut
