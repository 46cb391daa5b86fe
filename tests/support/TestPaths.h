// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where the tests find the built programs and the source tree: lutkit, lutkit-editor, tests/data,
// samples/, the build tree, the source tree, the fault shim. The paths are absolute and differ per
// clone, so they reach the code through one library (TestPaths.cpp, target lutkit_test_paths) and
// not as -DLUTKIT_CLI="/abs/path" on every test: ccache's CCACHE_BASEDIR makes the paths on the
// command line relative but not the string value of a -D, so every translation unit that expanded
// one (or included a header that did) hashed differently in a clone at another path and missed
// the cache. Only TestPaths.cpp differs between clones now.
// The macros keep their old names and give a const char* at run time, not a string literal:
// concatenate with std::string or QString (QString::fromUtf8(LUTKIT_EDITOR)), not "a" "b".

namespace lut::test::paths {

const char* cli();         // the lutkit CLI (build/bin/lutkit)
const char* editor();      // lutkit-editor, "" when the editor is not built
const char* testDataDir(); // tests/data
const char* samplesDir();  // samples
const char* binaryDir();   // the build tree
const char* sourceDir();   // the source tree
const char* faultShim();   // tests/robust/shim's LD_PRELOAD module, "" when it is not built

} // namespace lut::test::paths

#define LUTKIT_CLI (::lut::test::paths::cli())
#define LUTKIT_EDITOR (::lut::test::paths::editor())
#define LUTKIT_TEST_DATA_DIR (::lut::test::paths::testDataDir())
#define LUTKIT_SAMPLES_DIR (::lut::test::paths::samplesDir())
#define LUTKIT_BINARY_DIR (::lut::test::paths::binaryDir())
#define LUTKIT_SOURCE_DIR (::lut::test::paths::sourceDir())
// Only for the tests built with the shim (robust_tests, -DLUTKIT_HAS_FAULT_SHIM): code elsewhere
// asks "#ifdef LUTKIT_FAULT_SHIM".
#ifdef LUTKIT_HAS_FAULT_SHIM
#define LUTKIT_FAULT_SHIM (::lut::test::paths::faultShim())
#endif
