// SPDX-License-Identifier: Apache-2.0
// lut::checkLut: the parts of the check (CheckDetail.h) in order, then one summary per check.
#include "lut/check/CheckLut.h"

#include "check/CheckDetail.h"
#include "core/Printf.h"

#include "lut/Error.h"
#include "lut/ops/Diff.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut {

using detail::fmt;

namespace {

std::string describe(const LutFile& file) {
    std::string s;
    if (file.shaper)
        s += "1D " + std::to_string(file.shaper->size()) + (file.cube ? " shaper + " : "");
    if (file.cube)
        s += "3D " + std::to_string(file.cube->size()) + "^3";
    return s;
}

void measureNeutral(const LutFile& file, CheckFigures& figures, int nthreads) {
    Lut3D table = file.shaper || !file.cube ? file.toLut3D(33) : *file.cube;
    Lut3D identity(table.size());
    identity.setDomain(table.domainMin(), table.domainMax());
    const int n = table.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                identity.at(r, g, b) = identity.latticeInput(r, g, b);
    DiffOptions o;
    o.nthreads = nthreads;
    const DiffReport d = diffLuts(identity, table, o);
    figures.neutralMeasured = true;
    figures.neutralMaxDeltaE = d.maxDeltaE;
    figures.neutralMeanDeltaE = d.meanDeltaE;
    figures.neutralMaxSteps = std::max({d.maxSteps8.x, d.maxSteps8.y, d.maxSteps8.z});
}

double scoreOf(const CheckFinding& f, const CheckThresholds& t) {
    const Threshold& th = check::thresholdFor(t, f.kind);
    const double figure =
        f.kind == FindingKind::Clip || f.kind == FindingKind::OutOfRange ? 100.0 * f.share : f.size;
    return figure / std::max(1e-9, th.warn);
}

void summarise(CheckReport& report, const CheckThresholds& t, bool oneD) {
    const CheckFigures& f = report.figures;
    const char* of = report.image ? "of the picture" : "of the cube";
    for (int k = 0; k < kCheckKindCount; ++k) {
        report.checks[static_cast<std::size_t>(k)].kind = static_cast<CheckKind>(k);
        report.checks[static_cast<std::size_t>(k)].status = CheckStatus::Pass;
    }
    for (const CheckFinding& x : report.findings) {
        CheckStatus& s = report.checks[static_cast<std::size_t>(checkOf(x.kind))].status;
        s = std::max(s, x.severity);
    }
    auto text = [&](CheckKind k) -> std::string& {
        return report.checks[static_cast<std::size_t>(k)].text;
    };
    text(CheckKind::Monotonicity) =
        (oneD ? std::string(f.worstFold > 0.0 ? "curves fold back" : "every curve monotone")
         : f.greyWorstFold > 0.0 ? fmt("grey axis folds back %.2f 8-bit steps", f.greyWorstFold)
                                 : std::string("grey axis monotone")) +
        (f.worstFold > 0.0 ? fmt("; worst fold-over %.2f 8-bit steps, %.2f%% ", f.worstFold,
                                 100.0 * f.foldShare) +
                                 of
                           : std::string("; every lattice line monotone")) +
        // A line that falls end to end is monotone (a negative LUT's way), and a finding may say
        // its channel "jumps from 65504 to -65504": the summary says so, not a bare "monotone".
        (!oneD && f.fallingShare > 0.0
             ? fmt(" (%.0f%% of them falling end to end: the table inverts there)",
                   100.0 * f.fallingShare)
             : std::string());
    text(CheckKind::Banding) =
        fmt("steepest %.2f output steps per input step", f.steepest) +
        (f.worstStep > 0.0 ? fmt("; worst step %.1f 8-bit steps", f.worstStep) : "") +
        (f.worstFlat > 0.0 ? fmt("; worst flat run loses %.1f 8-bit steps", f.worstFlat) : "") +
        (f.worstStep <= 0.0 && f.worstFlat <= 0.0 ? "; no flat runs or steps" : "");
    text(CheckKind::Hue) = fmt("worst hue shift %+.1f degrees at Oklab hue %.1f; mean |shift| "
                               "%.1f degrees; skin line drift %+.1f degrees",
                               f.worstHueShift, f.worstHue, f.meanHueShift, f.skinDrift);
    std::string range = f.nonFinite ? std::to_string(f.nonFinite) + " NaN/Inf entries; "
                                    : std::string("no NaN/Inf; ");
    const float lo = std::min({f.outputMin.x, f.outputMin.y, f.outputMin.z});
    const float hi = std::max({f.outputMax.x, f.outputMax.y, f.outputMax.z});
    // 1e30 as 1e+30, not 31 digits.
    const char* spec =
        std::max(std::fabs(lo), std::fabs(hi)) >= 1e6f ? "output %.4g..%.4g" : "output %.3f..%.3f";
    range += fmt(spec, lo, hi);
    if (lo < -65504.0f || hi > 65504.0f)
        range += " (the checks take values beyond +-65504 as +-65504, half-float's range)";
    if (f.outOfRangeShare > 0.0)
        range += fmt(" (%.2f%% outside [0, 1])", 100.0 * f.outOfRangeShare);
    range += fmt("; clipped R %.2f%% G %.2f%% B %.2f%% ", 100.0 * f.clippedShare[0],
                 100.0 * f.clippedShare[1], 100.0 * f.clippedShare[2]) +
             of + fmt("; reaches %.0f%% of the output cube", 100.0 * f.gamutCoverage);
    if (report.image)
        range += fmt("; %.2f%% of the picture outside the domain", 100.0 * f.imageOutsideDomain);
    text(CheckKind::Range) = range;
    text(CheckKind::Smoothness) =
        fmt("worst second difference %.2f 8-bit steps (33-point spacing); total variation "
            "%.3fx the net change",
            f.worstRough, f.totalVariationRatio);
    CheckStatus& inv = report.checks[static_cast<std::size_t>(CheckKind::Invertibility)].status;
    inv = std::max(inv, check::grade(100.0 * f.foldedShare, t.folded));
    text(CheckKind::Invertibility) =
        f.foldedShare <= 0.0 && f.flatShare <= 0.0
            ? std::string("one-to-one everywhere")
            : fmt("%.2f%% folded, %.2f%% flat ", 100.0 * f.foldedShare, 100.0 * f.flatShare) + of +
                  " (no unique inverse there)" +
                  (f.foldedShare > 0.0 ? fmt("; worst fold in the cell at RGB (%.3f, %.3f, %.3f)",
                                             f.worstFolded.x, f.worstFolded.y, f.worstFolded.z)
                                       : std::string());
    text(CheckKind::Neutral) =
        f.neutralMeasured
            ? fmt("distance from neutral: max dE2000 %.2f (%.1f 8-bit steps), mean %.2f",
                  f.neutralMaxDeltaE, f.neutralMaxSteps, f.neutralMeanDeltaE)
            : std::string("not measured");
}

} // namespace

