// SPDX-License-Identifier: Apache-2.0
#pragma once
// No command writes over any of its inputs: the one check every command runs on each output
// before it writes (convert, embed, extract with --original-lut, fit with both images, apply and
// preview with the image and the --lut file, ...).
#include <string>
#include <vector>

namespace lut {

// Throws lut::Error if output names the same file as any of inputs: the same path (however
// spelled: "./a.cube", "dir/../a.cube"), a symbolic link to it, a hard link to it, or a path
// through a linked folder. The message names both: "OUTPUT: output is the same file as input
// INPUT (same path or a link to it); refusing to overwrite it". Empty inputs and "-" (standard
// input) are skipped.
void checkNotOverwritingInputs(const std::string& output, const std::vector<std::string>& inputs);

// The same for one input.
void checkNotSameFile(const std::string& input, const std::string& output);

// Whether two paths name one file: the same device and inode when both exist, else the same
// path however spelled. "-" is standard output: the file descriptor 1 is compared.
bool sameFile(const std::string& a, const std::string& b);

} // namespace lut
