// SPDX-License-Identifier: Apache-2.0
#pragma once
// The lutkit command line in-process (lutkit_cli), for tests that read its option tables or run
// it with stub run functions: what users get, without touching files.
#include "CommandLine.h"
#include "OptionTable.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lut::test {

// Every run function replaced by one that does nothing and succeeds.
inline cli::RunHooks stubHooks() {
    cli::RunHooks h;
    h.neutral = [](const cli::NeutralOptions&) { return 0; };
    h.convert = [](const cli::ConvertOptions&) { return 0; };
    h.info = [](const cli::InfoOptions&) { return 0; };
    h.validate = [](const cli::ValidateOptions&) { return 0; };
    h.apply = [](const cli::ApplyOptions&) { return 0; };
    h.preview = [](const cli::PreviewOptions&) { return 0; };
    h.embed = [](const cli::EmbedOptions&) { return 0; };
    h.extract = [](const cli::ExtractOptions&) { return 0; };
    h.fit = [](const cli::FitOptions&) { return 0; };
    h.match = [](const cli::MatchCommandOptions&) { return 0; };
    h.bench = [](const cli::BenchOptions&) { return 0; };
    h.bake = [](const cli::BakeCommandOptions&) { return 0; };
    h.diff = [](const cli::DiffCommandOptions&) { return 0; };
    h.compose = [](const cli::ComposeCommandOptions&) { return 0; };
    h.invert = [](const cli::InvertCommandOptions&) { return 0; };
    h.resize = [](const cli::ResizeCommandOptions&) { return 0; };
    h.smooth = [](const cli::SmoothCommandOptions&) { return 0; };
    h.mix = [](const cli::MixCommandOptions&) { return 0; };
    h.plot = [](const cli::PlotCommandOptions&) { return 0; };
    h.adjust = [](const cli::AdjustCommandOptions&) { return 0; };
    h.check = [](const cli::CheckCommandOptions&) { return 0; };
    h.chart = [](const cli::ChartCommandOptions&) { return 0; };
    h.atlas = [](const cli::AtlasCommandOptions&) { return 0; };
    return h;
}

inline cli::ProgramEntry programTable() {
    cli::CommandLine cl(stubHooks());
    return cli::describeProgram(cl.app());
}

// "a b c" split at blanks (the examples and test command lines have no quoted words).
inline std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    for (const char c : line + " ") {
        if (c == ' ') {
            if (!cur.empty())
                out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    return out;
}

struct InProcessResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// Runs `lutkit <line>` in-process with the given hooks, capturing stdout and stderr.
inline InProcessResult runInProcess(const std::string& line,
                                    const cli::RunHooks& hooks = stubHooks()) {
    cli::CommandLine cl(hooks);
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    InProcessResult r;
    r.exitCode = cl.run(words(line));
    r.out = ::testing::internal::GetCapturedStdout();
    r.err = ::testing::internal::GetCapturedStderr();
    return r;
}

} // namespace lut::test
