// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUTs known by name, usable wherever a LUT file is (lutkit --lut, --original-lut, convert's
// input, the editor): "builtin:NAME". The prefix cannot be a LUT file's name by accident (a file
// really named so is reached as ./builtin:NAME); lut::formats::readLut answers these names.
//   builtin:neutral        the identity, 16^3
//   builtin:smash-default  Smash Ultimate's stage LUT when a stage has none, as the reference
//                          renderer has it: per channel 0, 15, 30, 46, 64, 82, 101, 121, 140,
//                          158, 176, 193, 209, 224, 240, 255 (of 255) on a 16^3 lattice, each
//                          channel from its own input (ScanMountGoat/ssbh_wgpu,
//                          ssbh_wgpu/src/texture.rs, create_default_lut: "a subtle
//                          contrast/saturation adjustment"; docs/pipeline.md)
#include "lut/Lut3D.h"

#include <string>
#include <string_view>
#include <vector>

namespace lut {

constexpr std::string_view kBuiltinLutPrefix = "builtin:";

struct BuiltinLutInfo {
    std::string name;        // "smash-default"; the spelling users type is "builtin:" + name
    std::string description; // one line
    bool gameLut = false;    // a LUT the game applies (as a .nutexb is), not an edit
};
std::vector<BuiltinLutInfo> builtinLuts();

// Whether `path` names a built-in LUT (starts with "builtin:"), known or not.
bool isBuiltinLutName(std::string_view path);

// Whether "builtin:NAME" is a LUT the game applies (builtin:smash-default): converting it to a
// .nutexb writes it as it is, and the editor opens it as a game LUT.
bool isBuiltinGameLut(std::string_view path);

// The LUT "builtin:NAME" names. Throws lut::Error listing the known names for another.
Lut3D builtinLut(std::string_view path);

// The per-channel values (0..255) of builtin:smash-default, index = lattice point 0..15.
const std::vector<int>& smashDefaultLutValues();

} // namespace lut
