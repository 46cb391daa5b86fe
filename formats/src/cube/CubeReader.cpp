// SPDX-License-Identifier: Apache-2.0
// The .cube entry points for reading: from memory and from a file (CubeParser.h says what is
// accepted and refused).
#include "cube/CubeParser.h"

#include "lut/LimitError.h"
#include "lut/Limits.h"
#include "lut/io/InputFile.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <cstdint>
#include <fstream>

namespace lut::formats {

namespace cube {

FileBytes readCubeFile(const std::string& path) {
    return readFileBytes(path, static_cast<std::size_t>(limits::kMaxLutFileBytes),
                         LimitId::MaxLutFileBytes);
}

void checkCubeFileHeader(const std::string& path, const CubeReadOptions& options) {
    os::FileInfo st;
    if (os::fileInfo(path, st) != 0 || st.type != os::FileType::Regular ||
        st.size <= kHeaderPrefixBytes)
        return; // readFileBytes says what is wrong with it, or reads it whole anyway
    std::ifstream in(os::toPath(path), std::ios::binary);
    std::string prefix(kHeaderPrefixBytes, '\0');
    in.read(prefix.data(), static_cast<std::streamsize>(prefix.size()));
    prefix.resize(static_cast<std::size_t>(in.gcount()));
    const std::size_t lastEnd = prefix.find_last_of("\r\n");
    if (lastEnd == std::string::npos)
        return;
    prefix.resize(lastEnd + 1); // whole lines only
    Diagnostics ignored;        // the whole parse reports them
    CubeParser(prefix, path, options, ignored).checkHeader();
}

} // namespace cube

LutFile parseCube(std::string_view text, const std::string& path, const CubeReadOptions& options) {
    Diagnostics diags;
    cube::CubeParser parser(text, path, options, diags);
    return parser.parse();
}

LutFile readCube(const std::string& path, const CubeReadOptions& options) {
    cube::checkCubeFileHeader(path, options); // LUT_3D_SIZE 257 refused before reading the rest
    const FileBytes bytes = cube::readCubeFile(path);
    return parseCube(bytes.view(), path, options);
}

} // namespace lut::formats
