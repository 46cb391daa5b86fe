// SPDX-License-Identifier: Apache-2.0
#pragma once
// The lutkit command line: every subcommand (commands/X.{h,cpp}: its options, CLI11 set-up, help
// with examples, and run function), plus `help [COMMAND]`, -V/--version and the hidden
// `--generate man|bash|zsh|fish` the build uses to write the man page and shell completions, and
// the hidden `--names spaces|looks|displays|views[:DISPLAY]` those completions call: the active
// config's names ($OCIO, else lutkit's own), one a line.
//
// main() is `return lut::cli::CommandLine().run(argc, argv);`. Tests and the CLI fuzzer build the
// same command line with hooks in place of the run functions, so they see exactly the options,
// validators and conversions users get. Files with no command are a drop (Drop.h): each is
// converted into color_grading_lut.nutexb beside it.
#include "commands/Adjust.h"
#include "commands/Apply.h"
#include "commands/Atlas.h"
#include "commands/Bake.h"
#include "commands/Bench.h"
#include "commands/Chart.h"
#include "commands/Check.h"
#include "commands/Compose.h"
#include "commands/Convert.h"
#include "commands/Diff.h"
#include "commands/Embed.h"
#include "commands/Extract.h"
#include "commands/Fit.h"
#include "commands/Info.h"
#include "commands/Invert.h"
#include "commands/Match.h"
#include "commands/Mix.h"
#include "commands/Neutral.h"
#include "commands/Plot.h"
#include "commands/Preview.h"
#include "commands/Resize.h"
#include "commands/Smooth.h"
#include "commands/Validate.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lut::cli {

template <class Options> using RunFn = std::function<int(const Options&)>;

// What each subcommand runs once its options are parsed, returning the exit code; an empty
// function = the real run function (runConvert ...).
struct RunHooks {
    RunFn<NeutralOptions> neutral;
    RunFn<ConvertOptions> convert;
    RunFn<InfoOptions> info;
    RunFn<ValidateOptions> validate;
    RunFn<ApplyOptions> apply;
    RunFn<PreviewOptions> preview;
    RunFn<EmbedOptions> embed;
    RunFn<ExtractOptions> extract;
    RunFn<FitOptions> fit;
    RunFn<BenchOptions> bench;
    RunFn<BakeCommandOptions> bake;
    RunFn<DiffCommandOptions> diff;
    RunFn<ComposeCommandOptions> compose;
    RunFn<InvertCommandOptions> invert;
    RunFn<ResizeCommandOptions> resize;
    RunFn<SmoothCommandOptions> smooth;
    RunFn<MixCommandOptions> mix;
    RunFn<PlotCommandOptions> plot;
    RunFn<AdjustCommandOptions> adjust;
    RunFn<MatchCommandOptions> match;
    RunFn<CheckCommandOptions> check;
    RunFn<ChartCommandOptions> chart;
    RunFn<AtlasCommandOptions> atlas;
};

class CommandLine {
public:
    explicit CommandLine(const RunHooks& hooks = {});
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    // The CLI11 app: its subcommands and option tables (what --help, the man page, the
    // completions and the vocabulary test read). app().parse(...) runs the subcommand's hook.
    CLI::App& app() { return m_app; }
    // The exit code the last run subcommand returned (after app().parse()).
    int exitCode() const { return m_exitCode; }

    // Everything main does: parses the arguments (after the program name; UTF-8 from the wide
    // command line on Windows), runs the subcommand, prints help, usage errors ("did you mean")
    // and library errors; returns the exit code: 0 ok, 1 bad input or failed operation, 2 bad
    // usage, 130 interrupted. Where the console window is the program's own (Windows: a double
    // click or files dropped on lutkit.exe), it waits for a key before it returns.
    int run(int argc, const char* const* argv);
    int run(const std::vector<std::string>& args);

private:
    int runDrop(const std::vector<std::string>& files);
    int parseErrorExit(const CLI::ParseError& e);
    // Prints a command's error as its kind says (ErrorExit.h) and returns its exit code.
    int reportError(const std::exception& e);
    std::optional<std::string> unknownCommandMessage(const std::vector<std::string>& args) const;
    std::string commandPrefix() const; // "lutkit convert: " (the parsed subcommand)

    RunHooks m_hooks;
    CLI::App m_app;
    int m_exitCode = 0;
    std::string m_generate;       // --generate KIND
    std::string m_names;          // --names KIND: the active config's names, for completion
    std::string m_maxMemory;      // --max-memory of the commands that only set the limit
    bool m_helpRequested = false; // `help` was given
    std::string m_helpTopic;      // `help COMMAND`
};

} // namespace lut::cli
