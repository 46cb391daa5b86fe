// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared helpers for tests: paths to data, temporary folders, running the CLI.
#include <string>

namespace lut::test {

std::string dataPath(const std::string& name);   // tests/data/<name>
std::string samplePath(const std::string& name); // samples/<name>
// A fresh empty folder under the build tree (or $LUTKIT_TEST_TMP), unique per test (removed at
// start, kept after).
std::string tempDir();

struct RunResult {
    int exitCode = -1;
    std::string out; // stdout
    std::string err; // stderr
};
// Runs the lutkit CLI with the given shell-quoted argument string.
RunResult runCli(const std::string& args);
// Runs a shell command line (another program as an oracle: ffmpeg, oiiotool...).
RunResult runCommand(const std::string& command);
// Whether a program is on PATH.
bool haveProgram(const std::string& name);
// A path or argument in single quotes, for the shell of runCli and runCommand.
std::string shellQuoted(const std::string& s);
// A whole file's bytes ("" when it cannot be read).
std::string fileBytes(const std::string& path);

} // namespace lut::test
