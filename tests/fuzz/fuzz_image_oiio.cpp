// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: image files OpenImageIO reads for lutkit (TIFF, JPEG, TGA, BMP, HDR, DPX,
// PSD, GIF, tiled EXR, IFF, WebP), through the pre-open rule, apply's streaming (tiles, parts,
// codec errors) and preview's frame read. One harness for every format (the format is told by
// the file's first bytes); CI runs it on every seed, scripts/fuzz-nightly.sh runs it per format
// on that format's seeds. The target lives in ImageOiioFuzzTarget.h so that tests/regress replays
// findings through the same path in the normal build.
#include "ImageOiioFuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)lut::fuzz::runImageOiio(data, size);
    return 0;
}
