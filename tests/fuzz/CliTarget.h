#pragma once
// Fuzz target for the CLI's argument handling: the real subcommand set-up files
// (cli/setup_*.inc, where CLI11 converts and checks numbers and words) parse fuzzed argument
// lists, with each run function replaced by a stub that checks what validation promised (a
// --size that got through is 2..256, --bit-depth 8/16/32, --interp a name parseInterpolation
// knows). CLI11 must turn any bad argument into a CLI::ParseError (exit code 2 in main.cpp);
// any other exception escaping is a finding.
//
// Include this from exactly one translation unit: it defines the stub run functions.
#include "lut/Error.h"
#include "lut/interp/Interpolation.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace lut::fuzz::cli_stub {

inline void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "CLI validation let through: %s\n", what);
        std::abort();
    }
}
inline void checkSize(int size) {
    check(size == 0 || (size >= 2 && size <= 256), "--size outside 2..256");
}
inline void checkBitDepth(int bits) {
    check(bits == 0 || bits == 8 || bits == 16 || bits == 32, "--bit-depth not 8/16/32");
}
inline void checkInterp(const std::string& name) {
    try {
        (void)lut::parseInterpolation(name);
    } catch (const lut::Error&) {
        check(false, "--interp that parseInterpolation refuses");
    }
}

inline int g_exitCode = 0;
template <class Fn> void guarded(Fn&& fn) {
    g_exitCode = fn();
}

} // namespace lut::fuzz::cli_stub

// The setup files call guarded(...) unqualified, as in main.cpp.
using lut::fuzz::cli_stub::guarded;

#if __has_include("../../cli/setup_neutral.inc")
#include "../../cli/setup_neutral.inc"
int lut::cli::runNeutral(const NeutralOptions& o) {
    lut::fuzz::cli_stub::checkSize(o.size);
    lut::fuzz::cli_stub::checkBitDepth(o.bitDepth);
    return 0;
}
#endif
#if __has_include("../../cli/setup_convert.inc")
#include "../../cli/setup_convert.inc"
int lut::cli::runConvert(const ConvertOptions& o) {
    lut::fuzz::cli_stub::checkSize(o.size);
    lut::fuzz::cli_stub::checkBitDepth(o.bitDepth);
    lut::fuzz::cli_stub::checkInterp(o.interp);
    return 0;
}
#endif
#if __has_include("../../cli/setup_info.inc")
#include "../../cli/setup_info.inc"
int lut::cli::runInfo(const InfoOptions& o) {
    lut::fuzz::cli_stub::checkSize(o.size);
    return 0;
}
#endif

#if __has_include("../../cli/setup_validate.inc")
#include "../../cli/setup_validate.inc"
int lut::cli::runValidate(const ValidateOptions&) {
    return 0;
}
#endif
#if __has_include("../../cli/setup_apply.inc")
#include "../../cli/setup_apply.inc"
int lut::cli::runApply(const ApplyOptions&) {
    return 0;
}
#endif
#if __has_include("../../cli/setup_preview.inc")
#include "../../cli/setup_preview.inc"
int lut::cli::runPreview(const PreviewOptions&) {
    return 0;
}
#endif
#if __has_include("../../cli/setup_embed.inc")
#include "../../cli/setup_embed.inc"
int lut::cli::runEmbed(const EmbedOptions&) {
    return 0;
}
#endif
#if __has_include("../../cli/setup_extract.inc")
#include "../../cli/setup_extract.inc"
int lut::cli::runExtract(const ExtractOptions&) {
    return 0;
}
#endif
#if __has_include("../../cli/setup_fit.inc")
#include "../../cli/setup_fit.inc"
int lut::cli::runFit(const FitOptions&) {
    return 0;
}
#endif
#if __has_include("../../cli/setup_bench.inc")
#include "../../cli/setup_bench.inc"
int lut::cli::runBench(const BenchOptions&) {
    return 0;
}
#endif

namespace lut::fuzz {

// The bytes are the argument list after "lutkit", split at NUL and newline.
inline bool runCliArgs(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"lutkit"};
    std::string cur;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\0' || c == '\n') {
            args.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!cur.empty())
        args.push_back(cur);
    if (args.size() > 64)
        return false;
    std::vector<char*> argv;
    for (auto& a : args)
        argv.push_back(a.data());

    CLI::App app{"lutkit", "lutkit"};
    app.require_subcommand(1);
#if __has_include("../../cli/setup_neutral.inc")
    setupNeutral(app);
#endif
#if __has_include("../../cli/setup_convert.inc")
    setupConvert(app);
#endif
#if __has_include("../../cli/setup_info.inc")
    setupInfo(app);
#endif
#if __has_include("../../cli/setup_validate.inc")
    setupValidate(app);
#endif
#if __has_include("../../cli/setup_apply.inc")
    setupApply(app);
#endif
#if __has_include("../../cli/setup_preview.inc")
    setupPreview(app);
#endif
#if __has_include("../../cli/setup_embed.inc")
    setupEmbed(app);
#endif
#if __has_include("../../cli/setup_extract.inc")
    setupExtract(app);
#endif
#if __has_include("../../cli/setup_fit.inc")
    setupFit(app);
#endif
#if __has_include("../../cli/setup_bench.inc")
    setupBench(app);
#endif
    try {
        app.parse(static_cast<int>(argv.size()), argv.data());
        return true;
    } catch (const CLI::ParseError&) {
        return false; // exit code 2 in main.cpp
    }
}

} // namespace lut::fuzz