CheckStatus CheckReport::status() const {
    CheckStatus s = CheckStatus::Pass;
    for (const CheckSummary& c : checks)
        s = std::max(s, c.status);
    return s;
}

CheckReport checkLut(const LutFile& file, const CheckOptions& options) {
    const long long start = detail::nowNanos();
    const check::Context ctx(file, options);
    CheckReport report;
    report.image = ctx.image();
    report.description = describe(file);
    CheckFigures& fig = report.figures;
    std::vector<CheckFinding> findings;
    if (ctx.hasTable()) {
        std::vector<check::Flag> flags;
        check::scanLattice(ctx, flags, fig);
        check::scanEntries(ctx, flags, fig);
        check::groupFlags(ctx, flags, findings, fig);
        glm::vec3 worstFolded(0.0f);
        check::measureInvertibility(ctx, fig, worstFolded);
        fig.worstFolded = ctx.fileInput(worstFolded);
        if (file.shaper) { // the shaper's own curves, as a file of its own
            LutFile shaperOnly;
            shaperOnly.shaper = file.shaper;
            const check::Context shaperCtx(shaperOnly, options);
            CheckFigures sf;
            std::vector<CheckFinding> shaperFindings;
            check::scan1D(shaperCtx, shaperFindings, sf);
            for (CheckFinding& f : shaperFindings) {
                // The shaper's output is a place in the table, not a colour: its slope and
                // curvature are no finding (a gamma encode's shaper is steep near black); the
                // file's own, the shaper then the table, are judged on the lattice and the rays.
                if (f.kind == FindingKind::Steep || f.kind == FindingKind::Rough)
                    continue;
                f.where = "in the shaper, " + f.where;
                findings.push_back(std::move(f));
            }
            fig.nonFinite += sf.nonFinite;
            fig.worstFold = std::max(fig.worstFold, sf.worstFold);
        }
    } else {
        check::scan1D(ctx, findings, fig);
    }
    check::checkHue(ctx, findings, fig);
    check::measureGamut(ctx, fig);
    if (ctx.image())
        fig.imageOutsideDomain = ctx.imageOutsideDomain();
    if (options.measureNeutral)
        measureNeutral(file, fig, options.nthreads);
    const CheckThresholds& t = options.thresholds;
    std::stable_sort(findings.begin(), findings.end(),
                     [&](const CheckFinding& a, const CheckFinding& b) {
                         if (a.severity != b.severity)
                             return a.severity > b.severity;
                         return scoreOf(a, t) > scoreOf(b, t);
                     });
    report.findings = std::move(findings);
    summarise(report, t, !ctx.hasTable()); // every finding counts in its check's status
    if (report.findings.size() > options.maxFindings) {
        report.findingsLeftOut = report.findings.size() - options.maxFindings;
        report.findings.resize(options.maxFindings);
    }
    report.seconds = detail::secondsSince(start);
    return report;
}

CheckReport checkLut(const Lut3D& lut, const CheckOptions& options) {
    if (lut.empty())
        throw Error("check: the LUT has no entries");
    LutFile file;
    file.cube = lut;
    return checkLut(file, options);
}

} // namespace lut
