// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz target for the CLI's argument handling: the real command line (lutkit_cli's
// lut::cli::CommandLine, where CLI11 converts and checks numbers and words) parses fuzzed argument
// lists, with each run function replaced by a hook that checks what validation promised (a --size
// that got through is 2..256, --bit-depth 8/16/32, a layout, interpolation or preset that is one
// of the library's values). CLI11 must turn any bad argument into a CLI::ParseError (exit code 2);
// any other exception escaping is a finding.
#include "CommandLine.h"
#include "Usage.h"

#include "lut/pipeline/Pipeline.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace lut::fuzz {

namespace cli_stub {

inline void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "CLI validation let through: %s\n", what);
        std::abort();
    }
}
inline void checkSize(int size, int lo = 2, int hi = 256) {
    check(size == 0 || (size >= lo && size <= hi), "--size outside its range");
}
inline void checkBitDepth(int bits) {
    check(bits == 0 || bits == 8 || bits == 16 || bits == 32, "--bit-depth not 8/16/32");
}
inline void checkInterp(Interpolation m) {
    check(m == Interpolation::Nearest || m == Interpolation::Trilinear ||
              m == Interpolation::Tetrahedral,
          "--interp that is no interpolation");
}
inline void checkLayout(const std::optional<LutLayout>& l) {
    if (l) {
        const auto all = allLayouts();
        check(std::find(all.begin(), all.end(), *l) != all.end(), "a layout that is none");
    }
}

// --strength, --luma-strength, --chroma-strength: 0..2, never NaN (CLI::Range lets NaN through).
inline void checkStrength(const lut::StrengthOptions& s) {
    for (const double v : {s.strength, s.luma.value_or(1.0), s.chroma.value_or(1.0)})
        check(v >= 0.0 && v <= 2.0, "a strength outside 0..2 or NaN");
}

inline lut::cli::RunHooks hooks() {
    using namespace lut::cli;
    RunHooks h;
    h.neutral = [](const NeutralOptions& o) {
        checkSize(o.size);
        checkBitDepth(o.bitDepth);
        checkLayout(o.layout);
        return 0;
    };
    h.convert = [](const ConvertOptions& o) {
        checkSize(o.size);
        checkBitDepth(o.bitDepth);
        checkInterp(o.interp);
        checkLayout(o.layout);
        checkLayout(o.inLayout);
        checkStrength(o.strength);
        return 0;
    };
    h.info = [](const InfoOptions& o) {
        checkSize(o.size);
        checkLayout(o.inLayout);
        return 0;
    };
    h.validate = [](const ValidateOptions& o) {
        checkLayout(o.inLayout);
        return 0;
    };
    h.apply = [](const ApplyOptions& o) {
        checkInterp(o.interp);
        checkLayout(o.lutLayout);
        checkStrength(o.strength);
        check(o.threads >= 0 && o.threads <= 1024, "--threads outside 0..1024");
        return 0;
    };
    h.preview = [](const PreviewOptions& o) {
        checkInterp(o.interp);
        checkStrength(o.strength);
        checkBitDepth(o.bitDepth);
        const auto presets = allPresets();
        check(std::find(presets.begin(), presets.end(), o.preset) != presets.end(),
              "--preset that is none");
        // Every stage setting that got through must be one the pipeline takes ("bloom.*" names
        // the preset's bloom stage, checked only when the pipeline is built: exit 2 there).
        try {
            PipelineSettings s;
            s.preset = o.preset;
            for (const auto& a : o.stageSettings)
                if (a.rfind("bloom.", 0) != 0)
                    s.assignments.push_back(a);
            s.enable = o.enable;
            Pipeline p(s);
        } catch (const lut::Error&) {
            check(false, "--stage/--enable the pipeline refuses");
        }
        return 0;
    };
    h.embed = [](const EmbedOptions& o) {
        checkSize(o.size, 5, 64);
        checkLayout(o.layout);
        return 0;
    };
    h.extract = [](const ExtractOptions& o) {
        checkSize(o.size);
        checkLayout(o.layout);
        checkStrength(o.strength);
        return 0;
    };
    h.atlas = [](const AtlasCommandOptions& o) {
        check(o.action == "build" || o.action == "split" || o.action == "info",
              "an atlas action that is none");
        if (o.size)
            checkSize(o.size);
        checkInterp(o.interp);
        checkLayout(o.layout);
        checkLayout(o.inLayout);
        return 0;
    };
    h.fit = [](const FitOptions& o) {
        checkSize(o.size, 2, 129);
        checkLayout(o.layout);
        return 0;
    };
    h.bench = [](const BenchOptions& o) {
        for (const int s : o.sizes)
            checkSize(s);
        for (const Interpolation m : o.methods)
            checkInterp(m);
        return 0;
    };
    h.check = [](const CheckCommandOptions& o) {
        checkLayout(o.inLayout);
        return 0;
    };
    h.chart = [](const ChartCommandOptions& o) {
        checkBitDepth(o.bitDepth);
        checkSize(o.width, 16, 16384);
        checkSize(o.height, 16, 16384);
        return 0;
    };
    return h;
}

} // namespace cli_stub

// The bytes are the argument list after "lutkit", split at NUL and newline. Returns whether the
// command line parsed (false: a usage error, exit code 2 in lutkit).
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

    lut::cli::CommandLine cli(cli_stub::hooks());
    try {
        cli.app().parse(static_cast<int>(argv.size()), argv.data());
        return !cli.app().get_subcommands().empty();
    } catch (const CLI::ParseError&) {
        return false; // exit code 2 in lutkit
    } catch (const lut::cli::UsageError&) {
        // A combination a command's own check refuses after parsing (convert with no OUT):
        // exit code 2 in lutkit too (CommandLine::run).
        return false;
    }
}

} // namespace lut::fuzz
