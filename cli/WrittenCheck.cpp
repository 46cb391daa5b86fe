// SPDX-License-Identifier: Apache-2.0
#include "WrittenCheck.h"

#include "lut/Error.h"
#include "lut/check/CheckLut.h"
#include "lut/io/FileNames.h"
#include "lut/io/OutputPolicy.h"
#include "lut/smash/SmashShownEdit.h"

#include <cstdio>
#include <iostream>

namespace lut::cli {

void checkWrittenLut(const std::string& path, const LutFile& written, const Verbosity& verbosity,
                     bool shownByGame) {
    (void)verbosity; // -q keeps warnings (Notes.h)
    if (!written.cube && !written.shaper)
        return;
    CheckOptions options;
    options.measureNeutral = false; // informational only, and the slowest part
    CheckReport report;
    try {
        if (shownByGame) {
            LutFile shown;
            shown.cube = smashShownEdit(written.toLut3D());
            report = checkLut(shown, options);
        } else {
            report = checkLut(written, options);
        }
    } catch (const Error&) {
        return; // the write succeeded; the check has nothing to say about an empty table
    }
    const std::string name = isStdStream(path) ? "the LUT written" : path;
    for (const CheckSummary& c : report.checks) {
        if (c.status != CheckStatus::Fail)
            continue;
        std::string worst = c.text;
        for (const CheckFinding& f : report.findings)
            if (checkOf(f.kind) == c.kind && f.severity == CheckStatus::Fail) {
                worst = f.text();
                break;
            }
        std::cerr << "lutkit: warning: " << printable(name) << ": check " << toString(c.kind)
                  << (shownByGame ? " of the edit the game shows" : "") << " fails: " << worst
                  << "\n";
    }
    if (report.status() == CheckStatus::Fail && !shownByGame)
        std::cerr << "lutkit: " << printable(name) << ": 'lutkit check"
                  << (isStdStream(path) ? "" : " " + printable(path))
                  << " --report check.png' shows where\n";
    else if (report.status() == CheckStatus::Fail)
        std::cerr << "lutkit: " << printable(name) << ": 'lutkit check"
                  << (isStdStream(path) ? "" : " " + printable(path))
                  << " --target smash --report check.png' shows where\n";
}

void checkWrittenLut(const std::string& path, const Lut3D& written, const Verbosity& verbosity,
                     bool shownByGame) {
    LutFile file;
    file.cube = written;
    checkWrittenLut(path, file, verbosity, shownByGame);
}

} // namespace lut::cli
