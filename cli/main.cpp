// lutkit: the command-line front end. The only translation unit that includes CLI11.
// main catches library errors, then CLI::Error, then the rest (CLI11's subcom_in_files shape).
#include "Commands.h"

#include "lut/Error.h"
#include "lut/Version.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

using namespace lut::cli;

namespace {

int g_exitCode = kExitOk;

// Runs a subcommand, turning library errors into a one-line message and exit code 1.
template <class Fn> void guarded(Fn&& fn) {
    try {
        g_exitCode = fn();
    } catch (const UsageError& e) {
        std::cerr << "lutkit: " << e.what() << "\n";
        g_exitCode = kExitUsage;
    } catch (const lut::Error& e) {
        std::cerr << "lutkit: error: " << e.what() << "\n";
        g_exitCode = kExitFailure;
    } catch (const std::bad_alloc&) {
        std::cerr << "lutkit: error: out of memory\n";
        g_exitCode = kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "lutkit: error: " << e.what() << "\n";
        g_exitCode = kExitFailure;
    }
}

} // namespace

// Subcommand wiring, one file per subcommand, all in this translation unit.
#include "setup_apply.inc"
#include "setup_bench.inc"
#include "setup_convert.inc"
#include "setup_embed.inc"
#include "setup_extract.inc"
#include "setup_fit.inc"
#include "setup_info.inc"
#include "setup_neutral.inc"
#include "setup_preview.inc"
#include "setup_validate.inc"

int main(int argc, char** argv) {
    CLI::App app{"lutkit: author and convert colour grading LUTs", "lutkit"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("lutkit ") + LUTKIT_VERSION);

    // Each setup_NAME.inc (owned with cmd_NAME.cpp) defines setupNAME(CLI::App&), which adds one
    // subcommand whose callback calls guarded([&]{ return runNAME(options); }).
    setupNeutral(app);
    setupConvert(app);
    setupInfo(app);
    setupValidate(app);
    setupApply(app);
    setupPreview(app);
    setupEmbed(app);
    setupExtract(app);
    setupFit(app);
    setupBench(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitUsage;
    }
    return g_exitCode;
}
