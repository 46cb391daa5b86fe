// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit atlas build|split|info: LUTs as the rows of one picture (ReShade's MultiLUT.fx atlas by
// default) and back (lut/formats/Atlas.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/interp/Interpolation.h"
#include "lut/io/Layout.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct AtlasCommandOptions {
    std::string action;              // build | split | info
    std::vector<std::string> inputs; // build: the LUTs, row by row; split, info: atlas pictures
    OutputOptions output;            // -o: build, the atlas; split, a folder; -y, -n
    std::optional<LutLayout> layout; // build: the rows' layout (default reshade)
    // split, info: the atlas's layout (default: detected); build: the layout of LUT images read
    std::optional<LutLayout> inLayout;
    int size = 0;              // build: N of every row (default: the layout's, else the first's)
    bool neutralFirst = false; // build: row 0 the neutral LUT
    Interpolation interp = Interpolation::Tetrahedral;
    Verbosity verbosity;
};

int runAtlas(const AtlasCommandOptions& options);

CLI::App* setupAtlas(CLI::App& app, std::function<void(const AtlasCommandOptions&)> onParsed);

} // namespace lut::cli
