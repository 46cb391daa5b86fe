// SPDX-License-Identifier: Apache-2.0
// Replays the fuzz regression corpus (tests/data/fuzz-regress/<fuzzer>/) through the same targets
// the libFuzzer harnesses use (tests/fuzz/FuzzTargets.h), in the normal build: every input that
// once crashed a reader must now be read or refused with lut::Error, never crash. Files whose
// name starts with "reject-" must be refused.
#include "../fuzz/CheckFuzzTarget.h"
#include "../fuzz/CliTarget.h"
#include "../fuzz/FuzzTargets.h"
#include "../fuzz/ImageFuzzTarget.h"
#include "../fuzz/ImageOiioFuzzTarget.h"
#include "../fuzz/OcioFuzzTarget.h"
#include "../fuzz/PatchFuzzTarget.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

namespace fs = std::filesystem;
using lut::fuzz::Outcome;

namespace {

using Target = Outcome (*)(const std::uint8_t*, std::size_t);

Outcome runCli(const std::uint8_t* data, std::size_t size) {
    const bool parsed = lut::fuzz::runCliArgs(data, size);
    const Outcome word = lut::fuzz::runCliWords(data, size);
    return parsed || word == Outcome::Accepted ? Outcome::Accepted : Outcome::Refused;
}

const std::map<std::string, Target>& targets() {
    static const std::map<std::string, Target> t = {
        {"cube", lut::fuzz::runCube},
        {"strip", lut::fuzz::runStrip},
        {"hald", lut::fuzz::runHald},
        {"nutexb", lut::fuzz::runNutexb},
        {"cli_numbers", runCli},
        {"ocio", lut::fuzz::runOcio},
        {"image_apply", lut::fuzz::runImageApply},
        {"image_oiio", lut::fuzz::runImageOiio},
        {"patch", lut::fuzz::runPatch},
        {"check", lut::fuzz::runCheck},
    };
    return t;
}

std::vector<fs::path> corpusFiles(const std::string& fuzzer) {
    std::vector<fs::path> files;
    const fs::path dir = lut::test::dataPath("fuzz-regress/" + fuzzer);
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file())
                files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

class FuzzRegress : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzRegress, EveryInputIsReadOrRefusedWithLutError) {
    const auto files = corpusFiles(GetParam());
    for (const auto& f : files) {
        SCOPED_TRACE(f.string());
        std::ifstream in(f, std::ios::binary);
        const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
        Outcome o = Outcome::Accepted;
        // Anything but lut::Error escaping the target is the bug the corpus guards against.
        EXPECT_NO_THROW(o = targets().at(GetParam())(bytes.data(), bytes.size()));
        if (f.filename().string().rfind("reject-", 0) == 0) {
            EXPECT_EQ(o, Outcome::Refused) << "a known-bad input was accepted";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Corpus, FuzzRegress,
                         ::testing::Values("cube", "strip", "hald", "nutexb", "cli_numbers", "ocio",
                                           "image_apply", "patch", "check", "image_oiio"),
                         [](const auto& info) { return info.param; });

// The corpus is not allowed to rot silently: every fuzzer folder in it is one we replay.
TEST(FuzzRegressCorpus, HasOnlyKnownFuzzersAndSomeInputs) {
    const fs::path root = lut::test::dataPath("fuzz-regress");
    ASSERT_TRUE(fs::is_directory(root));
    std::size_t total = 0;
    for (const auto& e : fs::directory_iterator(root)) {
        if (!e.is_directory())
            continue;
        EXPECT_TRUE(targets().count(e.path().filename().string())) << e.path();
        total += corpusFiles(e.path().filename().string()).size();
    }
    EXPECT_GT(total, 0u);
}

} // namespace
