// The .cube entry points for reading: from memory and from a file (CubeParser.h says what is
// accepted and refused).
#include "cube/CubeParser.h"

namespace lut::formats {

LutFile parseCube(std::string_view text, const std::string& path, const CubeReadOptions& options) {
    Diagnostics diags;
    cube::CubeParser parser(text, path, options, diags);
    return parser.parse();
}

LutFile readCube(const std::string& path, const CubeReadOptions& options) {
    const FileView file(path);
    return parseCube(file.bytes(), path, options);
}

} // namespace lut::formats
