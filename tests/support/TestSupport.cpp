// SPDX-License-Identifier: Apache-2.0
#include "TestSupport.h"

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace lut::test {

std::string dataPath(const std::string& name) {
    return std::string(LUTKIT_TEST_DATA_DIR) + "/" + name;
}
std::string samplePath(const std::string& name) {
    return std::string(LUTKIT_SAMPLES_DIR) + "/" + name;
}

std::string tempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "misc";
    for (auto& c : name)
        if (c == '/')
            c = '_';
    // $LUTKIT_TEST_TMP: another root, for a second run of the same tests at the same time (the
    // package test runs docs_tests from the extracted package while ctest may run them too).
    const char* other = std::getenv("LUTKIT_TEST_TMP");
    fs::path dir =
        (other && *other ? fs::path(other) : fs::path(LUTKIT_BINARY_DIR) / "test-tmp") / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

RunResult runCli(const std::string& args) {
    return runCommand(std::string("'") + LUTKIT_CLI + "' " + args);
}

bool haveProgram(const std::string& name) {
    return std::system(("command -v '" + name + "' >/dev/null 2>&1").c_str()) == 0;
}

RunResult runCommand(const std::string& command) {
    // Not via tempDir(): that empties the calling test's folder, deleting its input files.
    fs::path dir = fs::path(LUTKIT_BINARY_DIR) / "test-tmp" / "cli-capture";
    fs::create_directories(dir);
    static int counter = 0;
    std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
    fs::path out = dir / ("out_" + tag), err = dir / ("err_" + tag);
    std::string cmd = command + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
    int status = std::system(cmd.c_str());
    RunResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out);
    r.err = slurp(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

std::string shellQuoted(const std::string& s) {
    return "'" + s + "'";
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

} // namespace lut::test
