// The .cube entry points for reading: from memory and from a file (CubeParser.h says what is
// accepted and refused).
#include "cube/CubeParser.h"

#include "lut/Limits.h"
#include "lut/io/InputFile.h"

namespace lut::formats {

namespace cube {

FileBytes readCubeFile(const std::string& path) {
    return readFileBytes(path, static_cast<std::size_t>(limits::kMaxLutFileBytes),
                         "lut::limits::kMaxLutFileBytes");
}

} // namespace cube

LutFile parseCube(std::string_view text, const std::string& path, const CubeReadOptions& options) {
    Diagnostics diags;
    cube::CubeParser parser(text, path, options, diags);
    return parser.parse();
}

LutFile readCube(const std::string& path, const CubeReadOptions& options) {
    const FileBytes bytes = cube::readCubeFile(path);
    return parseCube(bytes.view(), path, options);
}

} // namespace lut::formats
