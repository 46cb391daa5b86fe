// SPDX-License-Identifier: Apache-2.0
#pragma once
// --strength, --luma-strength and --chroma-strength: the LUT a command writes or applies, blended
// with neutral (lut/ops/Strength.h). The same three options on convert, apply, preview and
// extract (mix keeps its own --strength, the blend of two LUTs).
#include "Notes.h"

#include "lut/Lut3D.h"
#include "lut/ops/Strength.h"

#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

void addStrengthOptions(CLI::App& sub, StrengthOptions& target);

// The LUT at the strength asked for; with -v a note on stderr names the LUT and the amounts.
Lut3D strengthLut(Lut3D lut, const std::string& name, const StrengthOptions& options,
                  const Verbosity& verbosity);

// "luma 0.5, chroma 0.8 (blended with neutral in Oklab)"; "" at full strength.
std::string strengthText(const StrengthOptions& options);

} // namespace lut::cli
