// SPDX-License-Identifier: Apache-2.0
// The one translation unit that holds the clone's absolute paths (see TestPaths.h): it alone
// misses ccache in a clone at another path. LUTKIT_PATH_* come from tests/support/CMakeLists.txt.
#include "TestPaths.h"

namespace lut::test::paths {

const char* cli() {
    return LUTKIT_PATH_CLI;
}
const char* editor() {
    return LUTKIT_PATH_EDITOR;
}
const char* testDataDir() {
    return LUTKIT_PATH_TEST_DATA_DIR;
}
const char* samplesDir() {
    return LUTKIT_PATH_SAMPLES_DIR;
}
const char* binaryDir() {
    return LUTKIT_PATH_BINARY_DIR;
}
const char* sourceDir() {
    return LUTKIT_PATH_SOURCE_DIR;
}
const char* faultShim() {
    return LUTKIT_PATH_FAULT_SHIM;
}

} // namespace lut::test::paths
